// The HTML report of pfconform --report DIR: one table row per case (result, largest colour
// and depth errors, pixels off, time, why), and for each case the reference, actual and diff
// images side by side. Generated, never committed.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "conformance.h"
#include "png_image.h"

namespace pfconf {

namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

bool writeImage(const std::string& path, const Image& img, std::string* error) {
  if (img.rgba.empty() || img.width <= 0 || img.height <= 0) return true;  // nothing rendered
  return pf::writePngBottomUp(path, img.rgba.data(), img.width, img.height, error);
}

}  // namespace

bool writeHtmlReport(const std::string& dir, const std::vector<ReportRow>& rows, std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    if (error) *error = "cannot create " + dir + ": " + ec.message();
    return false;
  }
  std::ofstream html(dir + "/index.html");
  if (!html) {
    if (error) *error = "cannot write " + dir + "/index.html";
    return false;
  }
  int pass = 0, fail = 0, deviation = 0;
  for (const ReportRow& r : rows) {
    pass += r.result.status == Result::Status::Pass;
    fail += r.result.status == Result::Status::Fail;
    deviation += r.result.status == Result::Status::ExpectedDeviation;
  }
  html << "<!doctype html><html><head><meta charset=\"utf-8\"><title>primflow conformance</title><style>"
          "body{font-family:sans-serif;margin:1em}table{border-collapse:collapse}td,th{border:1px solid #ccc;"
          "padding:3px 6px;vertical-align:top}.pass{color:#070}.FAIL{color:#b00;font-weight:bold}"
          ".dev{color:#a60}img{width:192px;image-rendering:pixelated;margin-right:4px}pre{margin:0;font-size:11px}"
          "</style></head><body><h1>primflow conformance</h1>\n";
  html << "<p>" << rows.size() << " cases: " << pass << " pass, " << fail << " fail, " << deviation
       << " expected deviations. GL cases are compared with OSMesa (reference, left), primflow (middle) and "
          "their difference (right: red where they differ).</p>\n<table><tr><th>case</th><th>category</th>"
          "<th>result</th><th>max colour error</th><th>pixels off</th><th>max depth error</th><th>ms</th>"
          "<th>images and details</th></tr>\n";
  for (const ReportRow& row : rows) {
    const Result& r = row.result;
    const char* cls = r.status == Result::Status::Pass ? "pass" : r.status == Result::Status::Fail ? "FAIL" : "dev";
    html << "<tr><td><b>" << escape(row.name) << "</b><br><small>" << escape(row.what) << "</small></td><td>"
         << escape(row.category) << "</td><td class=\"" << cls << "\">" << statusName(r.status) << "</td><td>"
         << r.max_colour_error << "/255</td><td>" << r.pixels_off << "</td><td>" << r.max_depth_error << "</td><td>";
    char ms[32];
    std::snprintf(ms, sizeof ms, "%.1f", r.milliseconds);
    html << ms << "</td><td>";
    const std::string base = dir + "/" + row.name;
    if (!writeImage(base + "_reference.png", r.reference, error) || !writeImage(base + "_actual.png", r.actual, error))
      return false;
    if (!r.reference.rgba.empty()) html << "<img src=\"" << row.name << "_reference.png\" title=\"reference\">";
    if (!r.actual.rgba.empty()) html << "<img src=\"" << row.name << "_actual.png\" title=\"primflow\">";
    if (!r.reference.rgba.empty() && r.reference.rgba.size() == r.actual.rgba.size()) {
      if (!writeImage(base + "_diff.png", diffImage(r.reference, r.actual), error)) return false;
      html << "<img src=\"" << row.name << "_diff.png\" title=\"difference\">";
    }
    if (!r.detail.empty()) html << "<pre>" << escape(r.detail) << "</pre>";
    html << "</td></tr>\n";
  }
  html << "</table></body></html>\n";
  return static_cast<bool>(html);
}

}  // namespace pfconf
