// pfparticles: many small spheres in one glBegin -- particles, the atoms of a molecule -- drawn
// by a sphere primitive through the API, timed (docs/performance.md, "100k spheres").
//   pfparticles [--primitive sphere_impostors|sphere] [--count 100000] [--threads 1]
//               [--frames 5] [--size 1024] [--stats] [--csv FILE]
// Spheres of 5-20 pixels at random places in a frustum, lit, each its own colour. Each frame
// times the API calls, glEnd (setup and binning) and glFinish (rasterization and shading);
// prints the median and the fastest frame, and the median glEnd. PF_SETUP_BATCH=0 sets the
// instances up one at a time (scalar) instead of 16 at a time.
#include <CLI/CLI.hpp>

#include "tools/command_line.h"

#include <primflow/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

// The context internals, for --stats only.
#include "api/src/context_state.h"

int main(int argc, char** argv) {
  CLI::App app{"pfparticles: many small spheres through the API, timed"};
  std::string primitive = "sphere_impostors";
  int count = 100000, threads = 1, frames = 5, size = 1024;
  bool stats = false;
  float radius_scale = 1;
  std::string csv;
  app.add_option("--primitive", primitive, "the sphere primitive");
  app.add_option("--count", count, "spheres")->check(CLI::Range(1, 10000000));
  app.add_option("--threads", threads, "rasterizer threads")->check(CLI::Range(0, 256));
  app.add_option("--frames", frames, "timed frames (after one warm-up)")->check(CLI::Range(1, 1000));
  app.add_option("--size", size, "image size (square)")->check(CLI::Range(16, 8192));
  app.add_option("--radius-scale", radius_scale, "radii times this (3: a dense cloud, many spheres per pixel)")
      ->check(CLI::Range(0.01, 100.0));
  app.add_flag("--stats", stats, "print the work counters per frame");
  app.add_option("--csv", csv, "append primitive,count,size,threads,median_ms,fastest_ms,glend_ms to FILE");
  PF_PARSE_COMMAND_LINE(app, argc, argv);

  std::vector<unsigned char> pixels(static_cast<size_t>(size) * size * 4);
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  if (!ctx || !pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, size, size)) {
    std::fprintf(stderr, "pfparticles: no context\n");
    return 1;
  }
  const GLenum mode = pfglGetPrimitiveEXT(primitive.c_str());
  if (mode == 0) {
    std::fprintf(stderr, "pfparticles: no primitive named '%s'\n", primitive.c_str());
    return 1;
  }
  struct Ball {
    float x, y, z, r, c[3];
  };
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<Ball> balls(static_cast<size_t>(count));
  for (Ball& b : balls) b = {u(rng) * 8 - 4, u(rng) * 6 - 3, u(rng) * 6 - 3, (0.01f + 0.03f * u(rng)) * radius_scale, {u(rng), u(rng), u(rng)}};
  const GLuint centre = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.47, 0.47, -0.47, 0.47, 1, 30);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslatef(0, 0, -9);
  pfglEnable(GL_DEPTH_TEST);
  pfglEnable(GL_LIGHTING);
  pfglEnable(GL_LIGHT0);
  pfglEnable(GL_COLOR_MATERIAL);
  std::vector<double> ms, end_ms, call_ms;
  for (int f = 0; f <= frames; ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    pfglBegin(mode);
    for (const Ball& b : balls) {
      pfglColor3f(b.c[0], b.c[1], b.c[2]);
      pfglRastParamfEXT(radius, b.r);
      pfglRastParam3fEXT(centre, b.x, b.y, b.z);
      pfglSequencePointEXT();
    }
    const auto t_before_end = std::chrono::steady_clock::now();
    pfglEnd();
    const auto t_end = std::chrono::steady_clock::now();
    pfglFinish();
    const double t = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (f > 0) {  // frame 0 warms up
      ms.push_back(t);
      end_ms.push_back(std::chrono::duration<double, std::milli>(t_end - t_before_end).count());
      call_ms.push_back(std::chrono::duration<double, std::milli>(t_before_end - t0).count());
    }
  }
  if (pfglGetError() != GL_NO_ERROR) {
    std::fprintf(stderr, "pfparticles: GL error\n");
    return 1;
  }
  std::sort(ms.begin(), ms.end());
  std::sort(end_ms.begin(), end_ms.end());
  std::sort(call_ms.begin(), call_ms.end());
  std::printf("%s: %d spheres, %dx%d, %d thread(s): median %.1f ms, fastest %.1f ms over %d frames; glEnd (setup, "
              "binning) median %.1f ms; clear and calls before it median %.1f ms\n",
              primitive.c_str(), count, size, size, pfGetThreadCount(ctx), ms[ms.size() / 2], ms.front(), frames,
              end_ms[end_ms.size() / 2], call_ms[call_ms.size() / 2]);
  if (!csv.empty()) {
    std::FILE* f = std::fopen(csv.c_str(), "a");
    if (!f) {
      std::fprintf(stderr, "pfparticles: cannot write %s\n", csv.c_str());
      return 1;
    }
    std::fprintf(f, "%s,%d,%d,%d,%.1f,%.1f,%.1f\n", primitive.c_str(), count, size, pfGetThreadCount(ctx),
                 ms[ms.size() / 2], ms.front(), end_ms[end_ms.size() / 2]);
    std::fclose(f);
  }
  if (stats) {
    // The counters add up since the context was made; every frame draws the same.
    const pf::FrameStats& s = ctx->renderer.stats();
    const double n = frames + 1.0;
    std::printf("per frame: %.0f blocks run (%.0f packed, %.0f of them ganged, %.0f accepted, %.0f rejected; %.0f "
                "culled by depth, and %.0f pixels), %.1f%% lanes active at start, %.1f%% committed; %.0f pixel "
                "instructions (%.1f per block), %.0f setup instructions (%.0f per sphere)\n",
                double(s.blocks_run) / n, double(s.blocks_packed) / n, double(s.blocks_ganged) / n,
                double(s.blocks_accepted) / n, double(s.blocks_rejected) / n, double(s.blocks_depth_culled) / n,
                double(s.pixels_depth_culled) / n,
                s.blocks_run ? 100.0 * double(s.lanes_started) / (64.0 * double(s.blocks_run)) : 0.0,
                s.blocks_run ? 100.0 * double(s.lanes_committed) / (64.0 * double(s.blocks_run)) : 0.0,
                double(s.pixel_instructions) / n,
                s.blocks_run ? double(s.pixel_instructions) / double(s.blocks_run) : 0.0,
                double(s.setup_instructions) / n, double(s.setup_instructions) / (n * count));
  }
  pfDestroyContext(ctx);
  return 0;
}
