// pfbench: primflow against OSMesa (llvmpipe) on the same GL scenes, in one process run.
//   pfbench [--threads N] [--frames F] [--warmup W] [--scenes small,large,fill,lit] [--csv FILE]
//           [--lanes sse2,avx2,avx512|all]   (the pixel kernels' instruction sets to time, one row each)
// llvmpipe's thread count is LP_NUM_THREADS, read once per process: pfbench sets it to N before
// OSMesa starts, so compare thread counts by running pfbench once per count (bench/run).
// Times are medians of F frames after W warm-up frames, each frame ending in glFinish.
// Every scene's last frames are also compared, pixel by pixel, with the conformance suite's
// tolerance for scenes of many triangles (its "showcase" case): 2/255 per channel except at 0.1%
// of the pixels. Those few are llvmpipe's: it snaps vertices to a 1/256-pixel grid (GL leaves the
// subpixel precision to the implementation) -- with the scenes' vertices snapped so, `small`
// drops from 58 such pixels to 1 -- and rounds depth its own way where two triangles cross.
// `--check` makes a mismatch the exit status (the ctest pfbench.scenes_match_osmesa).
#include <CLI/CLI.hpp>

#include "tools/command_line.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

#include "bench/scene_data.h"
#include "compiler/native/native_cache.h"
#include "raster/lane_kernels.h"

namespace pfbench {

SceneData makeScene(const std::string& name) {
  SceneData s;
  s.name = name;
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  auto tri = [&](float cx, float cy, float r) {
    float z = u01(rng) * 1.8f - 0.9f;
    for (int k = 0; k < 3; ++k) {
      float a = 6.2831853f * (k / 3.0f + 0.1f * u01(rng));
      s.vertices.insert(s.vertices.end(), {cx + r * std::cos(a), cy + r * std::sin(a), z});
      s.colors.insert(s.colors.end(), {u01(rng), u01(rng), u01(rng)});
    }
  };
  if (name == "textured" || name == "blended") {
    for (int i = 0; i < 2000; ++i) tri(u01(rng) * s.width, u01(rng) * s.height, 150.0f + 150.0f * u01(rng));
    if (name == "blended") s.alpha = 0.5f;
    if (name == "textured") {
      // Each vertex's coordinates: its window position over 128 pixels per repeat, so the
      // texture is magnified about 2x and wraps; the image a checkerboard of 32-texel squares
      // with a smooth ramp in each channel, so that bilinear filtering shows.
      for (size_t i = 0; i < s.vertices.size() / 3; ++i)
        s.texcoords.insert(s.texcoords.end(), {s.vertices[3 * i] / 128.0f, s.vertices[3 * i + 1] / 128.0f});
      s.texture_size = 256;
      s.texels.resize(256 * 256 * 3);
      for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
          const bool dark = ((x / 32) + (y / 32)) % 2 == 0;
          unsigned char* t = &s.texels[(static_cast<size_t>(y) * 256 + x) * 3];
          t[0] = static_cast<unsigned char>(dark ? x / 2 : 255 - x / 2);
          t[1] = static_cast<unsigned char>(dark ? y / 2 : 255 - y / 2);
          t[2] = static_cast<unsigned char>(dark ? 64 : 224);
        }
    }
  } else if (name == "small" || name == "lit") {
    for (int i = 0; i < 200000; ++i) tri(u01(rng) * s.width, u01(rng) * s.height, 1.5f + u01(rng));
    if (name == "lit")  // a unit normal per vertex, facing the viewer
      for (size_t i = 0; i < s.vertices.size() / 3; ++i) {
        float x = u01(rng) - 0.5f, y = u01(rng) - 0.5f, z = 1.0f;
        float l = std::sqrt(x * x + y * y + z * z);
        s.normals.insert(s.normals.end(), {x / l, y / l, z / l});
      }
  } else if (name == "large") {
    for (int i = 0; i < 2000; ++i) tri(u01(rng) * s.width, u01(rng) * s.height, 150.0f + 150.0f * u01(rng));
  } else {  // fill: 32 layers of two triangles covering the frame
    for (int layer = 0; layer < 32; ++layer) {
      float z = 0.9f - layer * 0.05f;
      float w = static_cast<float>(s.width), h = static_cast<float>(s.height);
      const float quad[6][2] = {{0, 0}, {w, 0}, {w, h}, {0, 0}, {w, h}, {0, h}};
      for (const auto& p : quad) {
        s.vertices.insert(s.vertices.end(), {p[0], p[1], z});
        s.colors.insert(s.colors.end(), {u01(rng), u01(rng), u01(rng)});
      }
    }
  }
  return s;
}

}  // namespace pfbench

