// pfcomposite: what sort-last compositing costs (docs/performance.md, "Compositing over MPI"),
// PixelFlow's image composition (Molnar et al. 1992, cited in seed 003 section 1) done in
// software over MPI. Under mpirun, each rank draws its share of a sphere cloud
// (tools/mpi/sphere_cloud.h) once per image size, then times pfCompositeDepthMPI several times
// from that same frame (restored before each run), per algorithm and compression.
//   mpirun -np P pfcomposite [--sizes 512x512,1920x1080] [--spheres N] [--split round-robin|spatial]
//                            [--repeats R] [--threads T] [--csv FILE]
// Rank 0 appends one CSV row per run: the slowest rank's time, the largest and mean bytes sent,
// the merge time and pixels merged (per-pixel cost), the slowest rank's draw time (the
// per-sphere cost the model in bench/composite_report.py scales up) and the largest peak
// resident memory (what a sphere costs to hold until glFinish).
#include <CLI/CLI.hpp>

#include <sys/resource.h>

#include <primflow/composite.h>
#include <primflow/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "mpi/object_split.h"
#include "mpi/sphere_cloud.h"
#include "scene/scene.h"

namespace {

struct Size {
  int w, h;
};

std::vector<Size> parseSizes(const std::string& text) {
  std::vector<Size> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    Size s{};
    if (std::sscanf(item.c_str(), "%dx%d", &s.w, &s.h) != 2 || s.w < 1 || s.h < 1 || s.w > 8192 || s.h > 8192) return {};
    out.push_back(s);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  CLI::App app{"pfcomposite: time pfCompositeDepthMPI"};
  std::string sizes_text = "512x512,1024x1024,1920x1080,3840x2160", csv, split_name = "round-robin";
  uint64_t spheres = 20000;
  int repeats = 5, threads = 1;
  app.add_option("--sizes", sizes_text, "image sizes WxH, comma-separated");
  app.add_option("--spheres", spheres, "spheres in the cloud")->check(CLI::Range(uint64_t{1}, uint64_t{1} << 32));
  app.add_option("--split", split_name, "round-robin or spatial");
  float radius_scale = 1.0f;
  app.add_option("--radius-scale", radius_scale, "the cloud's radii times this")->check(CLI::Range(0.001f, 1000.0f));
  app.add_option("--repeats", repeats, "timed composites per case")->check(CLI::Range(1, 1000));
  app.add_option("--threads", threads, "rasterizer threads per rank")->check(CLI::Range(0, 256));
  app.add_option("--csv", csv, "append rows to FILE (rank 0)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (rank == 0) app.exit(e);
    MPI_Finalize();
    return e.get_exit_code() == 0 ? 0 : 2;
  }
  const std::vector<Size> sizes = parseSizes(sizes_text);
  const auto split = pf::split::parseSplit(split_name);
  if (sizes.empty() || !split) {
    if (rank == 0) std::fprintf(stderr, "pfcomposite: bad --sizes or --split\n");
    MPI_Finalize();
    return 2;
  }
  pf::cloud::SphereCloud cloud;
  cloud.count = spheres;
  cloud.radius_scale = radius_scale;
  const std::vector<uint64_t> mine = pf::split::objectsOfRank(
      *split, pf::cloud::objectCount(cloud), rank, ranks,
      [&](uint64_t i) { return pf::cloud::objectCentre(cloud, i).x; });
  std::FILE* out = nullptr;
  if (rank == 0 && !csv.empty()) out = std::fopen(csv.c_str(), "a");

  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  int status = 0;
  for (const Size& s : sizes) {
    const size_t n = static_cast<size_t>(s.w) * s.h;
    std::vector<unsigned char> pixels(n * 4);
    if (!ctx || !pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, s.w, s.h)) {
      status = 1;
      break;
    }
    MPI_Barrier(MPI_COMM_WORLD);
    const auto t0 = std::chrono::steady_clock::now();
    const pf::scene::Scene frame = pf::cloud::cloudFrame(s.w, s.h);
    pf::scene::beginScene(frame, s.w, s.h);
    for (uint64_t o : mine) pf::cloud::drawCloudObject(cloud, o);
    pfglFinish();
    const double draw_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);  // the peak so far: the frame's instances are held until glFinish
    const double max_rss_kb = static_cast<double>(usage.ru_maxrss);
    GLint w, h, f;
    void *color = nullptr, *depth = nullptr;
    pfGetColorBuffer(ctx, &w, &h, &f, &color);
    pfGetDepthBuffer(ctx, &w, &h, &f, &depth);
    const std::vector<unsigned char> saved_color(static_cast<unsigned char*>(color), static_cast<unsigned char*>(color) + 4 * n);
    const std::vector<float> saved_depth(static_cast<float*>(depth), static_cast<float*>(depth) + n);
    std::vector<int> algorithms = {PF_COMPOSITE_AUTO};
    if (ranks > 2 && (ranks & (ranks - 1)) == 0) algorithms.push_back(PF_COMPOSITE_DIRECT_SEND);
    if (ranks > 2 && (ranks & (ranks - 1)) != 0) algorithms.push_back(PF_COMPOSITE_BINARY_SWAP);
    for (int algorithm : algorithms)
      for (int compress : {0, 1})
        for (int rep = 0; rep < repeats; ++rep) {
          std::memcpy(color, saved_color.data(), saved_color.size());
          std::memcpy(depth, saved_depth.data(), saved_depth.size() * sizeof(float));
          PFcompositeOptions options;
          pfCompositeDefaultOptions(&options);
          options.algorithm = algorithm;
          options.compress = compress;
          options.timeout_seconds = 120;
          PFcompositeStats st;
          MPI_Barrier(MPI_COMM_WORLD);
          const int rc = pfCompositeDepthMPI(MPI_COMM_WORLD, &options, &st);
          if (rc != PF_COMPOSITE_OK) {
            if (rank == 0) std::fprintf(stderr, "pfcomposite: %s\n", pfCompositeErrorString(rc));
            status = 1;
            break;
          }
          // Slowest rank's times; largest and mean bytes.
          double mine_v[5] = {st.seconds, st.merge_seconds, static_cast<double>(st.bytes_sent), draw_ms, max_rss_kb};
          double max_v[5], sum_v[5];
          MPI_Reduce(mine_v, max_v, 5, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
          MPI_Reduce(mine_v, sum_v, 5, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
          double merged = static_cast<double>(st.pixels_merged), merged_sum = 0;
          MPI_Reduce(&merged, &merged_sum, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
          if (rank == 0) {
            const char* name = st.algorithm == PF_COMPOSITE_BINARY_SWAP ? "binary-swap" : "direct-send";
            std::printf("%d ranks %dx%d %-11s %-12s %-12s %8.2f ms  %10.0f bytes sent (max)\n", ranks, s.w, s.h,
                        split_name.c_str(), name, compress ? "compressed" : "raw", max_v[0] * 1e3, max_v[2]);
            if (out)
              std::fprintf(out, "%d,%d,%d,%s,%s,%d,%d,%.6f,%.6f,%.6f,%.0f,%.0f,%.0f,%.3f,%llu,%d,%.0f\n", ranks, s.w,
                           s.h, split_name.c_str(), name, compress, rep, max_v[0], max_v[1], sum_v[1], max_v[2],
                           sum_v[2] / ranks, merged_sum, max_v[3], static_cast<unsigned long long>(spheres),
                           pfGetThreadCount(ctx), max_v[4]);
          }
        }
  }
  if (out) std::fclose(out);
  pfDestroyContext(ctx);
  MPI_Finalize();
  return status;
}
