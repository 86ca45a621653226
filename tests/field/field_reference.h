// Test-only references for fields: a double-precision evaluation of a tape, the reference hit
// along a ray (dense double marching + bisection), and a double interpreter of Fidget .vm text
// that shares nothing with the reader under test. (Also used by bench/pffields for accuracy.)
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <fstream>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "compiler/field/field_tape.h"
#include "compiler/field/perlin_tables.h"
#include "compiler/field/sampled_grid.h"

namespace pf::field::testing {

#ifdef PF_MODELS_DIR
inline std::string readModelText(const std::string& relative) {
  std::ifstream in(std::string(PF_MODELS_DIR) + "/" + relative);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
#endif

inline double dmin(double a, double b) { return (a < b || b != b) ? a : b; }
inline double dmax(double a, double b) { return (a > b || b != b) ? a : b; }

// A sampled grid's value in double, written apart from SampledGrid: a sum over samples of a
// kernel of the distance in grid units -- the hat function max(0, 1 - |t|) for trilinear, the
// cubic B-spline kernel for tricubic -- with the coordinate clamped to the grid and the samples
// past its edges repeating the edge sample.
inline double sampledReference(const SampledGrid& g, double x, double y, double z) {
  const double p[3] = {x, y, z};
  double u[3];
  for (int a = 0; a < 3; ++a) {
    u[a] = (p[a] - g.boxMin(a)) / (g.boxMax(a) - g.boxMin(a)) * (g.size(a) - 1);
    u[a] = std::min(std::max(u[a], 0.0), static_cast<double>(g.size(a) - 1));
  }
  const bool cubic = g.interpolation() == SampleInterpolation::CubicBSpline;
  auto kernel = [cubic](double t) {
    t = std::fabs(t);
    if (!cubic) return t < 1.0 ? 1.0 - t : 0.0;
    if (t < 1.0) return (4.0 - 6.0 * t * t + 3.0 * t * t * t) / 6.0;
    if (t < 2.0) return (2.0 - t) * (2.0 - t) * (2.0 - t) / 6.0;
    return 0.0;
  };
  auto clampIndex = [&](int i, int a) { return std::min(std::max(i, 0), g.size(a) - 1); };
  double sum = 0.0;
  int base[3];
  for (int a = 0; a < 3; ++a) base[a] = static_cast<int>(std::floor(u[a]));
  for (int k = base[2] - 2; k <= base[2] + 3; ++k)
    for (int j = base[1] - 2; j <= base[1] + 3; ++j)
      for (int i = base[0] - 2; i <= base[0] + 3; ++i) {
        const double w = kernel(u[0] - i) * kernel(u[1] - j) * kernel(u[2] - k);
        if (w != 0.0) sum += w * g.sample(clampIndex(i, 0), clampIndex(j, 1), clampIndex(k, 2));
      }
  return sum;
}

// The tape evaluated in double (same operation meanings as the float form). `scratch` saves an
// allocation per call in dense reference loops.
inline double evaluateDouble(const FieldTape& tape, double x, double y, double z, std::vector<double>* scratch = nullptr) {
  std::vector<double> local;
  std::vector<double>& v = scratch ? *scratch : local;
  v.resize(tape.instrs.size());
  for (size_t i = 0; i < tape.instrs.size(); ++i) {
    const FieldInstr& in = tape.instrs[i];
    const double a = fieldOpArity(in.op) >= 1 ? v[in.a] : 0.0;
    const double b = fieldOpArity(in.op) >= 2 ? v[in.b] : 0.0;
    double r = 0.0;
    switch (in.op) {
      case FieldOp::X: r = x; break;
      case FieldOp::Y: r = y; break;
      case FieldOp::Z: r = z; break;
      case FieldOp::Const: r = in.value; break;
      case FieldOp::Neg: r = -a; break;
      case FieldOp::Abs: r = std::fabs(a); break;
      case FieldOp::Square: r = a * a; break;
      case FieldOp::Sqrt: r = std::sqrt(a); break;
      case FieldOp::Exp: r = std::exp(a); break;
      case FieldOp::Log: r = std::log(a); break;
      case FieldOp::Sin: r = std::sin(a); break;
      case FieldOp::Cos: r = std::cos(a); break;
      case FieldOp::Atan: r = std::atan(a); break;
      case FieldOp::Floor: r = std::floor(a); break;
      case FieldOp::NoisePerm: case FieldOp::NoiseGradX: case FieldOp::NoiseGradY: case FieldOp::NoiseGradZ: {
        // HyperFun's tables as it holds them (ints, double gradients) at floor(a), clamped.
        if (a != a) { r = a; break; }
        const double k = std::clamp(std::floor(a), 0.0, static_cast<double>(kPerlinTableSize - 1));
        const PerlinTables& t = perlinTables();
        const int table = perlinTableOf(in.op);
        r = table == 0 ? t.perm[static_cast<int>(k)] : t.grad[static_cast<int>(k)][table - 1];
        break;
      }
      case FieldOp::Add: r = a + b; break;
      case FieldOp::Sub: r = a - b; break;
      case FieldOp::Mul: r = a * b; break;
      case FieldOp::Div: r = a / b; break;
      case FieldOp::Min: r = dmin(a, b); break;
      case FieldOp::Max: r = dmax(a, b); break;
      case FieldOp::Less: r = a < b ? 1.0 : 0.0; break;
      case FieldOp::LessEq: r = a <= b ? 1.0 : 0.0; break;
      case FieldOp::Select: r = a != 0.0 ? b : v[in.c]; break;
      case FieldOp::Sample: r = sampledReference(*tape.grids[static_cast<size_t>(in.value)], x, y, z); break;
    }
    v[i] = r;
  }
  return v[tape.result];
}

// The reference hit on a ray (test-only, as the issue asks): dense double-precision marching over
// [entry, exit] in `steps` steps, then bisection to 1e-12. +inf where no sample is inside.
inline double referenceHit(const FieldTape& tape, const std::array<double, 3>& o, const std::array<double, 3>& d,
                           double entry, double exit, int steps) {
  if (!(exit >= entry)) return std::numeric_limits<double>::infinity();
  std::vector<double> scratch;
  auto f = [&](double t) { return evaluateDouble(tape, o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2], &scratch); };
  if (f(entry) >= 0.0) return entry;
  double prev = entry;
  for (int k = 1; k <= steps; ++k) {
    const double t = entry + (exit - entry) * k / steps;
    if (f(t) >= 0.0) {
      double lo = prev, hi = t;
      while (hi - lo > 1e-12) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) >= 0.0 ? hi : lo) = mid;
      }
      return hi;
    }
    prev = t;
  }
  return std::numeric_limits<double>::infinity();
}

