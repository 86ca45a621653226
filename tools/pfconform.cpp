// pfconform: runs primflow's conformance suite and reports. GL cases are drawn by OSMesa (the
// reference) and by primflow from one GL-1.x source and compared; the extension's own cases are
// judged against references computed in double precision (tests/conformance/).
//   pfconform                      every case; a table on stdout; exit 1 if any fails
//   pfconform --case NAME ...      only these (ctest runs one per test)
//   pfconform --list               the cases, one per line
//   pfconform --report DIR         also DIR/index.html: reference / actual / diff images
//   A failing case always leaves its reference, actual and diff PNGs in --failures DIR
//   (default: conformance-failures/ in the working directory).
#include <CLI/CLI.hpp>

#include "tools/command_line.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <set>

#include "conformance/conformance.h"

namespace {

void printRow(const pfconf::ReportRow& row) {
  const pfconf::Result& r = row.result;
  std::printf("%-28s %-14s %-19s %4d/255 %8d %10.2g %8.1f\n", row.name.c_str(), row.category.c_str(),
              pfconf::statusName(r.status), r.max_colour_error, r.pixels_off, r.max_depth_error, r.milliseconds);
  if (r.status != pfconf::Result::Status::Pass && !r.detail.empty()) std::printf("%s", r.detail.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pfconform: primflow's conformance suite (OSMesa as the reference for the GL cases)"};
  std::vector<std::string> only;
  std::string report, failures = "conformance-failures";
  int size = 256, threads = 1;
  bool list = false;
  app.add_option("--case", only, "run only these cases (repeatable)");
  app.add_option("--report", report, "write an HTML report with images into this directory");
  app.add_option("--failures", failures, "where a failing case's reference / actual / diff PNGs go");
  app.add_option("--size", size, "image size of the GL cases (square)")->check(CLI::Range(16, 2048));
  app.add_option("--threads", threads, "primflow's rasterizer threads")->check(CLI::Range(1, 64));
  app.add_flag("--list", list, "list the cases and exit");
  PF_PARSE_COMMAND_LINE(app, argc, argv);

  const auto& gl = pfconf::glCases();
  const auto& ext = pfconf::extensionCases();
  if (list) {
    for (const auto& c : gl) std::printf("%s\n", c.name);
    for (const auto& c : ext) std::printf("%s\n", c.name);
    return 0;
  }
  std::set<std::string> wanted(only.begin(), only.end());
  for (const std::string& name : wanted) {
    bool known = false;
    for (const auto& c : gl) known = known || name == c.name;
    for (const auto& c : ext) known = known || name == c.name;
    if (!known) {
      std::fprintf(stderr, "pfconform: no case '%s' (pfconform --list shows them)\n", name.c_str());
      return 2;
    }
  }
  auto selected = [&](const char* name) { return wanted.empty() || wanted.count(name) > 0; };

  std::printf("%-28s %-14s %-19s %8s %8s %10s %8s\n", "case", "category", "result", "max err", "px off", "max depth",
              "ms");
  std::vector<pfconf::ReportRow> rows;
  using Clock = std::chrono::steady_clock;
  for (const auto& c : gl) {
    if (!selected(c.name)) continue;
    const auto start = Clock::now();
    pfconf::Rendering ref = pfconf::renderOsmesa(c.name, size, size);
    pfconf::Rendering got = pfconf::renderPrimflow(c.name, size, size, threads);
    pfconf::ReportRow row{c.name, c.category, c.what, pfconf::compareGl(c, ref, got)};
    row.result.milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    if (c.tolerance.why && row.result.status == pfconf::Result::Status::Pass)
      row.result.detail = std::string("tolerance: ") + c.tolerance.why;
    printRow(row);
    rows.push_back(std::move(row));
  }
  for (const auto& c : ext) {
    if (!selected(c.name)) continue;
    const auto start = Clock::now();
    pfconf::ReportRow row{c.name, "extension", c.what, {}};
    c.run(row.result);
    if (row.result.status == pfconf::Result::Status::Fail)
      if (const char* reason = pfconf::expectedDeviation(c.name)) {
        row.result.status = pfconf::Result::Status::ExpectedDeviation;
        row.result.detail = std::string("expected deviation: ") + reason + "\n" + row.result.detail;
      }
    row.result.milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    printRow(row);
    rows.push_back(std::move(row));
  }
  int failed = 0, deviations = 0;
  for (const auto& r : rows) {
    failed += r.result.status == pfconf::Result::Status::Fail;
    deviations += r.result.status == pfconf::Result::Status::ExpectedDeviation;
  }
  std::printf("%zu cases: %zu pass, %d fail, %d expected deviations\n", rows.size(), rows.size() - failed - deviations,
              failed, deviations);
  std::vector<pfconf::ReportRow> failing;
  for (const auto& r : rows)
    if (r.result.status == pfconf::Result::Status::Fail) failing.push_back(r);
  if (!failing.empty()) {
    std::string error;
    if (pfconf::writeHtmlReport(failures, failing, &error))
      std::printf("failing cases' images: %s/\n", failures.c_str());
    else
      std::fprintf(stderr, "pfconform: %s\n", error.c_str());
  }
  if (!report.empty()) {
    std::string error;
    if (!pfconf::writeHtmlReport(report, rows, &error)) {
      std::fprintf(stderr, "pfconform: %s\n", error.c_str());
      return 2;
    }
    std::printf("report: %s/index.html\n", report.c_str());
  }
  return failed ? 1 : 0;
}
