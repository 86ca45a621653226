// pfrender: renders a scene with primflow to a PNG.
//   pfrender [SCENE.json] [-o OUT.png] [--size WxH] [--threads N] [--stats]
// A scene file (docs/scenes.md); with no scene, the built-in showcase (tools/showcase.cpp).
// --size overrides the scene's own image size.
#include <CLI/CLI.hpp>

#include <primflow/gl.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <iostream>
#include <vector>

#include "png_image.h"
#include "raster/renderer.h"
#include "scene/scene.h"
#include "showcase.h"

// The context internals, for --stats only.
#include "api/src/context_state.h"

int main(int argc, char** argv) {
  CLI::App app{"pfrender: render a scene with primflow (no scene: the built-in showcase)"};
  std::string scene_path;
  std::string out;
  std::string size;
  int threads = 0;
  bool stats = false;
  app.add_option("scene", scene_path, "scene file (.json); none: the built-in showcase");
  app.add_option("-o,--output", out, "output PNG file (default: the scene's name, or showcase.png)");
  app.add_option("--size", size, "image size WxH (each 1..8192; default: the scene's, or 960x640)");
  app.add_option("--threads", threads, "rasterizer threads (0: PF_NUM_THREADS or all cores)")->check(CLI::Range(0, 256));
  app.add_flag("--stats", stats, "print the renderer's work counters");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  // The scene is read before anything else: a bad file is reported before any work.
  std::optional<pf::scene::Scene> scene;
  if (!scene_path.empty()) {
    const std::string ext = std::filesystem::path(scene_path).extension().string();
    if (ext != ".json") {
      std::cerr << "pfrender: " << scene_path << ": error: unknown scene type '" << ext
                << "' (pfrender reads .json scene files, docs/scenes.md)\n";
      return 1;
    }
    try {
      scene = pf::scene::loadScene(scene_path);
    } catch (const pf::scene::SceneError& e) {
      std::cerr << e.what() << "\n";
      return 1;
    }
  }
  if (out.empty()) out = scene ? std::filesystem::path(scene_path).stem().string() + ".png" : "showcase.png";
  int w = scene ? scene->width : 960, h = scene ? scene->height : 640;
  char tail = 0;
  if (!size.empty() &&
      (std::sscanf(size.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w < 1 || h < 1 || w > 8192 || h > 8192)) {
    std::cerr << "pfrender: --size must be WxH with each side in 1..8192, not '" << size << "'\n";
    return 2;
  }
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  if (!ctx) {
    std::cerr << "pfrender: could not create a context\n";
    return 1;
  }
  std::vector<unsigned char> pixels(static_cast<size_t>(w) * h * 4);
  if (!pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, w, h)) {
    std::cerr << "pfrender: could not bind a " << w << "x" << h << " buffer\n";
    pfDestroyContext(ctx);
    return 1;
  }
  auto t0 = std::chrono::steady_clock::now();
  if (scene) {
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
  GLenum err = pfglGetError();
  if (err != GL_NO_ERROR) std::cerr << "pfrender: GL error 0x" << std::hex << err << std::dec << "\n";
  if (stats) {
    const pf::FrameStats& s = ctx->renderer.stats();
    double ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
    std::printf("threads            %d\n", pfGetThreadCount(ctx));
    std::printf("frame time         %.2f ms\n", ms);
    std::printf("instances          %llu submitted, %llu killed in setup\n",
                static_cast<unsigned long long>(s.instances_submitted), static_cast<unsigned long long>(s.instances_killed));
    std::printf("bin entries        %llu\n", static_cast<unsigned long long>(s.bin_entries));
    std::printf("tiles run          %llu\n", static_cast<unsigned long long>(s.tiles_run));
    std::printf("blocks run         %llu\n", static_cast<unsigned long long>(s.blocks_run));
    std::printf("active lanes       %.1f%% at start, %.1f%% committed\n",
                s.blocks_run ? 100.0 * s.lanes_started / (64.0 * s.blocks_run) : 0.0,
                s.blocks_run ? 100.0 * s.lanes_committed / (64.0 * s.blocks_run) : 0.0);
    std::printf("pixels shaded      %llu\n", static_cast<unsigned long long>(s.pixels_shaded));
    std::printf("instructions       %llu setup, %llu pixel (per 8x8 block): %.1f%% uniform setup\n",
                static_cast<unsigned long long>(s.setup_instructions), static_cast<unsigned long long>(s.pixel_instructions),
                s.setup_instructions + s.pixel_instructions
                    ? 100.0 * s.setup_instructions / double(s.setup_instructions + s.pixel_instructions) : 0.0);
    std::printf("g-buffer bytes     %llu\n", static_cast<unsigned long long>(s.gbuffer_bytes));
  }
  std::string error;
  bool ok = pf::writePngBottomUp(out, pixels.data(), w, h, &error);
  pfDestroyContext(ctx);
  if (!ok) {
    std::cerr << "pfrender: " << error << "\n";
    return 1;
  }
  return 0;
}
