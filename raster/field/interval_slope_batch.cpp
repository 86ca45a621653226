// IntervalSlopeBatchEvaluator: IntervalSlopeEvaluator::evaluate's switch, lane for lane over the
// pairs, from the branch-free interval operations of interval_lanes.h (-fno-trapping-math for
// this file, as for interval_batch.cpp). tests/field/interval_batch_test.cpp holds it to the
// scalar evaluator, bit for bit.
#include "raster/field/interval_slope_batch.h"

#include <stdexcept>

#include "raster/field/interval_lanes.h"
#include "raster/field/sampled_bounds.h"
#include "raster/simd_clones.h"

namespace pf::field {
namespace {

using namespace interval_lanes;
constexpr int K = IntervalSlopeBatchEvaluator::kBoxes;

// One slot's four arrays.
struct SlotLanes {
  float* vlo;
  float* vhi;
  float* rlo;
  float* rhi;
};

// minSide (interval_slope_evaluator.cpp): which operand min(a, b) is over the box, 1 (a), 2 (b)
// or 0 (either); only finite operands decide.
inline int minSide(float alo, float ahi, float blo, float bhi) {
  const bool decidable = finite(alo, ahi) & finite(blo, bhi);
  const int side = ahi <= blo ? 1 : bhi <= alo ? 2 : 0;
  return decidable ? side : 0;
}

// One instruction over lanes [0, n): value and rate. `o` never shares a slot with an operand.
PF_SIMD_CLONES void runSlopeInstruction(const FloatSlotInstr& in, int n, const SlotLanes& o, const SlotLanes& a,
                                        const SlotLanes& b, const SlotLanes& c) {
  float* __restrict vlo = o.vlo;
  float* __restrict vhi = o.vhi;
  float* __restrict rlo = o.rlo;
  float* __restrict rhi = o.rhi;
  const float* __restrict avlo = a.vlo;
  const float* __restrict avhi = a.vhi;
  const float* __restrict arlo = a.rlo;
  const float* __restrict arhi = a.rhi;
  const float* __restrict bvlo = b.vlo;
  const float* __restrict bvhi = b.vhi;
  const float* __restrict brlo = b.rlo;
  const float* __restrict brhi = b.rhi;
  switch (in.op) {
    case FieldOp::Const:
      for (int j = 0; j < n; ++j) {
        vlo[j] = vhi[j] = in.value;
        rlo[j] = rhi[j] = 0.0f;
      }
      break;
    case FieldOp::Neg:
      for (int j = 0; j < n; ++j) {
        vlo[j] = -avhi[j], vhi[j] = -avlo[j];
        rlo[j] = -arhi[j], rhi[j] = -arlo[j];
      }
      break;
    case FieldOp::Abs:
      for (int j = 0; j < n; ++j) {
        absLane(avlo[j], avhi[j], vlo[j], vhi[j]);
        // The rate's sign follows a's where a keeps one; both signs where a spans 0.
        const bool pos = avlo[j] >= 0.0f, neg = avhi[j] <= 0.0f;
        float hlo, hhi;
        hullLane(arlo[j], arhi[j], -arhi[j], -arlo[j], hlo, hhi);
        rlo[j] = pos ? arlo[j] : neg ? -arhi[j] : hlo;
        rhi[j] = pos ? arhi[j] : neg ? -arlo[j] : hhi;
      }
      break;
    case FieldOp::Square:
      for (int j = 0; j < n; ++j) {
        squareLane(avlo[j], avhi[j], vlo[j], vhi[j]);
        float tlo, thi;  // 2a, then (2a) a'
        mulLane(2.0f, 2.0f, avlo[j], avhi[j], tlo, thi);
        mulLane(tlo, thi, arlo[j], arhi[j], rlo[j], rhi[j]);
      }
      break;
    case FieldOp::Sqrt:
      for (int j = 0; j < n; ++j) {
        sqrtLane(avlo[j], avhi[j], vlo[j], vhi[j]);
        float tlo, thi;  // a' / (2 sqrt(a))
        mulLane(2.0f, 2.0f, vlo[j], vhi[j], tlo, thi);
        divLane(arlo[j], arhi[j], tlo, thi, rlo[j], rhi[j]);
      }
      break;
    case FieldOp::Add:
      for (int j = 0; j < n; ++j) {
        addLane(avlo[j], avhi[j], bvlo[j], bvhi[j], vlo[j], vhi[j]);
        addLane(arlo[j], arhi[j], brlo[j], brhi[j], rlo[j], rhi[j]);
      }
      break;
    case FieldOp::Sub:
      for (int j = 0; j < n; ++j) {
        addLane(avlo[j], avhi[j], -bvhi[j], -bvlo[j], vlo[j], vhi[j]);
        addLane(arlo[j], arhi[j], -brhi[j], -brlo[j], rlo[j], rhi[j]);
      }
      break;
    case FieldOp::Mul:
      for (int j = 0; j < n; ++j) {
        mulLane(avlo[j], avhi[j], bvlo[j], bvhi[j], vlo[j], vhi[j]);
        float plo, phi, qlo, qhi;  // a' b + a b'
        mulLane(arlo[j], arhi[j], bvlo[j], bvhi[j], plo, phi);
        mulLane(avlo[j], avhi[j], brlo[j], brhi[j], qlo, qhi);
        addLane(plo, phi, qlo, qhi, rlo[j], rhi[j]);
      }
      break;
    case FieldOp::Div:
      for (int j = 0; j < n; ++j) {
        divLane(avlo[j], avhi[j], bvlo[j], bvhi[j], vlo[j], vhi[j]);
        float plo, phi, qlo, qhi;  // (a' - (a/b) b') / b
        mulLane(vlo[j], vhi[j], brlo[j], brhi[j], plo, phi);
        addLane(arlo[j], arhi[j], -phi, -plo, qlo, qhi);
        divLane(qlo, qhi, bvlo[j], bvhi[j], rlo[j], rhi[j]);
      }
      break;
    case FieldOp::Min:
    case FieldOp::Max: {
      const bool is_min = in.op == FieldOp::Min;
      for (int j = 0; j < n; ++j) {
        const float a0 = avlo[j], a1 = avhi[j], b0 = bvlo[j], b1 = bvhi[j];
        const float min_lo = b0 < a0 ? b0 : a0, min_hi = b1 < a1 ? b1 : a1;
        const float max_lo = a0 < b0 ? b0 : a0, max_hi = a1 < b1 ? b1 : a1;
        vlo[j] = is_min ? min_lo : max_lo;
        vhi[j] = is_min ? min_hi : max_hi;
        const int side = is_min ? minSide(a0, a1, b0, b1) : minSide(b0, b1, a0, a1);
        float hlo, hhi;
        hullLane(arlo[j], arhi[j], brlo[j], brhi[j], hlo, hhi);
        rlo[j] = side == 1 ? arlo[j] : side == 2 ? brlo[j] : hlo;
        rhi[j] = side == 1 ? arhi[j] : side == 2 ? brhi[j] : hhi;
      }
      break;
    }
    case FieldOp::Less:
    case FieldOp::LessEq: {
      const bool or_equal = in.op == FieldOp::LessEq;
      for (int j = 0; j < n; ++j) {
        const float a0 = avlo[j], a1 = avhi[j], b0 = bvlo[j], b1 = bvhi[j];
        const bool both_finite = finite(a0, a1) & finite(b0, b1);
        const bool yes = both_finite & (or_equal ? a1 <= b0 : a1 < b0);
        const bool no = both_finite & !yes & (or_equal ? a0 > b1 : a0 >= b1);
        vlo[j] = yes ? 1.0f : 0.0f;
        vhi[j] = no ? 0.0f : 1.0f;
        // A step inside the box: its rate is the whole line.
        rlo[j] = (yes | no) ? 0.0f : -kInf;
        rhi[j] = (yes | no) ? 0.0f : kInf;
      }
      break;
    }
    case FieldOp::Floor:  // constant over the box (rate 0) unless it steps inside it
    case FieldOp::NoisePerm:  // (the table look-ups too: one entry over the box, or a step)
    case FieldOp::NoiseGradX:
    case FieldOp::NoiseGradY:
    case FieldOp::NoiseGradZ:
      for (int j = 0; j < n; ++j) {
        const Interval a{avlo[j], avhi[j]};
        const Interval v = in.op == FieldOp::Floor ? intervalFloor(a) : intervalNoiseTable(in.op, a);
        const bool constant = finite(v.lo, v.hi) & (v.lo == v.hi);
        vlo[j] = v.lo, vhi[j] = v.hi;
        rlo[j] = constant ? 0.0f : -kInf;
        rhi[j] = constant ? 0.0f : kInf;
      }
      break;
    case FieldOp::Select:
      for (int j = 0; j < n; ++j) {
        const float a0 = avlo[j], a1 = avhi[j];
        const bool left = finite(a0, a1) & ((a0 > 0.0f) | (a1 < 0.0f));
        const bool right = !left & (a0 == 0.0f) & (a1 == 0.0f);
        float hlo, hhi;
        hullLane(bvlo[j], bvhi[j], c.vlo[j], c.vhi[j], hlo, hhi);
        vlo[j] = left ? bvlo[j] : right ? c.vlo[j] : hlo;
        vhi[j] = left ? bvhi[j] : right ? c.vhi[j] : hhi;
        rlo[j] = left ? brlo[j] : right ? c.rlo[j] : -kInf;  // may switch sides inside the box
        rhi[j] = left ? brhi[j] : right ? c.rhi[j] : kInf;
      }
      break;
    case FieldOp::Exp:
    case FieldOp::Log:
    case FieldOp::Sin:
    case FieldOp::Cos:
    case FieldOp::Atan:
      // The value by the scalar operation, lane by lane; the rate as the scalar evaluator
      // composes it.
      for (int j = 0; j < n; ++j) {
        const Interval av{avlo[j], avhi[j]};
        Interval v, r;
        switch (in.op) {
          case FieldOp::Exp: v = intervalExp(av), r = intervalMul(v, {arlo[j], arhi[j]}); break;
          case FieldOp::Log: v = intervalLog(av), r = intervalDiv({arlo[j], arhi[j]}, av); break;
          case FieldOp::Sin: v = intervalSin(av), r = intervalMul(intervalCos(av), {arlo[j], arhi[j]}); break;
          case FieldOp::Cos:
            v = intervalCos(av), r = intervalNeg(intervalMul(intervalSin(av), {arlo[j], arhi[j]}));
            break;
          default:
            v = intervalAtan(av);
            r = intervalDiv({arlo[j], arhi[j]}, intervalAdd(Interval::point(1.0f), intervalSquare(av)));
            break;
        }
        vlo[j] = v.lo, vhi[j] = v.hi, rlo[j] = r.lo, rhi[j] = r.hi;
      }
      break;
    case FieldOp::X:
    case FieldOp::Y:
    case FieldOp::Z:
    case FieldOp::Sample: return;  // (the evaluator fills these from the pairs)
  }
  // Anything whose value may be NaN or infinite has no rate bound.
  for (int j = 0; j < n; ++j) {
    const bool bounded = finite(vlo[j], vhi[j]);
    rlo[j] = bounded ? rlo[j] : -kInf;
    rhi[j] = bounded ? rhi[j] : kInf;
  }
}

}  // namespace

void IntervalSlopeBatchEvaluator::reset(const FieldTape& tape) {
  try {
    buildSlotProgram(tape, program_, scratch_);
  } catch (...) {
    program_ = SlotProgram{};
    throw;
  }
  const size_t size = static_cast<size_t>(program_.slot_count) * 4 * K;
  if (values_.size() < size) values_.resize(size, 0.0f);
}

void IntervalSlopeBatchEvaluator::evaluate(const Boxes& boxes, int n, IntervalSlope* out) {
  n = n < 0 ? 0 : n > K ? K : n;
  if (program_.code.empty()) {
    for (int j = 0; j < n; ++j) out[j] = {Interval::whole(), Interval::whole()};
    return;
  }
  const int lanes = (n + 15) / 16 * 16;
  float* const base = values_.data();
  auto slot = [&](uint16_t s) {
    float* p = base + static_cast<size_t>(s) * 4 * K;
    return SlotLanes{p, p + K, p + 2 * K, p + 3 * K};
  };
  for (const FloatSlotInstr& in : program_.code) {
    const SlotLanes o = slot(in.out);
    if (in.op == FieldOp::X || in.op == FieldOp::Y || in.op == FieldOp::Z) {
      const int axis = in.op == FieldOp::X ? 0 : in.op == FieldOp::Y ? 1 : 2;
      const float* const from[4][3] = {{boxes.x_lo, boxes.y_lo, boxes.z_lo},
                                       {boxes.x_hi, boxes.y_hi, boxes.z_hi},
                                       {boxes.dx_lo, boxes.dy_lo, boxes.dz_lo},
                                       {boxes.dx_hi, boxes.dy_hi, boxes.dz_hi}};
      float* const to[4] = {o.vlo, o.vhi, o.rlo, o.rhi};
      for (int q = 0; q < 4; ++q)
        for (int j = 0; j < lanes; ++j) to[q][j] = from[q][axis][j < n ? j : 0];  // lanes past n: pair 0
      continue;
    }
    if (in.op == FieldOp::Sample) {  // the grid over each box and its directions (lanes past n: pair 0)
      for (int j = 0; j < lanes; ++j) {
        const int q = j < n ? j : 0;
        Interval v, r;
        sampleSlope(*in.grid, {boxes.x_lo[q], boxes.x_hi[q]}, {boxes.y_lo[q], boxes.y_hi[q]}, {boxes.z_lo[q], boxes.z_hi[q]},
                    {boxes.dx_lo[q], boxes.dx_hi[q]}, {boxes.dy_lo[q], boxes.dy_hi[q]}, {boxes.dz_lo[q], boxes.dz_hi[q]}, v, r);
        const bool bounded = std::isfinite(v.lo) && std::isfinite(v.hi);
        o.vlo[j] = v.lo, o.vhi[j] = v.hi;
        o.rlo[j] = bounded ? r.lo : -kInf, o.rhi[j] = bounded ? r.hi : kInf;
      }
      continue;
    }
    runSlopeInstruction(in, lanes, o, slot(in.a), slot(in.b), slot(in.c));
  }
  const SlotLanes r = slot(static_cast<uint16_t>(program_.result_slot));
  for (int j = 0; j < n; ++j) out[j] = {{r.vlo[j], r.vhi[j]}, {r.rlo[j], r.rhi[j]}};
}

}  // namespace pf::field
