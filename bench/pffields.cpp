// pffields: implicit surfaces, time against accuracy, per model x method x parameter
// (docs/performance.md, "Implicit surfaces"). Every model is drawn through the API as pfrender
// draws it (tools/model: --ortho view of its box), timed as the median of --frames frames after a
// warm-up, glFinish inside the timed region; accuracy against the reference of issue #8 -- per
// pixel, dense double-precision marching plus bisection to 1e-12 along the same ray -- at
// --ref-size (the reference is slow), in world units of depth and in coverage mismatches.
//   pffields [--models a.vm b.hf@x0,y0,z0,x1,y1,z1 ...] [--time 0.5] [--size 512] [--prospero-size 1024] [--ref-size 96]
//            [--ref-steps 1000] [--frames 5] [--threads 1] [--methods auto ...] [--csv FILE]
// 2D models (no z): plain per-pixel evaluation (march, 1 step) against interval culling with
// tape simplification, coverage compared over the whole image. 3D models: interval; march with
// M = 50, 500 (and 5000 for small tapes: seed 004's values); analytic where the field is a
// polynomial.
#include <CLI/CLI.hpp>

#include "tools/command_line.h"

#include <primflow/gl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "compiler/field/field_source.h"
#include "field/field_reference.h"
#include "model/model_file.h"
#include "raster/field/csg_tree.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/gradient_evaluator.h"
#include "raster/field/implicit_field.h"
#include "raster/field/ray_polynomial.h"

