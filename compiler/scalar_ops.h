// The arithmetic of one lane: the single definition of every value-producing instruction,
// used by the constant folder (passes.cpp), by the scalar setup interpreter and, lane by lane,
// by the pixel executor, so that folding and both programs can never disagree on what an
// operation means.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "compiler/fixed_point.h"
#include "compiler/isa.h"
#include "compiler/perlin_noise.h"

namespace pf {

inline float asF(uint32_t x) { return std::bit_cast<float>(x); }
inline uint32_t fromF(float x) { return std::bit_cast<uint32_t>(x); }
inline int32_t asI(uint32_t x) { return static_cast<int32_t>(x); }
inline uint32_t fromI(int32_t x) { return static_cast<uint32_t>(x); }

// Float -> int conversion that saturates instead of invoking undefined behaviour; NaN -> 0.
inline int32_t saturatingToInt(float f) {
  if (!(f == f)) return 0;
  if (f >= 2147483647.0f) return 2147483647;
  if (f <= -2147483648.0f) return static_cast<int32_t>(0x80000000u);
  return static_cast<int32_t>(f);
}

// Always inlined: with `op` a constant (the pixel kernels are instantiated per op), the switch
// folds away and the lane loop around it vectorizes.
// One word of a fixed-point instruction's result (the Q ops of isa.h).
inline uint32_t evalFixed(Op op, uint32_t a, uint32_t b, uint32_t c, uint32_t d, uint32_t imm) {
  const FixedFormat f = fixedFormatOf(imm);
  const int half = fixedHalfOf(imm);
  const int64_t x = fixedJoin(a, b), y = fixedJoin(c, d);
  switch (op) {
    case Op::QAdd: return fixedHalf(fixedWrap(static_cast<__int128>(x) + y, f.bits), half);
    case Op::QSub: return fixedHalf(fixedWrap(static_cast<__int128>(x) - y, f.bits), half);
    case Op::QMul: return fixedHalf(fixedMul(x, y, f), half);
    case Op::QDiv: return fixedHalf(fixedDiv(x, y, f), half);
    case Op::QNeg: return fixedHalf(fixedWrap(-static_cast<__int128>(x), f.bits), half);
    case Op::QAbs: return fixedHalf(fixedWrap(x < 0 ? -static_cast<__int128>(x) : x, f.bits), half);
    case Op::QLt: return x < y;
    case Op::QLe: return x <= y;
    case Op::QEq: return x == y;
    case Op::QFromF: return fixedHalf(fixedFromFloat(asF(a), f), half);
    case Op::QFromI: return fixedHalf(fixedFromInt(asI(a), f), half);
    case Op::QToF: return fromF(fixedToFloat(x, f.frac));
    case Op::QToI: return fromI(fixedToInt(x, f.frac));
    case Op::QConv: return fixedHalf(fixedConvert(x, asI(c), f), half);
    default: return 0;
  }
}

// imm: the instruction's immediate, which only the fixed-point instructions read.
[[gnu::always_inline]] inline uint32_t evalScalar(Op op, uint32_t a, uint32_t b, uint32_t c, uint32_t d = 0, uint32_t imm = 0) {
  switch (op) {
    case Op::FAdd: return fromF(asF(a) + asF(b));
    case Op::FSub: return fromF(asF(a) - asF(b));
    case Op::FMul: return fromF(asF(a) * asF(b));
    case Op::FDiv: return fromF(asF(a) / asF(b));
    case Op::FMin: return fromF(asF(b) < asF(a) ? asF(b) : asF(a));
    case Op::FMax: return fromF(asF(a) < asF(b) ? asF(b) : asF(a));
    case Op::FNeg: return a ^ 0x80000000u;
    case Op::FAbs: return a & 0x7fffffffu;
    case Op::FFloor: return fromF(std::floor(asF(a)));
    case Op::FCeil: return fromF(std::ceil(asF(a)));
    case Op::FSqrt: return fromF(std::sqrt(asF(a)));
    case Op::FSign: return fromF(asF(a) > 0 ? 1.0f : asF(a) < 0 ? -1.0f : 0.0f);
    case Op::FSin: return fromF(std::sin(asF(a)));
    case Op::FCos: return fromF(std::cos(asF(a)));
    case Op::FTan: return fromF(std::tan(asF(a)));
    case Op::FAsin: return fromF(std::asin(asF(a)));
    case Op::FAcos: return fromF(std::acos(asF(a)));
    case Op::FAtan: return fromF(std::atan(asF(a)));
    case Op::FAtan2: return fromF(std::atan2(asF(a), asF(b)));
    case Op::FPow: return fromF(std::pow(asF(a), asF(b)));
    case Op::FExp: return fromF(std::exp(asF(a)));
    case Op::FLog: return fromF(std::log(asF(a)));
    case Op::FNoise: return fromF(perlinNoise(asF(a), asF(b), asF(c)));
    // Integer arithmetic wraps (two's complement); division by zero gives 0.
    case Op::IAdd: return a + b;
    case Op::ISub: return a - b;
    case Op::IMul: return a * b;
    case Op::IDiv:
      if (b == 0 || (asI(a) == INT32_MIN && asI(b) == -1)) return b == 0 ? 0 : a;
      return fromI(asI(a) / asI(b));
    case Op::IMod:
      if (b == 0 || asI(b) == -1) return 0;
      return fromI(asI(a) % asI(b));
    case Op::INeg: return 0u - a;
    case Op::IMin: return asI(a) < asI(b) ? a : b;
    case Op::IMax: return asI(a) < asI(b) ? b : a;
    case Op::IAbs: return asI(a) < 0 ? 0u - a : a;
    case Op::I2F: return fromF(static_cast<float>(asI(a)));
    case Op::F2I: return fromI(saturatingToInt(asF(a)));
    case Op::FLt: return asF(a) < asF(b);
    case Op::FLe: return asF(a) <= asF(b);
    case Op::FEq: return asF(a) == asF(b);
    case Op::FNe: return asF(a) != asF(b);
    case Op::ILt: return asI(a) < asI(b);
    case Op::ILe: return asI(a) <= asI(b);
    case Op::IEq: return a == b;
    case Op::INe: return a != b;
    case Op::BAnd: return (a & b) & 1u;
    case Op::BOr: return (a | b) & 1u;
    case Op::BNot: return a ^ 1u;
    case Op::Sel: return a ? b : c;
    case Op::CrossSign: {
      // Products of two floats are exact in double, and the sign of a difference is never
      // rounded away: an exact orientation predicate for float inputs.
      // Branch-free so that the lane loop vectorizes (packed double multiplies and compares).
      double p = static_cast<double>(asF(a)) * asF(d), q = static_cast<double>(asF(b)) * asF(c);
      return fromF(static_cast<float>(p > q) - static_cast<float>(p < q));
    }
    case Op::QAdd: case Op::QSub: case Op::QMul: case Op::QDiv: case Op::QNeg: case Op::QAbs:
    case Op::QLt: case Op::QLe: case Op::QEq: case Op::QFromF: case Op::QFromI: case Op::QToF:
    case Op::QToI: case Op::QConv:
      return evalFixed(op, a, b, c, d, imm);
    case Op::Mov: return a;
    default: return 0;
  }
}

}  // namespace pf
