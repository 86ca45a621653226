// The arithmetic of the language's fixed<bits,frac> type (docs/language.md, "Fixed-point
// numbers"): a signed two's-complement integer of `bits` bits (1..64) counting units of
// 2^-frac (0 <= frac <= bits). PixelFlow's pixel processors computed on integers of any width
// (paper section 3); this is that arithmetic, defined once for the constant folder, the setup
// executors, the pixel executor and the reference interpreter.
//
// A fixed value occupies two 32-bit slots, its low and high words (the raw integer
// sign-extended to 64 bits). Every instruction on fixed values (Op::QAdd ... Op::QConv) reads
// its operands as word pairs -- (a, b) the first, (c, d) the second -- and produces one 32-bit
// word: imm says which half, and the format of the result.
//
// The rules:
//  - arithmetic (+ - * / negation, abs) wraps modulo 2^bits, as integer hardware does;
//  - products and quotients are rounded to the nearest unit, ties away from zero;
//  - division by zero gives 0 (as int division: a masked-off lane must not trap);
//  - conversions into a fixed type (from float, int or another format) round to nearest, ties
//    away from zero, and saturate to the format's range; NaN converts to 0;
//  - fixed -> float is correctly rounded; fixed -> int truncates toward zero and saturates.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace pf {

struct FixedFormat {
  int bits = 32;  // 1..64
  int frac = 0;   // 0..bits
};

constexpr int kMaxFixedBits = 64;

// imm of a fixed instruction: bit 0 the half (0 low, 1 high), bits 1-7 frac, bits 8-13 bits - 1.
constexpr int fixedImm(FixedFormat f, int half) { return (half & 1) | (f.frac << 1) | ((f.bits - 1) << 8); }
constexpr FixedFormat fixedFormatOf(uint32_t imm) {
  return FixedFormat{static_cast<int>((imm >> 8) & 63u) + 1, static_cast<int>((imm >> 1) & 127u)};
}
constexpr int fixedHalfOf(uint32_t imm) { return static_cast<int>(imm & 1u); }

inline int64_t fixedJoin(uint32_t lo, uint32_t hi) {
  return static_cast<int64_t>((static_cast<uint64_t>(hi) << 32) | lo);
}
inline uint32_t fixedHalf(int64_t v, int half) {
  return static_cast<uint32_t>(static_cast<uint64_t>(v) >> (half ? 32 : 0));
}

// The largest and smallest raw values of a `bits`-bit format.
inline int64_t fixedMax(int bits) { return static_cast<int64_t>((1ull << (bits - 1)) - 1); }
inline int64_t fixedMin(int bits) { return -fixedMax(bits) - 1; }

// The low `bits` bits of v, sign-extended: arithmetic modulo 2^bits.
inline int64_t fixedWrap(__int128 v, int bits) {
  const uint64_t low = static_cast<uint64_t>(v);
  if (bits == 64) return static_cast<int64_t>(low);
  const uint64_t mask = (1ull << bits) - 1;
  const uint64_t x = low & mask;
  return static_cast<int64_t>((x & (1ull << (bits - 1))) ? (x | ~mask) : x);
}

inline int64_t fixedSaturate(__int128 v, int bits) {
  const int64_t hi = fixedMax(bits), lo = fixedMin(bits);
  return v > hi ? hi : v < lo ? lo : static_cast<int64_t>(v);
}

// 2^s as a 128-bit integer (s 0..126): scaling by it is a multiplication, so negative values
// shift without any question of what a left shift of a negative number means.
inline __int128 pow2(int s) { return static_cast<__int128>(1) << s; }

// v / 2^shift rounded to nearest, ties away from zero (shift 0..127).
inline __int128 roundedShiftRight(__int128 v, int shift) {
  if (shift == 0) return v;
  const __int128 half = static_cast<__int128>(1) << (shift - 1);
  return v >= 0 ? (v + half) >> shift : -((-v + half) >> shift);
}

// n / d rounded to nearest, ties away from zero (d != 0).
inline __int128 roundedQuotient(__int128 n, __int128 d) {
  __int128 q = n / d, r = n % d;
  const __int128 ar = r < 0 ? -r : r, ad = d < 0 ? -d : d;
  if (2 * ar >= ad) q += ((n < 0) != (d < 0)) ? -1 : 1;
  return q;
}

inline int64_t fixedMul(int64_t a, int64_t b, FixedFormat f) {
  return fixedWrap(roundedShiftRight(static_cast<__int128>(a) * b, f.frac), f.bits);
}

inline int64_t fixedDiv(int64_t a, int64_t b, FixedFormat f) {
  if (b == 0) return 0;
  const __int128 n = a * pow2(f.frac);
  // n / -1 can be 2^127, one past the 128-bit range: negate modulo 2^128 (only the low bits count).
  if (b == -1) return fixedWrap(static_cast<__int128>(0 - static_cast<unsigned __int128>(n)), f.bits);
  return fixedWrap(roundedQuotient(n, b), f.bits);
}

inline int64_t fixedFromFloat(float x, FixedFormat f) {
  if (!(x == x)) return 0;
  // x * 2^frac is exact in double (a float's 24 bits, scaled by a power of two).
  const double scaled = std::round(std::ldexp(static_cast<double>(x), f.frac));
  const double top = std::ldexp(1.0, f.bits - 1);  // 2^(bits-1): one past the largest raw value
  if (scaled >= top) return fixedMax(f.bits);
  if (scaled < -top) return fixedMin(f.bits);
  return static_cast<int64_t>(scaled);
}

inline int64_t fixedFromInt(int32_t x, FixedFormat f) {
  return fixedSaturate(x * pow2(f.frac), f.bits);
}

// Correctly rounded: the int64 -> float conversion rounds once, and the power-of-two scale is
// exact (the smallest result, 2^-64, is a normal float).
inline float fixedToFloat(int64_t raw, int frac) {
  return std::ldexp(static_cast<float>(raw), -frac);
}

inline int32_t fixedToInt(int64_t raw, int frac) {
  const __int128 q = static_cast<__int128>(raw) / pow2(frac);  // toward zero
  return q > INT32_MAX ? INT32_MAX : q < INT32_MIN ? INT32_MIN : static_cast<int32_t>(q);
}

inline int64_t fixedConvert(int64_t raw, int from_frac, FixedFormat to) {
  const __int128 v = static_cast<__int128>(raw);
  return fixedSaturate(to.frac >= from_frac ? v * pow2(to.frac - from_frac) : roundedShiftRight(v, from_frac - to.frac),
                       to.bits);
}

}  // namespace pf
