// pfrender: renders a scene or a model with primflow to a PNG.
//   pfrender [SCENE.json] [-o OUT.png] [--size WxH] [--threads N] [--stats]
//   pfrender MODEL.vm|MODEL.hf|MODEL.pfl|MODEL.pfgrid [-o OUT.png] [--size WxH] [--bbox x0,y0,z0,x1,y1,z1] [--ortho]
//            [--method M] [--steps N] [--depth-out FILE.pfm] [--threads N] [--time T] [--stats]
// --depth-out: a model's visible world z; for a scene, its depth buffer (window depth in [0, 1]).
// A scene file (docs/scenes.md); with no scene, the built-in showcase (tools/showcase.cpp).
// A model (tools/model/model_file.h, docs/models.md) is drawn as an implicit surface.
// --size overrides the scene's own image size.
// Exit status: 0 drawn and written; 1 a bad scene or model, a GL error while drawing (the image,
// incomplete, is still written), out of memory, or an unwritable output; 2 a bad command line.
#include <CLI/CLI.hpp>

#include "tools/command_line.h"

#include <primflow/gl.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <optional>
#include <iostream>
#include <vector>

#include "model/model_file.h"
#include "png_image.h"
#include "raster/renderer.h"
#include "scene/scene.h"
#include "showcase.h"

// The context internals, for --stats only.
#include "api/src/context_state.h"
#include "compiler/native/native_cache.h"