namespace {
// How two RGBA images differ: the largest channel difference, and how many pixels differ by
// more than `tolerance` in some channel.
struct ImageDifference {
  int max_channel = 0;
  size_t pixels_beyond = 0;
};
ImageDifference compareImages(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b, int tolerance) {
  ImageDifference d;
  if (a.size() != b.size()) return {255, a.size() / 4 + 1};
  for (size_t p = 0; p + 3 < a.size(); p += 4) {
    int worst = 0;
    for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(int(a[p + c]) - int(b[p + c])));
    d.max_channel = std::max(d.max_channel, worst);
    if (worst > tolerance) ++d.pixels_beyond;
  }
  return d;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pfbench: primflow against OSMesa (llvmpipe) on the same GL scenes"};
  int threads = 1, frames = 7, warmup = 2;
  std::string scenes = "small,large,fill,lit,textured,blended", csv;
  app.add_option("--threads", threads, "rasterizer threads, for both (LP_NUM_THREADS for llvmpipe)")->check(CLI::Range(1, 64));
  app.add_option("--frames", frames, "timed frames (median reported)")->check(CLI::Range(1, 1000));
  app.add_option("--warmup", warmup, "frames before timing")->check(CLI::Range(0, 100));
  app.add_option("--scenes", scenes, "comma-separated: small, large, fill, lit, textured, blended");
  app.add_option("--csv", csv, "append results to this CSV file");
  bool stats = false;
  app.add_flag("--stats", stats, "print each scene's block counters per frame");
  bool check = false;
  app.add_flag("--check", check, "exit 1 if a scene's image differs from OSMesa's beyond the conformance tolerances");
  std::string lanes;
  app.add_option("--lanes", lanes,
                 "comma-separated instruction sets of the pixel kernels to time primflow with (sse2, avx2, avx512, "
                 "or all the machine runs; default: the one chosen at start-up)");
  PF_PARSE_COMMAND_LINE(app, argc, argv);
  // Native code unless PF_JIT=0 (bench/run times both, interleaved).
  const bool native = pf::nativeCodeWantedByEnvironment();
  std::vector<pf::LaneIsa> lane_isas;
  {
    std::stringstream names(lanes);
    std::string n;
    while (std::getline(names, n, ',')) {
      if (n == "all") {  // every set this machine runs
        for (pf::LaneIsa isa : pf::availableLaneIsas()) lane_isas.push_back(isa);
        continue;
      }
      bool known = false;
      for (pf::LaneIsa isa : {pf::LaneIsa::Baseline, pf::LaneIsa::Avx2, pf::LaneIsa::Avx512})
        if (n == pf::laneIsaName(isa)) {
          known = true;
          if (!pf::setLaneIsa(isa)) {
            std::fprintf(stderr, "pfbench: this machine cannot run the %s kernels\n", n.c_str());
            return 2;
          }
          lane_isas.push_back(isa);
        }
      if (!known) {
        std::fprintf(stderr, "pfbench: unknown instruction set '%s' (sse2, avx2, avx512)\n", n.c_str());
        return 2;
      }
    }
    if (lane_isas.empty()) lane_isas.push_back(pf::laneIsa());
  }
  setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);  // before OSMesa starts

  std::ostringstream rows;
  std::printf("%-6s %7s %12s %12s %8s %12s %12s %7s %s\n", "scene", "threads", "llvmpipe ms", "primflow ms", "ratio",
              "ns/pixel run", "native", "lanes", "image vs OSMesa");
  bool all_match = true;
  std::stringstream list(scenes);
  std::string name;
  while (std::getline(list, name, ',')) {
    if (name != "small" && name != "large" && name != "fill" && name != "lit" && name != "textured" &&
        name != "blended") {
      std::fprintf(stderr, "pfbench: unknown scene '%s' (small, large, fill, lit, textured, blended)\n", name.c_str());
      return 2;
    }
    pfbench::SceneData s = pfbench::makeScene(name);
    std::vector<unsigned char> reference, image;
    double ref = median(pfbench::timeOsmesa(s, warmup, frames, &reference));
    for (pf::LaneIsa isa : lane_isas) {
      pf::setLaneIsa(isa);
      pfbench::FrameWork w;
      double ours = median(pfbench::timePrimflow(s, warmup, frames, threads, &w, &image));
      const ImageDifference diff = compareImages(image, reference, 2);
      const size_t allowed = image.size() / 4 / 1000;
      const bool match = !reference.empty() && diff.pixels_beyond <= allowed;
      all_match = all_match && match;
      char verdict[96];
      std::snprintf(verdict, sizeof verdict, "%s (%zu px beyond 2/255, max %d)", match ? "match" : "MISMATCH",
                    diff.pixels_beyond, diff.max_channel);
      // Per pixel-program run, of the whole frame's time (setup and shading included).
      double ns_per_pixel = w.pixels_run ? ours * 1e6 / static_cast<double>(w.pixels_run) : 0;
      // The blocks run as machine code (the rest interpreted).
      double share = w.blocks_run ? 100.0 * static_cast<double>(w.blocks_native) / static_cast<double>(w.blocks_run) : 0;
      std::printf("%-6s %7d %12.2f %12.2f %8.2f %12.2f %11.1f%% %7s %s\n", name.c_str(), threads, ref, ours,
                  ref > 0 ? ours / ref : 0, ns_per_pixel, share, pf::laneIsaName(isa), verdict);
      if (stats)
        std::printf("       blocks per frame: %llu run (%llu native, %llu packed, %llu accepted), %llu rejected\n",
                    static_cast<unsigned long long>(w.blocks_run), static_cast<unsigned long long>(w.blocks_native),
                    static_cast<unsigned long long>(w.blocks_packed), static_cast<unsigned long long>(w.blocks_accepted),
                    static_cast<unsigned long long>(w.blocks_rejected));
      rows << name << "," << threads << "," << ref << "," << ours << "," << (ref > 0 ? ours / ref : 0) << ","
           << w.pixels_run << "," << w.pixels_shaded << "," << w.setup_instructions << "," << w.pixel_instructions << ","
           << pf::laneIsaName(isa) << "," << diff.pixels_beyond << "," << diff.max_channel << "," << (native ? 1 : 0) << ","
           << share << "\n";
    }
  }
  if (!csv.empty()) {
    bool fresh = !std::ifstream(csv).good();
    std::ofstream out(csv, std::ios::app);
    if (fresh)
      out << "scene,threads,llvmpipe_ms,primflow_ms,ratio,pixels_run,pixels_shaded,setup_instructions,pixel_instructions,"
             "lanes,pixels_beyond_tolerance,max_channel_difference,native,native_blocks_percent\n";
    out << rows.str();
  }
  return check && !all_match ? 1 : 0;
}
