// The SIMD loops of the float form (float_evaluator.h) and the gradient form
// (gradient_evaluator.h) over slot programs: Highway, compiled for every x86 target it knows and
// dispatched at run time to the best one this machine has (AVX-512 here, AVX2 or SSE4
// elsewhere) -- the build itself targets baseline x86-64, whose SSE2 is all that
// auto-vectorization could use. exp, log, sin and cos are Highway's vector versions (at most
// 1, 4, 3 and 3 ULP from the correctly rounded value); their lanes outside Highway's valid
// ranges (exp above 104, log of x <= 0 or inf, sin / cos beyond +-39000, NaN) are recomputed
// with the C library, so every input keeps C's meaning (inf, NaN, 0) there. min and max are
// the tape's NaN-ignoring ones, lane for lane as field_scalar.h defines them.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/field/slot_loops_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include <cmath>

#include "compiler/field/perlin_tables.h"
#include "compiler/field/sampled_grid.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/gradient_evaluator.h"

HWY_BEFORE_NAMESPACE();
namespace pf::field {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Lanes of v whose input is outside Highway's valid range (`valid` false: NaN included),
// recomputed by the C library's f.
template <class D, class V, class M>
V fixLanes(D d, V v, M valid, V x, float (*f)(float), bool (*inRange)(float)) {
  if (hn::AllTrue(d, valid)) return v;
  HWY_ALIGN float xs[hn::MaxLanes(d)];
  HWY_ALIGN float vs[hn::MaxLanes(d)];
  hn::Store(x, d, xs);
  hn::Store(v, d, vs);
  for (size_t j = 0; j < hn::Lanes(d); ++j)
    if (!inRange(xs[j])) vs[j] = f(xs[j]);
  return hn::Load(d, vs);
}

float cExp(float v) { return std::exp(v); }
float cLog(float v) { return std::log(v); }
float cSin(float v) { return std::sin(v); }
float cCos(float v) { return std::cos(v); }
float cAtan(float v) { return std::atan(v); }
// Highway's valid ranges (hwy/contrib/math/math-inl.h), NaN outside all of them.
bool expRange(float v) { return v <= 104.0f; }
bool logRange(float v) { return v > 0.0f && v <= 3.4028235e38f; }
bool trigRange(float v) { return std::fabs(v) <= 39000.0f; }
bool atanRange(float v) { return v == v; }

template <class D>
void RunFloatSlotsWith(D d, const FloatSlotInstr* code, size_t count, float* base, const float* x, const float* y,
                       const float* z, int n) {
  const size_t N = hn::Lanes(d);
  const size_t end = (static_cast<size_t>(n) + N - 1) / N * N;  // <= kBatch: kBatch is a multiple
  for (size_t k = 0; k < count; ++k) {
    const FloatSlotInstr& in = code[k];
    float* HWY_RESTRICT o = base + static_cast<size_t>(in.out) * FloatEvaluator::kBatch;
    const float* HWY_RESTRICT a = base + static_cast<size_t>(in.a) * FloatEvaluator::kBatch;
    const float* HWY_RESTRICT b = base + static_cast<size_t>(in.b) * FloatEvaluator::kBatch;
    const float* HWY_RESTRICT c = base + static_cast<size_t>(in.c) * FloatEvaluator::kBatch;
    switch (in.op) {
      case FieldOp::X: case FieldOp::Y: case FieldOp::Z: {
        const float* src = in.op == FieldOp::X ? x : in.op == FieldOp::Y ? y : z;
        for (int j = 0; j < n; ++j) o[j] = src ? src[j] : 0.0f;
        continue;
      }
      case FieldOp::Const: {
        const auto c = hn::Set(d, in.value);
        for (size_t j = 0; j < end; j += N) hn::StoreU(c, d, o + j);
        continue;
      }
      case FieldOp::Sample:  // the grid's own scalar code (another file): the same on every target
        in.grid->values(x, y, z, n, o);
        continue;
      case FieldOp::NoisePerm: case FieldOp::NoiseGradX: case FieldOp::NoiseGradY: case FieldOp::NoiseGradZ:
        for (int j = 0; j < n; ++j) o[j] = perlinTableValue(in.op, a[j]);  // a gather: lane by lane
        continue;
      default: break;
    }
    for (size_t j = 0; j < end; j += N) {
      const auto va = hn::LoadU(d, a + j);
      hn::Vec<decltype(d)> r = va;
      switch (in.op) {
        case FieldOp::Neg: r = hn::Neg(va); break;
        case FieldOp::Abs: r = hn::Abs(va); break;
        case FieldOp::Square: r = hn::Mul(va, va); break;
        case FieldOp::Sqrt: r = hn::Sqrt(va); break;
        case FieldOp::Exp:
          r = fixLanes(d, hn::CallExp(d, va), hn::Le(va, hn::Set(d, 104.0f)), va, cExp, expRange);
          break;
        case FieldOp::Log: {
          const auto ok = hn::And(hn::Gt(va, hn::Zero(d)), hn::Le(va, hn::Set(d, 3.4028235e38f)));
          r = fixLanes(d, hn::CallLog(d, va), ok, va, cLog, logRange);
          break;
        }
        case FieldOp::Sin: case FieldOp::Cos: {
          const auto ok = hn::Le(hn::Abs(va), hn::Set(d, 39000.0f));
          r = in.op == FieldOp::Sin ? fixLanes(d, hn::CallSin(d, va), ok, va, cSin, trigRange)
                                    : fixLanes(d, hn::CallCos(d, va), ok, va, cCos, trigRange);
          break;
        }
        case FieldOp::Atan: r = fixLanes(d, hn::CallAtan(d, va), hn::Not(hn::IsNaN(va)), va, cAtan, atanRange); break;
        case FieldOp::Floor: r = hn::Floor(va); break;
        case FieldOp::Add: r = hn::Add(va, hn::LoadU(d, b + j)); break;
        case FieldOp::Sub: r = hn::Sub(va, hn::LoadU(d, b + j)); break;
        case FieldOp::Mul: r = hn::Mul(va, hn::LoadU(d, b + j)); break;
        case FieldOp::Div: r = hn::Div(va, hn::LoadU(d, b + j)); break;
        case FieldOp::Min: case FieldOp::Max: {
          // (a < b || b != b) ? a : b, and its mirror for max (field_scalar.h). IsNaN, not Ne:
          // Highway's Ne is an ordered compare on AVX2 and AVX-512 (false for NaN).
          const auto vb = hn::LoadU(d, b + j);
          const auto pick_a = hn::Or(in.op == FieldOp::Min ? hn::Lt(va, vb) : hn::Gt(va, vb), hn::IsNaN(vb));
          r = hn::IfThenElse(pick_a, va, vb);
          break;
        }
        case FieldOp::Less: case FieldOp::LessEq: {  // ordered compares: false for NaN, as C's
          const auto vb = hn::LoadU(d, b + j);
          r = hn::IfThenElseZero(in.op == FieldOp::Less ? hn::Lt(va, vb) : hn::Le(va, vb), hn::Set(d, 1.0f));
          break;
        }
        case FieldOp::Select:  // a != 0 (a NaN condition counts as true, as in C)
          r = hn::IfThenElse(hn::Eq(va, hn::Zero(d)), hn::LoadU(d, c + j), hn::LoadU(d, b + j));
          break;
        default: break;
      }
      hn::StoreU(r, d, o + j);
    }
  }
}

// Batches of a few points (bisection, a block's few hit lanes) run on vectors no wider than
// they need: a full AVX-512 vector for 2 points costs more than a 4-lane one (measured on the
// fractal model: sampling 1.35x slower with full-width vectors than with SSE4).
void RunFloatSlots(const FloatSlotInstr* code, size_t count, float* base, const float* x, const float* y,
                   const float* z, int n) {
  if (n <= 4) return RunFloatSlotsWith(hn::CappedTag<float, 4>(), code, count, base, x, y, z, n);
  if (n <= 8) return RunFloatSlotsWith(hn::CappedTag<float, 8>(), code, count, base, x, y, z, n);
  RunFloatSlotsWith(hn::ScalableTag<float>(), code, count, base, x, y, z, n);
}

// The gradient form: slot s holds value, d/dx, d/dy, d/dz as four arrays of kBatch floats.
// Each operation as GradientEvaluator's chain rule (gradient_evaluator.h), lane for lane.
template <class D>
void RunGradientSlotsWith(D d, const FloatSlotInstr* code, size_t count, float* base, const float* x, const float* y,
                          const float* z, int n) {
  constexpr size_t K = FloatEvaluator::kBatch;
  if (n <= 0) return;  // (GradientEvaluator clamps n to [0, kBatch]: this tells the compiler so)
  using V = hn::Vec<D>;
  const size_t N = hn::Lanes(d);
  const size_t end = (static_cast<size_t>(n) + N - 1) / N * N;
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0f);
  for (size_t k = 0; k < count; ++k) {
    const FloatSlotInstr& in = code[k];
    float* HWY_RESTRICT o = base + static_cast<size_t>(in.out) * 4 * K;
    const float* HWY_RESTRICT a = base + static_cast<size_t>(in.a) * 4 * K;
    const float* HWY_RESTRICT b = base + static_cast<size_t>(in.b) * 4 * K;
    const float* HWY_RESTRICT c = base + static_cast<size_t>(in.c) * 4 * K;
    if (in.op == FieldOp::Sample) {  // value and partial derivatives: the grid's own scalar code
      in.grid->valuesAndGradients(x, y, z, n, o, K);
      continue;
    }
    if (isNoiseTable(in.op)) {  // a table look-up, lane by lane; a step: derivatives exactly 0
      for (int j = 0; j < n; ++j) o[j] = perlinTableValue(in.op, a[j]);
      for (size_t j = 0; j < end; j += N)
        for (int c = 0; c < 3; ++c) hn::StoreU(zero, d, o + (c + 1) * K + j);
      continue;
    }
    if (in.op == FieldOp::X || in.op == FieldOp::Y || in.op == FieldOp::Z) {
      const int axis = in.op == FieldOp::X ? 0 : in.op == FieldOp::Y ? 1 : 2;
      const float* src = axis == 0 ? x : axis == 1 ? y : z;
      for (int j = 0; j < n; ++j) o[j] = src ? src[j] : 0.0f;
      for (size_t j = 0; j < end; j += N)
        for (int c = 0; c < 3; ++c) hn::StoreU(c == axis ? one : zero, d, o + (c + 1) * K + j);
      continue;
    }
    for (size_t j = 0; j < end; j += N) {
      V r, dx, dy, dz;
      if (in.op == FieldOp::Const) {
        r = hn::Set(d, in.value);
        dx = dy = dz = zero;
      } else if (in.op == FieldOp::Select) {  // the chosen operand's value and derivatives
        const auto take_c = hn::Eq(hn::LoadU(d, a + j), zero);
        r = hn::IfThenElse(take_c, hn::LoadU(d, c + j), hn::LoadU(d, b + j));
        dx = hn::IfThenElse(take_c, hn::LoadU(d, c + K + j), hn::LoadU(d, b + K + j));
        dy = hn::IfThenElse(take_c, hn::LoadU(d, c + 2 * K + j), hn::LoadU(d, b + 2 * K + j));
        dz = hn::IfThenElse(take_c, hn::LoadU(d, c + 3 * K + j), hn::LoadU(d, b + 3 * K + j));
      } else {
        const V av = hn::LoadU(d, a + j), ax = hn::LoadU(d, a + K + j), ay = hn::LoadU(d, a + 2 * K + j),
                az = hn::LoadU(d, a + 3 * K + j);
        V f = one;  // unary ops: the derivative factor of the chain rule
        bool unary = true;
        switch (in.op) {
          case FieldOp::Neg: r = hn::Neg(av); f = hn::Set(d, -1.0f); break;
          case FieldOp::Abs: r = hn::Abs(av); f = hn::IfThenElse(hn::Lt(av, zero), hn::Set(d, -1.0f), one); break;
          case FieldOp::Square: r = hn::Mul(av, av); f = hn::Mul(hn::Set(d, 2.0f), av); break;
          case FieldOp::Sqrt: r = hn::Sqrt(av); f = hn::Div(hn::Set(d, 0.5f), r); break;
          case FieldOp::Exp:
            r = fixLanes(d, hn::CallExp(d, av), hn::Le(av, hn::Set(d, 104.0f)), av, cExp, expRange);
            f = r;
            break;
          case FieldOp::Log: {
            const auto ok = hn::And(hn::Gt(av, zero), hn::Le(av, hn::Set(d, 3.4028235e38f)));
            r = fixLanes(d, hn::CallLog(d, av), ok, av, cLog, logRange);
            f = hn::Div(one, av);
            break;
          }
          case FieldOp::Sin: case FieldOp::Cos: {
            const auto ok = hn::Le(hn::Abs(av), hn::Set(d, 39000.0f));
            const V s = fixLanes(d, hn::CallSin(d, av), ok, av, cSin, trigRange);
            const V c = fixLanes(d, hn::CallCos(d, av), ok, av, cCos, trigRange);
            r = in.op == FieldOp::Sin ? s : c;
            f = in.op == FieldOp::Sin ? c : hn::Neg(s);
            break;
          }
          case FieldOp::Atan:
            r = fixLanes(d, hn::CallAtan(d, av), hn::Not(hn::IsNaN(av)), av, cAtan, atanRange);
            f = hn::Div(one, hn::Add(one, hn::Mul(av, av)));
            break;
          case FieldOp::Floor: r = hn::Floor(av); break;  // a step: derivative 0 (not defined at the integers)
          default: unary = false; break;
        }
        if (unary && in.op == FieldOp::Floor) {
          dx = dy = dz = zero;  // exactly 0, even where a's own derivatives are not finite
        } else if (unary) {
          dx = hn::Mul(f, ax);
          dy = hn::Mul(f, ay);
          dz = hn::Mul(f, az);
        } else {
          const V bv = hn::LoadU(d, b + j), bx = hn::LoadU(d, b + K + j), by = hn::LoadU(d, b + 2 * K + j),
                  bz = hn::LoadU(d, b + 3 * K + j);
          switch (in.op) {
            case FieldOp::Add: r = hn::Add(av, bv); dx = hn::Add(ax, bx); dy = hn::Add(ay, by); dz = hn::Add(az, bz); break;
            case FieldOp::Sub: r = hn::Sub(av, bv); dx = hn::Sub(ax, bx); dy = hn::Sub(ay, by); dz = hn::Sub(az, bz); break;
            case FieldOp::Mul:
              r = hn::Mul(av, bv);
              dx = hn::Add(hn::Mul(ax, bv), hn::Mul(av, bx));
              dy = hn::Add(hn::Mul(ay, bv), hn::Mul(av, by));
              dz = hn::Add(hn::Mul(az, bv), hn::Mul(av, bz));
              break;
            case FieldOp::Div: {
              r = hn::Div(av, bv);
              const V inv = hn::Div(one, bv);
              dx = hn::Mul(hn::Sub(ax, hn::Mul(r, bx)), inv);
              dy = hn::Mul(hn::Sub(ay, hn::Mul(r, by)), inv);
              dz = hn::Mul(hn::Sub(az, hn::Mul(r, bz)), inv);
              break;
            }
            case FieldOp::Less: case FieldOp::LessEq:  // a step: derivative 0 (where defined)
              r = hn::IfThenElseZero(in.op == FieldOp::Less ? hn::Lt(av, bv) : hn::Le(av, bv), one);
              dx = dy = dz = zero;
              break;
            default: {  // Min, Max: the side the float form returns, value and derivatives
              const auto wins = in.op == FieldOp::Min ? hn::Le(av, bv) : hn::Ge(av, bv);
              const auto take_a = hn::AndNot(hn::IsNaN(av), hn::Or(wins, hn::IsNaN(bv)));
              r = hn::IfThenElse(take_a, av, bv);
              dx = hn::IfThenElse(take_a, ax, bx);
              dy = hn::IfThenElse(take_a, ay, by);
              dz = hn::IfThenElse(take_a, az, bz);
              break;
            }
          }
        }
      }
      hn::StoreU(r, d, o + j);
      hn::StoreU(dx, d, o + K + j);
      hn::StoreU(dy, d, o + 2 * K + j);
      hn::StoreU(dz, d, o + 3 * K + j);
    }
  }
}

