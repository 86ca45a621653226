// pfcompile: what native code costs to make. Context creation (every built-in primitive
// registered) with and without native code, and each built-in primitive's pixel program, its
// covered variant, its block-rejection walk (of one region, and of 16 blocks at once) and its
// setup program (16 instances at once) compiled for the machine's instruction set with a
// 4-channel perspective-correct layout, timed one by one (fresh keys: a compile each).
//   pfcompile [--csv FILE]      CSV: what,name,ms
#include <CLI/CLI.hpp>

#include "tools/command_line.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <primflow/context.h>

#include "compiler/builtin_primitives.h"
#include "compiler/native/native_cache.h"
#include "raster/lane_kernels.h"
#include "raster/setup_batch.h"

namespace {

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// Median of `n` context creations (and destructions) with PF_JIT = `native`.
double contextMs(int native, int n) {
  std::vector<double> t;
  for (int i = 0; i < n; ++i) {
    const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, 1, PF_JIT, native, 0};
    const auto t0 = std::chrono::steady_clock::now();
    PFcontext ctx = pfCreateContextAttribs(attribs);
    pfDestroyContext(ctx);
    t.push_back(msSince(t0));
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pfcompile: the cost of native code: context creation, and each built-in program's compile"};
  std::string csv;
  app.add_option("--csv", csv, "write what,name,ms rows to this file (replaced)");
  PF_PARSE_COMMAND_LINE(app, argc, argv);
  if (!pf::nativeCodeAvailable()) {
    std::fprintf(stderr, "pfcompile: native code is unavailable here\n");
    return 1;
  }
  struct Row {
    std::string what, name;
    double ms;
  };
  std::vector<Row> rows;
  contextMs(1, 3);  // warm-up: the built-ins compile to bytecode once per process
  rows.push_back({"context", "interpreter", contextMs(0, 21)});
  rows.push_back({"context", "native", contextMs(1, 21)});

  pf::NativePixelVariant v;
  v.isa = pf::laneIsa() == pf::LaneIsa::Avx512 ? pf::NativeIsa::Avx512
          : pf::laneIsa() == pf::LaneIsa::Avx2 ? pf::NativeIsa::Avx2 : pf::NativeIsa::Sse2;
  v.channels = 4;
  v.kind_end[0] = 4;
  v.kind_begin[1] = v.kind_end[1] = v.kind_begin[2] = v.kind_end[2] = 4;
  pf::NativeProgramCache& cache = pf::NativeProgramCache::instance();
  for (const auto& prim : pf::builtinPrimitives().in_order) {
    v.writes_normal = prim->writes_normal;
    v.named_bound.assign(prim->named_interpolators.size(), false);
    auto time = [&](const char* what, const pf::PixelProgram& program, bool verdict) {
      pf::NativeProgramCache::Entry* e = verdict ? cache.verdictEntry(program) : cache.pixelEntry(program, v);
      const auto t0 = std::chrono::steady_clock::now();
      const bool made = cache.compile(e, program, verdict ? nullptr : &v) != nullptr;
      if (made) rows.push_back({what, prim->name, msSince(t0)});
    };
    time("pixel", prim->pixel, false);
    if (prim->pixel.covered) time("covered", *prim->pixel.covered, false);
    if (pf::nativeVerdictSupports(prim->pixel)) {
      time("verdict", prim->pixel, true);
      // The walk over a region's 16 blocks at once.
      pf::NativeProgramCache::Entry* e = cache.blockVerdictsEntry(prim->pixel, v.isa, pf::kNativeVerdictLanes);
      const auto t0 = std::chrono::steady_clock::now();
      if (cache.compileBlockVerdicts(e, prim->pixel, v.isa, pf::kNativeVerdictLanes))
        rows.push_back({"blocks", prim->name, msSince(t0)});
    }
    // The setup program over 16 instances at once, with the same layout (a primitive calling
    // others is set up by the interpreter: raster/setup_batch.h).
    if (pf::BatchSetupExecutor::batchable(*prim)) {
      pf::NativeSetupVariant sv;
      sv.isa = v.isa;
      sv.channels = v.channels;
      for (int k = 0; k < 3; ++k) {
        sv.kind_begin[k] = v.kind_begin[k];
        sv.kind_end[k] = v.kind_end[k];
      }
      sv.named_bound = v.named_bound;
      pf::NativeProgramCache::Entry* e = cache.setupEntry(prim->setup, sv);
      const auto t0 = std::chrono::steady_clock::now();
      if (cache.compileSetup(e, prim->setup, sv)) rows.push_back({"setup", prim->name, msSince(t0)});
    }
  }
  std::printf("%-9s %-18s %9s\n", "what", "name", "ms");
  for (const Row& r : rows) std::printf("%-9s %-18s %9.2f\n", r.what.c_str(), r.name.c_str(), r.ms);
  if (!csv.empty()) {
    std::FILE* f = std::fopen(csv.c_str(), "w");
    if (!f) {
      std::fprintf(stderr, "pfcompile: cannot write %s\n", csv.c_str());
      return 1;
    }
    std::fprintf(f, "what,name,ms,isa\n");
    for (const Row& r : rows) std::fprintf(f, "%s,%s,%.3f,%s\n", r.what.c_str(), r.name.c_str(), r.ms, pf::nativeIsaName(v.isa));
    std::fclose(f);
  }
  return 0;
}
