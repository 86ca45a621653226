// pfspheres: primflow's exact `sphere` primitive against tessellated spheres (gluSphere on OSMesa,
// llvmpipe) -- the time per frame and the error of each image against an exact image computed
// here in double precision -- in one process run.
//   pfspheres [--size 1024] [--counts 1,100,1000] [--levels 8,16,32,64,128] [--threads 1]
//             [--frames 5] [--warmup 1] [--csv bench/results_spheres.csv] [--check]
// Each scene (N lit spheres, overlapping and intersecting) is drawn by gluSphere at every level
// (slices = stacks) and by primflow. Times are medians of F frames after W warm-up frames, each
// ending in glFinish; llvmpipe runs LP_NUM_THREADS = --threads (set before OSMesa starts).
// Accuracy, against the exact image (bench/sphere_reference.h): missing / extra / wrong-surface
// pixels (from an ID frame, each sphere in its own flat colour), the depth and 8-bit colour error
// where both show the same sphere, and the PSNR of the whole lit RGB frame.
// Exit status: 0; 1 when a renderer fails, or with --check when primflow mismatches a pixel
// farther than --edge-tolerance pixels from an edge (the ctest smoke test bench.pfspheres.smoke);
// 2 on bad options.
#include <CLI/CLI.hpp>

#include "tools/command_line.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "bench/sphere_accuracy.h"
#include "bench/sphere_reference.h"
#include "bench/sphere_scene.h"

namespace {

using pfspheres::Accuracy;
using pfspheres::Rendering;

struct Options {
  int size = 1024, threads = 1, frames = 5, warmup = 1;
  std::string counts = "1,100,1000", levels = "8,16,32,64,128", csv = "bench/results_spheres.csv";
  // Pixels. primflow's sphere casts in float: the pixel's ray and the sphere's centre carry
  // rounding errors of ~2^-24 of their coordinates (< 10 eye units here), ~6e-7 units, which is
  // ~2e-4 of a pixel at 1024x1024 (a pixel spans 0.003 units at depth 4, 0.008 at depth 10) and
  // less at smaller sizes: a silhouette or intersection curve that close to a pixel centre may
  // fall on either side. The mismatches we measured all lie within 1e-4 pixels of an edge.
  double edge_tolerance = 1e-3;
  bool check = false;
};

struct Row {
  int spheres;
  std::string method;
  int slices;             // 0 for primflow
  int64_t triangles;      // per frame; 0 for primflow
  double ms;
  double primflow_ratio;  // primflow's ms / this row's (> 1: primflow is slower), as pfbench's ratio
  int64_t covered;        // pixels with a sphere in the exact image
  Accuracy acc;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

bool parseList(const std::string& text, std::vector<int>* out) {
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    char* end = nullptr;
    const long v = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || v < 1 || v > 1000000) return false;
    out->push_back(static_cast<int>(v));
  }
  return !out->empty();
}

// gluSphere(q, r, slices, stacks): two polar fans of `slices` triangles and stacks - 2 bands of
// `slices` quads.
int64_t gluSphereTriangles(int slices, int stacks) { return 2 * int64_t(slices) * (stacks - 1); }

std::string formatPsnr(double db) {
  char buf[32];
  if (std::isinf(db)) return "inf";
  std::snprintf(buf, sizeof buf, "%.2f", db);
  return buf;
}

void printHeader() {
  std::printf("%7s %-9s %10s %10s %8s %9s %8s %8s %8s %8s %10s %10s %7s %8s\n", "spheres", "method",
              "triangles", "ms/frame", "pf/this", "covered", "missing", "extra", "wrong", "off-edge", "max dz",
              "mean dz", "max dc", "PSNR dB");
}

void printRow(const Row& r) {
  std::printf("%7d %-9s %10lld %10.2f %8.2f %9lld %8lld %8lld %8lld %8lld %10.2e %10.2e %7d %8s\n", r.spheres,
              r.method.c_str(), static_cast<long long>(r.triangles), r.ms, r.primflow_ratio,
              static_cast<long long>(r.covered), static_cast<long long>(r.acc.missing),
              static_cast<long long>(r.acc.extra), static_cast<long long>(r.acc.wrong_surface),
              static_cast<long long>(r.acc.off_edge), r.acc.max_depth_error, r.acc.mean_depth_error,
              r.acc.max_color_error, formatPsnr(r.acc.psnr_db).c_str());
  std::fflush(stdout);
}

bool writeCsv(const std::string& path, const std::vector<Row>& rows, const Options& o) {
  std::ofstream out(path);
  if (!out) return false;
  out << "spheres,method,slices,triangles,size,threads,frames,ms_per_frame,primflow_ratio,covered,missing,extra,"
         "wrong_surface,mismatched,off_edge,max_depth_error,mean_depth_error,max_color_error,psnr_db\n";
  for (const Row& r : rows)
    out << r.spheres << "," << r.method << "," << r.slices << "," << r.triangles << "," << o.size << ","
        << o.threads << "," << o.frames << "," << r.ms << "," << r.primflow_ratio << "," << r.covered << ","
        << r.acc.missing << "," << r.acc.extra << "," << r.acc.wrong_surface << "," << r.acc.mismatched() << ","
        << r.acc.off_edge << "," << r.acc.max_depth_error << "," << r.acc.mean_depth_error << ","
        << r.acc.max_color_error << "," << formatPsnr(r.acc.psnr_db) << "\n";
  return static_cast<bool>(out);
}