namespace {

// The frames' times, in order, and whether each compiled native code (a program passing its
// compile threshold compiles on the rasterizer thread that passed it, inside that frame).
struct FrameTimes {
  std::vector<double> ms;
  std::vector<bool> compiled;
};

// The frame time --stats prints: with one frame, its time; with more, the median of the frames
// after the first (which compiles what the picture draws natively) that compiled nothing -- a
// program can pass its threshold only in a later frame, and with 2 threads up to one compile a
// frame would otherwise be most of the frames timed -- or of all frames after the first when
// every one of them compiled.
struct FrameTime {
  double median_ms = 0;
  int timed = 0;        // frames the median is of
  int after_first = 0;  // frames after the first
};

FrameTime frameTime(const FrameTimes& frames) {
  FrameTime t;
  t.after_first = static_cast<int>(frames.ms.size()) - 1;
  std::vector<double> quiet, all;
  for (size_t i = 1; i < frames.ms.size(); ++i) {
    all.push_back(frames.ms[i]);
    if (!frames.compiled[i]) quiet.push_back(frames.ms[i]);
  }
  std::vector<double>& timed = quiet.empty() ? all : quiet;
  if (timed.empty()) timed.push_back(frames.ms.front());  // one frame: its own time
  std::sort(timed.begin(), timed.end());
  const size_t n = timed.size();
  t.median_ms = n % 2 ? timed[n / 2] : 0.5 * (timed[n / 2 - 1] + timed[n / 2]);
  t.timed = static_cast<int>(n);
  return t;
}

// The frame time (frameTime) and the counters, which are the last frame's.
void printStats(PFcontext ctx, const FrameTimes& frames) {
  const pf::FrameStats& s = ctx->renderer.stats();
  std::printf("threads            %d\n", pfGetThreadCount(ctx));
  const FrameTime t = frameTime(frames);
  if (t.after_first == 0)
    std::printf("frame time         %.2f ms\n", t.median_ms);
  else if (t.timed == t.after_first)
    std::printf("frame time         %.2f ms (median of %d frames after the first, which took %.2f ms)\n", t.median_ms,
                t.timed, frames.ms.front());
  else
    std::printf("frame time         %.2f ms (median of %d frames after the first, which took %.2f ms; %d more "
                "compiled native code and are not timed)\n",
                t.median_ms, t.timed, frames.ms.front(), t.after_first - t.timed);
  std::printf("instances          %llu submitted, %llu killed in setup\n",
              static_cast<unsigned long long>(s.instances_submitted), static_cast<unsigned long long>(s.instances_killed));
  std::printf("bin entries        %llu\n", static_cast<unsigned long long>(s.bin_entries));
  std::printf("tiles run          %llu, %llu skipped (no instance there)\n", static_cast<unsigned long long>(s.tiles_run),
              static_cast<unsigned long long>(s.tiles_skipped));
  std::printf("blocks run         %llu, %llu rejected whole (%.1f%% of the blocks in bounds)\n",
              static_cast<unsigned long long>(s.blocks_run), static_cast<unsigned long long>(s.blocks_rejected),
              s.blocks_run + s.blocks_rejected ? 100.0 * s.blocks_rejected / double(s.blocks_run + s.blocks_rejected)
                                               : 0.0);
  std::printf("blocks covered     %llu (every lane committed: %.1f%% of the blocks run)\n",
              static_cast<unsigned long long>(s.blocks_covered),
              s.blocks_run ? 100.0 * s.blocks_covered / double(s.blocks_run) : 0.0);
  std::printf("blocks accepted    %llu (run without coverage tests: %.1f%% of the blocks run)\n",
              static_cast<unsigned long long>(s.blocks_accepted),
              s.blocks_run ? 100.0 * s.blocks_accepted / double(s.blocks_run) : 0.0);
  std::printf("blocks walked      %llu (rejected or accepted by a verdict of their own, their 32x32 region's "
              "undecided: %llu walks over such a region's blocks)\n",
              static_cast<unsigned long long>(s.blocks_walked), static_cast<unsigned long long>(s.region_walks));
  std::printf("blocks packed      %llu (a small bound's pixels packed into whole blocks: %.1f%% of the blocks run)\n",
              static_cast<unsigned long long>(s.blocks_packed),
              s.blocks_run ? 100.0 * s.blocks_packed / double(s.blocks_run) : 0.0);
  std::printf("blocks depth-culled %llu (skipped by coarse depth culling: an instance's depth_bound() against the "
              "block's stored depths), and %llu pixels of packed lanes\n",
              static_cast<unsigned long long>(s.blocks_depth_culled),
              static_cast<unsigned long long>(s.pixels_depth_culled));
  std::printf("blocks ganged      %llu (packed blocks shared by several small instances)\n",
              static_cast<unsigned long long>(s.blocks_ganged));
  std::printf("blocks native      %llu (run as machine code: %.1f%% of the blocks run; the rest interpreted)\n",
              static_cast<unsigned long long>(s.blocks_native),
              s.blocks_run ? 100.0 * s.blocks_native / double(s.blocks_run) : 0.0);
  const pf::SetupBatchCounters setup = ctx->renderer.setupBatchCounters();
  std::printf("setups             %llu batched (%llu of them finished in native code), %llu resumed scalar, %llu "
              "scalar (this context)\n",
              static_cast<unsigned long long>(setup.lanes_batched), static_cast<unsigned long long>(setup.lanes_native),
              static_cast<unsigned long long>(setup.lanes_resumed), static_cast<unsigned long long>(setup.lanes_scalar));

  const pf::NativeCacheStats n = pf::NativeProgramCache::instance().stats();
  std::printf("native programs    %llu compiled in %.1f ms, %llu left to the interpreter (this process)\n",
              static_cast<unsigned long long>(n.compiled), n.milliseconds,
              static_cast<unsigned long long>(n.refused + n.failed));
  std::printf("active lanes       %.1f%% at start, %.1f%% committed\n",
              s.blocks_run ? 100.0 * s.lanes_started / (64.0 * s.blocks_run) : 0.0,
              s.blocks_run ? 100.0 * s.lanes_committed / (64.0 * s.blocks_run) : 0.0);
  std::printf("pixels shaded      %llu\n", static_cast<unsigned long long>(s.pixels_shaded));
  std::printf("instructions       %llu setup, %llu pixel (interpreted, per 8x8 block): %.1f%% uniform setup\n",
              static_cast<unsigned long long>(s.setup_instructions), static_cast<unsigned long long>(s.pixel_instructions),
              s.setup_instructions + s.pixel_instructions
                  ? 100.0 * s.setup_instructions / double(s.setup_instructions + s.pixel_instructions) : 0.0);
  std::printf("g-buffer bytes     %llu (the layout's slots and shading ids of the tiles run)\n",
              static_cast<unsigned long long>(s.gbuffer_bytes));
  if (s.field.rays) {
    const pf::field::FieldCounters& f = s.field;
    std::printf("field rays         %llu, %llu hit\n", static_cast<unsigned long long>(f.rays),
                static_cast<unsigned long long>(f.hits));
    std::printf("field evaluations  %llu points (%.1f per ray), %llu intervals\n",
                static_cast<unsigned long long>(f.point_evaluations), double(f.point_evaluations) / double(f.rays),
                static_cast<unsigned long long>(f.interval_evaluations));
    std::printf("field slabs        %llu culled, %llu filled, %llu monotone; %llu ray segments searched, %llu left to samples\n",
                static_cast<unsigned long long>(f.slabs_culled), static_cast<unsigned long long>(f.slabs_filled),
                static_cast<unsigned long long>(f.slabs_monotone), static_cast<unsigned long long>(f.segments_searched),
                static_cast<unsigned long long>(f.segments_left_to_samples));
    if (f.tape_ops_full)
      std::printf("tape ops pruned    %.1f%% (sampled slabs ran %llu of %llu instructions)\n",
                  100.0 * (1.0 - double(f.tape_ops_run) / double(f.tape_ops_full)),
                  static_cast<unsigned long long>(f.tape_ops_run), static_cast<unsigned long long>(f.tape_ops_full));
    if (f.lipschitz_overshoots || f.analytic_fallbacks || f.iteration_cap_lanes)
      std::printf("field fallbacks    %llu Lipschitz overshoots, %llu analytic lanes to interval, %llu capped lanes\n",
                  static_cast<unsigned long long>(f.lipschitz_overshoots),
                  static_cast<unsigned long long>(f.analytic_fallbacks),
                  static_cast<unsigned long long>(f.iteration_cap_lanes));
  }
}

// "x0,y0,z0,x1,y1,z1" with x0 < x1 etc.
bool parseBox(const std::string& text, glm::dvec3& lo, glm::dvec3& hi) {
  double v[6];
  char tail = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &tail) != 6)
    return false;
  for (double x : v)
    if (!std::isfinite(x)) return false;
  lo = {v[0], v[1], v[2]};
  hi = {v[3], v[4], v[5]};
  return lo.x < hi.x && lo.y < hi.y && lo.z < hi.z;
}