namespace {

struct Run {
  std::string method_name;
  int method;
  float param;
};

struct Frame {
  double ms = 0;
  std::vector<unsigned char> color;
  std::vector<float> z;  // world z, NaN where nothing
};

// Draws `model` `frames` + 1 times (the first is the warm-up) into a w x h context, a HyperFun
// model at `time`.
Frame render(const pf::model::Model& model, int w, int h, const Run& run, int threads, int frames, double time) {
  Frame f;
  f.color.assign(size_t(w) * h * 4, 0);
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  pfMakeCurrent(ctx, f.color.data(), GL_UNSIGNED_BYTE, w, h);
  pf::model::ModelView v;
  v.width = w;
  v.height = h;
  v.ortho = true;
  v.box_min = model.default_box_min;
  v.box_max = model.default_box_max;
  v.method = run.method;
  v.steps = run.param;
  v.time = time;
  std::vector<double> ms;
  for (int k = 0; k <= frames; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    pf::model::drawModel(model, v);  // clears, draws, glFinish
    const auto t1 = std::chrono::steady_clock::now();
    if (k > 0) ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  f.ms = ms.empty() ? 0.0 : ms[ms.size() / 2];
  GLint dw, dh, bytes;
  void* data = nullptr;
  pfGetDepthBuffer(ctx, &dw, &dh, &bytes, &data);
  const float* d = static_cast<const float*>(data);
  f.z = pf::model::worldDepth(model, v, std::vector<float>(d, d + size_t(w) * h));
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  return f;
}

// The reference world z per pixel of the --ortho view (NaN: no surface), on `threads` threads.
std::vector<double> reference(const pf::field::FieldTape& tape, const pf::model::Model& m, int n, int steps,
                              bool two_dimensional) {
  std::vector<double> z(size_t(n) * n);
  const glm::dvec3 lo = m.default_box_min, hi = m.default_box_max;
  auto rows = [&](int r0, int r1) {
    for (int j = r0; j < r1; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = lo.x + (i + 0.5) * (hi.x - lo.x) / n, y = lo.y + (j + 0.5) * (hi.y - lo.y) / n;
        const double t = pf::field::testing::referenceHit(tape, {x, y, hi.z}, {0, 0, -(hi.z - lo.z)}, 0.0, 1.0,
                                                          two_dimensional ? 1 : steps);
        z[size_t(j) * n + i] = std::isinf(t) ? std::nan("") : hi.z - t * (hi.z - lo.z);
      }
  };
  const int workers = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (int k = 0; k < workers; ++k) pool.emplace_back(rows, n * k / workers, n * (k + 1) / workers);
  for (auto& t : pool) t.join();
  return z;
}

struct Accuracy {
  int judged = 0, coverage_mismatches = 0;
  double max_depth = 0, mean_depth = 0;
  double max_normal_degrees = 0, mean_normal_degrees = 0;  // where both hit the surface itself
};

// The outward normal -grad f / |grad f| at p, by central differences of the field in double.
std::array<double, 3> referenceNormal(const pf::field::FieldTape& tape, const std::array<double, 3>& p, double h) {
  std::vector<double> scratch;
  std::array<double, 3> g{};
  for (int k = 0; k < 3; ++k) {
    std::array<double, 3> a = p, b = p;
    a[k] += h;
    b[k] -= h;
    g[k] = (pf::field::testing::evaluateDouble(tape, a[0], a[1], a[2], &scratch) -
            pf::field::testing::evaluateDouble(tape, b[0], b[1], b[2], &scratch)) / (2 * h);
  }
  const double len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  return {-g[0] / len, -g[1] / len, -g[2] / len};
}

// Per pixel of the n x n --ortho view of the model's box: coverage and depth against the
// reference; and the angle between the renderer's normal (the derived gradient, in float, at its
// own hit -- what shading uses) and the reference normal at the reference hit, where both hit the
// surface itself (not the box's top face, where a ray starts inside the solid).
Accuracy compare(const std::vector<float>& got, const std::vector<double>& want, const pf::field::FieldTape& tape,
                 const pf::model::Model& m, int n) {
  Accuracy a;
  int both = 0, normals = 0;
  pf::field::GradientEvaluator ge(tape);
  const glm::dvec3 lo = m.default_box_min, hi = m.default_box_max;
  const double h = 1e-6 * glm::length(hi - lo);
  for (size_t k = 0; k < want.size(); ++k) {
    ++a.judged;
    const bool g = !std::isnan(got[k]), r = !std::isnan(want[k]);
    if (g != r) {
      ++a.coverage_mismatches;
      continue;
    }
    if (!g) continue;
    const double e = std::fabs(got[k] - want[k]);
    a.max_depth = std::max(a.max_depth, e);
    a.mean_depth += e;
    ++both;
    if (m.two_dimensional || want[k] >= hi.z || got[k] >= static_cast<float>(hi.z)) continue;
    const int i = static_cast<int>(k % n), j = static_cast<int>(k / n);
    const double x = lo.x + (i + 0.5) * (hi.x - lo.x) / n, y = lo.y + (j + 0.5) * (hi.y - lo.y) / n;
    const pf::field::FieldGradient gf = ge.evaluate(static_cast<float>(x), static_cast<float>(y), got[k]);
    const double gl = std::sqrt(double(gf.dx) * gf.dx + double(gf.dy) * gf.dy + double(gf.dz) * gf.dz);
    const std::array<double, 3> nr = referenceNormal(tape, {x, y, want[k]}, h);
    if (!(gl > 0) || !std::isfinite(nr[0] + nr[1] + nr[2])) continue;
    const double c = std::clamp(-(gf.dx * nr[0] + gf.dy * nr[1] + gf.dz * nr[2]) / gl, -1.0, 1.0);
    const double deg = std::acos(c) * 180.0 / 3.14159265358979323846;
    a.max_normal_degrees = std::max(a.max_normal_degrees, deg);
    a.mean_normal_degrees += deg;
    ++normals;
  }
  if (both) a.mean_depth /= both;
  if (normals) a.mean_normal_degrees /= normals;
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pffields: implicit surfaces, time against accuracy per model and method"};
  std::vector<std::string> models;
  std::string csv;
  int size = 512, prospero_size = 1024, ref_size = 96, ref_steps = 1000, frames = 5, threads = 1;
  double time = 0.5;
  bool no_accuracy = false;
  app.add_option("--models", models,
                 ".vm / .hf files, each optionally FILE@x0,y0,z0,x1,y1,z1 with its box "
                 "(default: tests/data/models/fidget/*.vm)");
  app.add_option("--time", time, "HyperFun models' time x[4]");
  std::vector<std::string> methods;
  app.add_option("--methods", methods, "run only these methods (auto analytic interval march sphere newton regula-falsi; march, newton, regula-falsi: 64 steps)");
  app.add_option("--size", size, "3D models' image size (square)")->check(CLI::Range(8, 8192));
  app.add_option("--prospero-size", prospero_size, "2D models' image size (square)")->check(CLI::Range(8, 8192));
  app.add_option("--ref-size", ref_size, "3D accuracy image size")->check(CLI::Range(8, 1024));
  app.add_option("--ref-steps", ref_steps, "reference marching steps per ray")->check(CLI::Range(10, 1000000));
  app.add_option("--frames", frames, "timed frames after one warm-up")->check(CLI::Range(1, 1000));
  app.add_option("--threads", threads, "rasterizer threads")->check(CLI::Range(1, 256));
  app.add_option("--csv", csv, "append results here");
  std::vector<std::string> simd;
  app.add_option("--simd", simd,
                 "run each method on these instruction sets of the float loops, in turn (default: the best; "
                 "names as the float_evaluator reports them, e.g. AVX3 AVX2 SSE4 SCALAR)");
  app.add_flag("--no-accuracy", no_accuracy,
               "time only: no reference and no accuracy columns (for profiles; not with --csv)");
  PF_PARSE_COMMAND_LINE(app, argc, argv);
  if (no_accuracy && !csv.empty()) {
    std::fprintf(stderr, "pffields: --no-accuracy writes no CSV rows (they need the accuracy)\n");
    return 2;
  }
  if (simd.empty()) simd.push_back(pf::field::floatSlotsTarget());
  for (const std::string& t : simd)
    if (!pf::field::useFloatSlotsTarget(t)) {
      std::fprintf(stderr, "pffields: no instruction set '%s' here (this machine:", t.c_str());
      for (const std::string& have : pf::field::floatSlotsTargets()) std::fprintf(stderr, " %s", have.c_str());
      std::fprintf(stderr, ")\n");
      return 2;
    }

  if (models.empty()) {
    for (const auto& e : std::filesystem::directory_iterator(std::string(PF_SOURCE_DIR) + "/tests/data/models/fidget"))
      if (e.path().extension() == ".vm") models.push_back(e.path().string());
    std::sort(models.begin(), models.end());
  }
  std::ofstream out;
  if (!csv.empty()) {
    const bool fresh = !std::filesystem::exists(csv);
    out.open(csv, std::ios::app);
    if (fresh)
      out << "model,method,param,size,threads,ms_median,ref_size,judged,coverage_mismatches,max_depth_error,"
             "mean_depth_error,max_normal_degrees,mean_normal_degrees,simd\n";
  }
  std::printf("%-14s %-12s %7s %6s %6s %10s | %6s %8s %11s %11s %9s %9s\n", "model", "method", "param", "simd", "size",
              "ms", "judged", "mismatch", "max depth", "mean depth", "max N deg", "mean N");
  for (const std::string& entry : models) {
    // "FILE" or "FILE@x0,y0,z0,x1,y1,z1" (the model's box).
    std::string file = entry;
    std::optional<std::pair<glm::dvec3, glm::dvec3>> box;
    if (const size_t colon = entry.rfind('@'); colon != std::string::npos) {
      double v[6];
      if (std::sscanf(entry.c_str() + colon + 1, "%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]) == 6) {
        file = entry.substr(0, colon);
        box = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
      }
    }
    pf::model::Model m;
    try {
      m = pf::model::loadModel(file, time);
    } catch (const pf::model::ModelError& e) {
      std::fprintf(stderr, "%s", e.what());
      return 1;
    }
    pf::DiagnosticLog log;
    const pf::field::FieldTape tape = *pf::field::compileFieldSource(
        m.format, file, m.text, {}, m.format == pf::field::FieldFormat::HyperFun ? time : 0.0, log);
    const std::string name = std::filesystem::path(file).stem().string();
    // The tanglecube's file suggests --scale 0.222: its surface spans about [-3, 3]^3.
    if (name == "tanglecube") {
      m.default_box_min = glm::dvec3(-3.0);
      m.default_box_max = glm::dvec3(3.0);
    }
    if (box) {
      m.default_box_min = box->first;
      m.default_box_max = box->second;
    }
    std::vector<Run> runs;
    if (m.two_dimensional) {
      runs = {{"march", GL_FIELD_METHOD_MARCH_EXT, 1.0f}, {"interval", GL_FIELD_METHOD_INTERVAL_EXT, 0.0f}};
    } else {
      runs = {{"interval", GL_FIELD_METHOD_INTERVAL_EXT, 0.0f},
              {"march", GL_FIELD_METHOD_MARCH_EXT, 50.0f},
              {"march", GL_FIELD_METHOD_MARCH_EXT, 500.0f}};
      // M = 5000 (seed 004's finest) only where a frame of it takes seconds, not minutes.
      if (tape.size() < 100) runs.push_back({"march", GL_FIELD_METHOD_MARCH_EXT, 5000.0f});
      // Seed 000's approximate refinements of the same 50-step march's brackets.
      runs.push_back({"newton", GL_FIELD_METHOD_NEWTON_EXT, 50.0f});
      runs.push_back({"regula-falsi", GL_FIELD_METHOD_REGULA_FALSI_EXT, 50.0f});
      const int degree = pf::field::fieldPolynomialDegree(tape);
      // Analytic where the field is one polynomial, or a CSG tree of them (csg_tree.h).
      if ((degree >= 0 && degree <= 4) || pf::field::csgTreeOf(tape))
        runs.insert(runs.begin(), {"analytic", GL_FIELD_METHOD_ANALYTIC_EXT, 0.0f});
    }
    if (!methods.empty()) {
      runs.clear();
      for (const std::string& name : methods) {
        const auto method = pf::field::parseRootMethod(name);
        if (!method) {
          std::fprintf(stderr, "pffields: no method '%s'\n", name.c_str());
          return 2;
        }
        runs.push_back({name, static_cast<int>(*method), *method == pf::field::RootMethod::March || *method == pf::field::RootMethod::Newton ||
                                                             *method == pf::field::RootMethod::RegulaFalsi
                                                         ? 64.0f
                                                         : 0.0f});
      }
    }
    const int n = m.two_dimensional ? prospero_size : size;
    const int rn = m.two_dimensional ? prospero_size : ref_size;
    const std::vector<double> want = no_accuracy ? std::vector<double>{} : reference(tape, m, rn, ref_steps, m.two_dimensional);
    for (const Run& run : runs)
      for (const std::string& target : simd) {
        pf::field::useFloatSlotsTarget(target);
        const Frame timed = render(m, n, n, run, threads, frames, time);
        if (no_accuracy) {
          std::printf("%-14s %-12s %7g %6s %6d %10.2f |\n", name.c_str(), run.method_name.c_str(), run.param,
                      target.c_str(), n, timed.ms);
          continue;
        }
        const Frame judged = rn == n ? timed : render(m, rn, rn, run, threads, 0, time);
        const Accuracy a = compare(judged.z, want, tape, m, rn);
        std::printf("%-14s %-12s %7g %6s %6d %10.2f | %6d %8d %11.3g %11.3g %9.3g %9.3g\n", name.c_str(),
                    run.method_name.c_str(), run.param, target.c_str(), n, timed.ms, a.judged, a.coverage_mismatches,
                    a.max_depth, a.mean_depth, a.max_normal_degrees, a.mean_normal_degrees);
        if (out)
          out << name << ',' << run.method_name << ',' << run.param << ',' << n << ',' << threads << ',' << timed.ms
              << ',' << rn << ',' << a.judged << ',' << a.coverage_mismatches << ',' << a.max_depth << ','
              << a.mean_depth << ',' << a.max_normal_degrees << ',' << a.mean_normal_degrees << ',' << target << '\n';
      }
  }
  return 0;
}
