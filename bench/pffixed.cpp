// pffixed: what declaring the pixel built-ins in fixed point costs (issue 25 item 3; the paper's
// figures 6 and 7 write `varying fixed<32,16> X, Y; inout varying fixed<32,32> Z`). The shipped
// screen_triangle (primitives/screen_triangle.pfl) against the same source with that
// declaration -- every read of X, Y or Z a conversion into the format, the arithmetic as written
// -- on the same triangles: each pixel program's instruction count, the pixel instructions the
// interpreter executes per frame, and the median frame time with native code and on the
// interpreter (1 rasterizer thread). The two images must be identical (figure 7's pixel centres
// are exact in fixed<32,16>); a difference is the exit status.
//   pffixed [--triangles N] [--size S] [--frames F] [--warmup W] [--csv FILE]
//   CSV: variant,native,triangles,size,frames,pixel_instructions,executed_pixel_instructions,frame_ms
#include <CLI/CLI.hpp>

#include "tools/command_line.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <primflow/context.h>
#include <primflow/gl.h>

#include "api/src/context_state.h"  // the renderer's counters
#include "compiler/compiler.h"
#include "compiler/native/native_cache.h"

namespace {

struct Variant {
  std::string name;    // float, fixed
  std::string source;  // the primitive, named screen_triangle_<name>
};

// The shipped screen_triangle as `screen_triangle_float`, and with figure 7's declaration as
// `screen_triangle_fixed`; empty if the file cannot be read or no longer declares X, Y, Z so.
std::vector<Variant> variants() {
  std::ifstream in(std::string(PF_SOURCE_DIR) + "/primitives/screen_triangle.pfl", std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string head = "primitive screen_triangle(", floats = "varying float X, Y; inout varying float Z)";
  const size_t h = text.find(head), f = text.find(floats);
  if (h == std::string::npos || f == std::string::npos) return {};
  std::vector<Variant> out;
  for (const char* name : {"float", "fixed"}) {
    std::string s = text;
    if (std::string(name) == "fixed") s.replace(f, floats.size(), "varying fixed<32,16> X, Y; inout varying fixed<32,32> Z)");
    s.replace(h, head.size(), std::string("primitive screen_triangle_") + name + "(");
    out.push_back({name, s});
  }
  return out;
}

struct Run {
  double frame_ms = 0;
  uint64_t executed = 0;  // pixel instructions the interpreter ran over the timed frames
  std::vector<unsigned char> image;
};

// `frames` timed frames (after `warmup`) of the triangles drawn with the variant's primitive.
Run draw(const Variant& v, const std::vector<float>& verts, int size, int native, int frames, int warmup) {
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, 1, PF_JIT, native, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  Run run;
  run.image.resize(static_cast<size_t>(size) * size * 4);
  pfMakeCurrent(ctx, run.image.data(), GL_UNSIGNED_BYTE, size, size);
  pfglCompilePrimitivesEXT(v.source.c_str());
  const GLenum prim = pfglGetPrimitiveEXT(("screen_triangle_" + v.name).c_str());
  const GLuint vertex = pfglGetParamNameEXT("screen_vertex");
  pfglEnable(GL_DEPTH_TEST);
  std::vector<double> ms;
  for (int frame = 0; frame < warmup + frames; ++frame) {
    if (frame == warmup) ctx->renderer.resetStats();  // (counters over the timed frames)
    const auto t0 = std::chrono::steady_clock::now();
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    pfglBegin(prim);
    for (size_t k = 0; k + 7 <= verts.size(); k += 7) {
      // x, y, depth of the vertex and its colour's red, green, blue, then w = 1
      pfglColor3f(verts[k + 3], verts[k + 4], verts[k + 5]);
      pfglRastParam4fEXT(vertex, verts[k], verts[k + 1], verts[k + 2], 1.0f);
      pfglSequencePointEXT();
    }
    pfglEnd();
    pfglFinish();
    if (frame >= warmup) ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  run.executed = ctx->renderer.stats().pixel_instructions;
  if (pfglGetError() != GL_NO_ERROR) std::fprintf(stderr, "pffixed: a GL error drawing %s\n", v.name.c_str());
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  std::sort(ms.begin(), ms.end());
  run.frame_ms = ms.empty() ? 0.0 : ms[ms.size() / 2];
  return run;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pffixed: screen_triangle with X, Y, Z as floats and as the paper's fixed point"};
  int triangles = 20000, size = 512, frames = 20, warmup = 3;
  std::string csv;
  app.add_option("--triangles", triangles, "triangles per frame")->check(CLI::Range(1, 1000000));
  app.add_option("--size", size, "frame width and height")->check(CLI::Range(16, 4096));
  app.add_option("--frames", frames, "timed frames (the median is reported)")->check(CLI::Range(1, 100000));
  app.add_option("--warmup", warmup, "frames drawn before timing")->check(CLI::Range(0, 100000));
  app.add_option("--csv", csv, "append rows to this CSV file");
  PF_PARSE_COMMAND_LINE(app, argc, argv);

  const std::vector<Variant> vs = variants();
  if (vs.size() != 2) {
    std::fprintf(stderr, "pffixed: primitives/screen_triangle.pfl no longer declares 'varying float X, Y; inout varying float Z'\n");
    return 1;
  }
  // Triangles about 30 pixels across at random places and depths (a fixed seed), one colour
  // per vertex.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> place(0.0f, static_cast<float>(size)), off(-15.0f, 15.0f), unit(0.0f, 1.0f);
  std::vector<float> verts;
  for (int t = 0; t < triangles; ++t) {
    const float cx = place(rng), cy = place(rng), z = unit(rng);
    for (int k = 0; k < 3; ++k) verts.insert(verts.end(), {cx + off(rng), cy + off(rng), z, unit(rng), unit(rng), unit(rng), 1.0f});
  }
  std::FILE* out = csv.empty() ? nullptr : std::fopen(csv.c_str(), "a");
  if (!csv.empty() && !out) {
    std::fprintf(stderr, "pffixed: cannot open %s\n", csv.c_str());
    return 1;
  }
  const uint64_t threshold = pf::NativeProgramCache::instance().threshold();
  pf::NativeProgramCache::instance().setThreshold(0);  // native code from the first block
  std::vector<unsigned char> first_image;
  bool same = true;
  std::printf("%-7s %-12s %22s %30s %10s\n", "variant", "executor", "pixel instructions", "executed (interpreter)", "frame ms");
  for (const Variant& v : vs) {
    pf::CompiledModule module;
    pf::DiagnosticLog log;
    if (!pf::compileSource("screen_triangle_" + v.name + ".pfl", v.source, module, log) || module.primitives.empty()) {
      std::fprintf(stderr, "%s", log.format().c_str());
      return 1;
    }
    const size_t instructions = module.primitives[0]->pixel.code.size();
    for (int native : {1, 0}) {
      const Run r = draw(v, verts, size, native, frames, warmup);
      if (first_image.empty()) first_image = r.image;
      same = same && r.image == first_image;
      const uint64_t executed = native ? 0 : r.executed / static_cast<uint64_t>(frames);  // per frame
      std::printf("%-7s %-12s %22zu %30llu %10.2f\n", v.name.c_str(), native ? "native" : "interpreter", instructions,
                  static_cast<unsigned long long>(executed), r.frame_ms);
      if (out)
        std::fprintf(out, "%s,%d,%d,%d,%d,%zu,%llu,%.3f\n", v.name.c_str(), native, triangles, size, frames, instructions,
                     static_cast<unsigned long long>(executed), r.frame_ms);
    }
  }
  pf::NativeProgramCache::instance().setThreshold(threshold);
  if (out) std::fclose(out);
  if (!same) {
    std::fprintf(stderr, "pffixed: the fixed-point and float images differ\n");
    return 1;
  }
  return 0;
}