// "WxH" with each side in 1..8192 (digits only: no sign, no overflow past int).
bool parseSize(const std::string& text, int& w, int& h) {
  const size_t x = text.find('x');
  if (x == std::string::npos) return false;
  auto side = [](const std::string& digits, int& out) {
    if (digits.empty() || digits.size() > 4 || digits.find_first_not_of("0123456789") != std::string::npos) return false;
    out = std::stoi(digits);
    return out >= 1 && out <= 8192;
  };
  return side(text.substr(0, x), w) && side(text.substr(x + 1), h);
}

// CLI11's check that a number option is finite (its Range lets NaN through).
const CLI::Validator kFinite(
    [](std::string& v) {
      double d = 0;
      return CLI::detail::lexical_cast(v, d) && std::isfinite(d) ? std::string() : "must be a finite number, not '" + v + "'";
    },
    "FINITE");

int run(int argc, char** argv);

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::cerr << "pfrender: out of memory\n";
    return 1;
  }
}

namespace {

int run(int argc, char** argv) {
  CLI::App app{"pfrender: render a scene with primflow (no scene: the built-in showcase)"};
  std::string scene_path;
  std::string out;
  std::string size;
  int threads = 0, frames = 1;
  bool stats = false;
  std::string bbox, method_name = "auto", depth_out;
  bool ortho = false;
  double steps = 0.0, time = 0.0;
  app.add_option("scene", scene_path, "scene file (.json) or model (.vm, .hf, .pfl, .pfgrid); none: the built-in showcase");
  app.add_option("-o,--output", out, "output PNG file (default: the scene's name, or showcase.png)");
  app.add_option("--size", size, "image size WxH (each 1..8192; default: the scene's, or 960x640)");
  app.add_option("--threads", threads, "rasterizer threads (0: PF_NUM_THREADS or all cores)")->check(CLI::Range(0, 256));
  app.add_flag("--stats", stats, "print the renderer's work counters");
  app.add_option("--frames", frames,
                 "draw the picture this many times (--stats: the frame time is the median of the frames after the "
                 "first that compiled no native code, the counters the last frame's)")
      ->check(CLI::Range(1, 10000));
  auto* o_bbox = app.add_option("--bbox", bbox, "model: box x0,y0,z0,x1,y1,z1 (default [-1,1]^3 for .vm, [-10,10]^3 for .hf, [-2,2]^3 for .pfl, the grid's for .pfgrid)");
  auto* o_ortho = app.add_flag("--ortho", ortho, "model: look down -z from above the box, the image covering its x and y");
  auto* o_method = app.add_option("--method", method_name, "model: auto, analytic, interval, march, sphere, newton or regula-falsi");
  auto* o_steps = app.add_option("--steps", steps, "model: march's steps M, or sphere tracing's Lipschitz bound")
                      ->check(kFinite & CLI::Range(0.0, 1e6));
  app.add_option("--depth-out", depth_out,
                 "write the depth as a PFM: a model's visible world z (NaN: none); a scene's depth buffer "
                 "(window depth, 1 where nothing was drawn)");
  auto* o_time = app.add_option("--time", time, "model: HyperFun's time x[4] (Fidget models have none and ignore it)")
                     ->check(kFinite);
  PF_PARSE_COMMAND_LINE(app, argc, argv);
  const bool is_model = !scene_path.empty() && pf::model::isModelPath(scene_path);
  if (!is_model) {
    for (CLI::Option* o : {o_bbox, o_ortho, o_method, o_steps, o_time})
      if (o->count()) {
        std::cerr << "pfrender: " << o->get_name() << " applies to models (.vm, .hf, .pfl, .pfgrid), not to scenes\n";
        return 2;
      }
  }
  // The scene or model is read before anything else: a bad file is reported before any work.
  std::optional<pf::scene::Scene> scene;
  std::optional<pf::model::Model> model;
  pf::model::ModelView view;
  if (is_model) {
    try {
      model = pf::model::loadModel(scene_path, time);
    } catch (const pf::model::ModelError& e) {
      std::cerr << e.what() << (std::string(e.what()).back() == '\n' ? "" : "\n");
      return 1;
    }
    auto method = pf::field::parseRootMethod(method_name);
    if (!method) {
      std::cerr << "pfrender: --method must be auto, analytic, interval, march, sphere, newton or regula-falsi, not '" << method_name << "'\n";
      return 2;
    }
    view.method = static_cast<int>(*method);
    view.steps = static_cast<float>(steps);
    view.time = time;
    view.ortho = ortho;
    view.box_min = model->default_box_min;
    view.box_max = model->default_box_max;
    if (!bbox.empty() && !parseBox(bbox, view.box_min, view.box_max)) {
      std::cerr << "pfrender: --bbox must be x0,y0,z0,x1,y1,z1 with x0 < x1, y0 < y1, z0 < z1, not '" << bbox << "'\n";
      return 2;
    }
  } else if (!scene_path.empty()) {
    const std::string ext = std::filesystem::path(scene_path).extension().string();
    if (ext != ".json") {
      std::cerr << "pfrender: " << scene_path << ": error: unknown scene type '" << ext
                << "' (pfrender reads .json scene files, docs/scenes.md, and .vm / .hf / .pfl / .pfgrid models)\n";
      return 1;
    }
    try {
      scene = pf::scene::loadScene(scene_path);
    } catch (const pf::scene::SceneError& e) {
      std::cerr << e.what() << "\n";
      return 1;
    }
  }
  if (out.empty()) out = !scene_path.empty() ? std::filesystem::path(scene_path).stem().string() + ".png" : "showcase.png";
  int w = scene ? scene->width : model ? 512 : 960, h = scene ? scene->height : model ? 512 : 640;
  if (!size.empty() && !parseSize(size, w, h)) {
    std::cerr << "pfrender: --size must be WxH with each side in 1..8192, not '" << size << "'\n";
    return 2;
  }
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  if (!ctx) {
    std::cerr << "pfrender: could not create a context\n";
    return 1;
  }
  std::vector<unsigned char> pixels;
  try {
    pixels.resize(static_cast<size_t>(w) * h * 4);
  } catch (const std::bad_alloc&) {
    std::cerr << "pfrender: out of memory for a " << w << "x" << h << " image\n";
    pfDestroyContext(ctx);
    return 1;
  }
  if (!pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, w, h)) {
    std::cerr << "pfrender: could not bind a " << w << "x" << h << " buffer\n";
    pfDestroyContext(ctx);
    return 1;
  }
  // Each frame draws the whole picture again (glClear first); the first also compiles what the
  // picture draws natively.
  FrameTimes frame_times;
  auto nativeCompiles = [] {
    const pf::NativeCacheStats n = pf::NativeProgramCache::instance().stats();
    return n.compiled + n.refused + n.failed;
  };
  for (int frame = 0; frame < frames; ++frame) {
    if (frame == frames - 1) ctx->renderer.resetStats();
    const uint64_t compiles_before = nativeCompiles();
    auto t0 = std::chrono::steady_clock::now();
    if (model) {
      view.width = w;
      view.height = h;
      try {
        pf::model::drawModel(*model, view);
      } catch (const pf::model::ModelError& e) {
        std::cerr << e.what();
        pfDestroyContext(ctx);
        return 1;
      }
    } else if (scene) {
      try {
        pf::scene::drawScene(*scene, w, h);
      } catch (const pf::scene::SceneError& e) {
        std::cerr << e.what() << "\n";
        pfDestroyContext(ctx);
        return 1;
      }
    } else {
      pf::drawShowcase(w, h);
    }
    auto t1 = std::chrono::steady_clock::now();
    frame_times.ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    frame_times.compiled.push_back(nativeCompiles() != compiles_before);
  }
  GLenum err = pfglGetError();
  if (err != GL_NO_ERROR)
    std::cerr << "pfrender: GL error 0x" << std::hex << err << std::dec << " while drawing: the image is incomplete\n";
  if (stats) printStats(ctx, frame_times);
  if (!model && !depth_out.empty()) {  // a scene's (or the showcase's) depth buffer as it is
    GLint dw = 0, dh = 0, bytes = 0;
    void* data = nullptr;
    std::string error;
    if (!pfGetDepthBuffer(ctx, &dw, &dh, &bytes, &data) ||
        !pf::model::writePfm(depth_out, w, h,
                             std::vector<float>(static_cast<const float*>(data),
                                                static_cast<const float*>(data) + size_t(w) * h),
                             &error)) {
      std::cerr << "pfrender: " << (error.empty() ? "no depth buffer" : error) << "\n";
      pfDestroyContext(ctx);
      return 1;
    }
  }
  if (model && !depth_out.empty()) {
    GLint dw = 0, dh = 0, bytes = 0;
    void* data = nullptr;
    std::string error;
    if (!pfGetDepthBuffer(ctx, &dw, &dh, &bytes, &data) ||
        !pf::model::writePfm(depth_out, w, h,
                             pf::model::worldDepth(*model, view,
                                                   std::vector<float>(static_cast<const float*>(data),
                                                                      static_cast<const float*>(data) + size_t(w) * h)),
                             &error)) {
      std::cerr << "pfrender: " << (error.empty() ? "no depth buffer" : error) << "\n";
      pfDestroyContext(ctx);
      return 1;
    }
  }
  std::string error;
  bool ok = pf::writePngBottomUp(out, pixels.data(), w, h, &error);
  pfDestroyContext(ctx);
  if (!ok) {
    std::cerr << "pfrender: " << error << "\n";
    return 1;
  }
  return err == GL_NO_ERROR ? 0 : 1;
}

}  // namespace