void RunGradientSlots(const FloatSlotInstr* code, size_t count, float* base, const float* x, const float* y,
                      const float* z, int n) {
  if (n <= 4) return RunGradientSlotsWith(hn::CappedTag<float, 4>(), code, count, base, x, y, z, n);
  if (n <= 8) return RunGradientSlotsWith(hn::CappedTag<float, 8>(), code, count, base, x, y, z, n);
  RunGradientSlotsWith(hn::ScalableTag<float>(), code, count, base, x, y, z, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace pf::field
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace pf::field {

HWY_EXPORT(RunFloatSlots);

void runFloatSlots(const FloatSlotInstr* code, size_t count, float* slots, const float* x, const float* y,
                   const float* z, int n) {
  HWY_DYNAMIC_DISPATCH(RunFloatSlots)(code, count, slots, x, y, z, n);
}

HWY_EXPORT(RunGradientSlots);

void runGradientSlots(const FloatSlotInstr* code, size_t count, float* slots, const float* x, const float* y,
                      const float* z, int n) {
  HWY_DYNAMIC_DISPATCH(RunGradientSlots)(code, count, slots, x, y, z, n);
}

// Highway orders targets best first by their lowest bit; the dispatch takes the best supported.
const char* floatSlotsTarget() {
  const int64_t targets = hwy::SupportedTargets() & HWY_TARGETS;
  return hwy::TargetName(targets & -targets);
}

namespace {
// Every target compiled in and supported by this CPU (the mock, if any, lifted first).
int64_t machineTargets() {
  static const int64_t targets = [] {
    hwy::SetSupportedTargetsForTest(0);
    return hwy::SupportedTargets() & HWY_TARGETS;
  }();
  return targets;
}
}  // namespace

std::vector<std::string> floatSlotsTargets() {
  std::vector<std::string> out;
  for (int64_t t = machineTargets(); t != 0; t &= t - 1) out.push_back(hwy::TargetName(t & -t));
  return out;
}

bool useFloatSlotsTarget(const std::string& name) {
  const int64_t all = machineTargets();
  if (name.empty() || name == "best") {
    hwy::SetSupportedTargetsForTest(0);
    return true;
  }
  for (int64_t t = all; t != 0; t &= t - 1)
    if (name == hwy::TargetName(t & -t)) {
      hwy::SetSupportedTargetsForTest(t & -t);
      return true;
    }
  return false;
}

}  // namespace pf::field
#endif  // HWY_ONCE