// One scene: the exact image, primflow, then gluSphere at each level. False on a renderer failure.
bool measureScene(int count, const std::vector<int>& levels, const Options& o, std::vector<Row>* rows) {
  const pfspheres::SphereScene scene = pfspheres::makeSphereScene(count, o.size);
  const pfspheres::ExactImage exact = pfspheres::computeExactImage(scene, o.edge_tolerance);
  const int64_t covered = std::count_if(exact.id.begin(), exact.id.end(), [](uint32_t id) { return id != 0; });
  const pfspheres::Timing timing{o.warmup, o.frames};

  const Rendering ours = pfspheres::renderWithPrimflowSpheres(scene, o.threads, timing);
  if (!ours.error.empty()) {
    std::fprintf(stderr, "pfspheres: primflow, %d spheres: %s\n", count, ours.error.c_str());
    return false;
  }
  const double ours_ms = median(ours.frame_ms);
  rows->push_back({count, "primflow", 0, 0, ours_ms, 1.0, covered, pfspheres::measureAccuracy(exact, ours)});
  printRow(rows->back());
  for (int slices : levels) {
    const Rendering glu = pfspheres::renderWithGluSpheres(scene, slices, timing);
    if (!glu.error.empty()) {
      std::fprintf(stderr, "pfspheres: gluSphere %d, %d spheres: %s\n", slices, count, glu.error.c_str());
      return false;
    }
    const double ms = median(glu.frame_ms);
    rows->push_back({count, "glu" + std::to_string(slices), slices, count * gluSphereTriangles(slices, slices), ms,
                     ms > 0 ? ours_ms / ms : 0, covered, pfspheres::measureAccuracy(exact, glu)});
    printRow(rows->back());
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pfspheres: primflow's exact sphere primitive against gluSphere tessellations on OSMesa"};
  Options o;
  app.add_option("--size", o.size, "frame width and height in pixels")->check(CLI::Range(16, 8192));
  app.add_option("--counts", o.counts, "comma-separated sphere counts, one scene each");
  app.add_option("--levels", o.levels, "comma-separated gluSphere slices (= stacks)");
  app.add_option("--threads", o.threads, "rasterizer threads, for both (LP_NUM_THREADS for llvmpipe)")
      ->check(CLI::Range(1, 64));
  app.add_option("--frames", o.frames, "timed frames (median reported)")->check(CLI::Range(1, 1000));
  app.add_option("--warmup", o.warmup, "frames before timing")->check(CLI::Range(0, 100));
  app.add_option("--csv", o.csv, "write the results to this CSV file (replaced; empty: none)");
  app.add_option("--edge-tolerance", o.edge_tolerance,
                 "pixels: mismatches this close to a silhouette or intersection curve are not 'off-edge'")
      ->check(CLI::Range(0.0, 0.49));
  app.add_flag("--check", o.check, "exit 1 if primflow mismatches any pixel off the edges");
  PF_PARSE_COMMAND_LINE(app, argc, argv);
  std::vector<int> counts, levels;
  if (!parseList(o.counts, &counts) || !parseList(o.levels, &levels)) {
    std::fprintf(stderr, "pfspheres: --counts and --levels take comma-separated positive integers\n");
    return 2;
  }
  setenv("LP_NUM_THREADS", std::to_string(o.threads).c_str(), 1);  // before OSMesa starts

  std::printf("pfspheres: %dx%d, %d thread(s), median of %d frames after %d warm-up; off-edge: mismatches "
              "farther than %g pixels from an edge;\n  dz, dc: window depth and 8-bit colour error where both "
              "show the same sphere\n",
              o.size, o.size, o.threads, o.frames, o.warmup, o.edge_tolerance);
  printHeader();
  std::vector<Row> rows;
  for (int count : counts)
    if (!measureScene(count, levels, o, &rows)) return 1;
  if (!o.csv.empty() && !writeCsv(o.csv, rows, o)) {
    std::fprintf(stderr, "pfspheres: cannot write %s\n", o.csv.c_str());
    return 1;
  }
  int64_t primflow_off_edge = 0;
  for (const Row& r : rows)
    if (r.method == "primflow") primflow_off_edge += r.acc.off_edge;
  if (o.check && primflow_off_edge > 0) {
    std::fprintf(stderr, "pfspheres: primflow mismatches %lld pixel(s) farther than %g pixels from any edge\n",
                 static_cast<long long>(primflow_off_edge), o.edge_tolerance);
    return 1;
  }
  return 0;
}