// Fidget's own meaning of a .vm text, in double (negative inside, as the file says).
inline double interpretVmDouble(const std::string& text, double x, double y, double z) {
  std::unordered_map<std::string, double> val;
  std::istringstream lines(text);
  std::string line;
  double last = 0.0;
  while (std::getline(lines, line)) {
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::string name, op, a, b;
    if (!(words >> name >> op)) continue;
    words >> a >> b;
    double r = 0.0;
    if (op == "var-x") r = x;
    else if (op == "var-y") r = y;
    else if (op == "var-z") r = z;
    else if (op == "const") r = std::stod(a);
    else if (op == "neg") r = -val.at(a);
    else if (op == "abs") r = std::fabs(val.at(a));
    else if (op == "square") r = val.at(a) * val.at(a);
    else if (op == "sqrt") r = std::sqrt(val.at(a));
    else if (op == "exp") r = std::exp(val.at(a));
    else if (op == "ln") r = std::log(val.at(a));
    else if (op == "sin") r = std::sin(val.at(a));
    else if (op == "cos") r = std::cos(val.at(a));
    else if (op == "add") r = val.at(a) + val.at(b);
    else if (op == "sub") r = val.at(a) - val.at(b);
    else if (op == "mul") r = val.at(a) * val.at(b);
    else if (op == "div") r = val.at(a) / val.at(b);
    else if (op == "min") r = dmin(val.at(a), val.at(b));
    else if (op == "max") r = dmax(val.at(a), val.at(b));
    else throw std::runtime_error("reference interpreter: unknown op " + op);
    val[name] = r;
    last = r;
  }
  return last;
}

}  // namespace pf::field::testing
