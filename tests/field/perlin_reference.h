// HyperFun's Perlin noise as its C code computes it (perlin.h's noise3, hfA_turbulence.c's loop),
// in double over primflow's tables: the reference the noise tests compare tapes and pixels with.
#pragma once

#include <cmath>

#include "compiler/field/perlin_tables.h"

namespace pf::field::testing {

// perlin.h's noise3, in double, over the primflow tables (HyperFun's code, macros expanded).
inline double noise3(const double vec[3]) {
  const PerlinTables& tb = perlinTables();
  int b0[3], b1[3];
  double r0[3], r1[3];
  for (int k = 0; k < 3; ++k) {
    const double t = vec[k] + 4096.0;
    b0[k] = static_cast<int>(t) & 255;
    b1[k] = (b0[k] + 1) & 255;
    r0[k] = t - static_cast<int>(t);
    r1[k] = r0[k] - 1.0;
  }
  const int i = tb.perm[b0[0]], j = tb.perm[b1[0]];
  const int b00 = tb.perm[i + b0[1]], b10 = tb.perm[j + b0[1]];
  const int b01 = tb.perm[i + b1[1]], b11 = tb.perm[j + b1[1]];
  auto s_curve = [](double t) { return t * t * (3.0 - 2.0 * t); };
  auto lerp = [](double t, double a, double b) { return a + t * (b - a); };
  auto at3 = [&](int corner, double rx, double ry, double rz) {
    const double* q = tb.grad[corner];
    return rx * q[0] + ry * q[1] + rz * q[2];
  };
  const double t = s_curve(r0[0]), sy = s_curve(r0[1]), sz = s_curve(r0[2]);
  double a = lerp(t, at3(b00 + b0[2], r0[0], r0[1], r0[2]), at3(b10 + b0[2], r1[0], r0[1], r0[2]));
  double b = lerp(t, at3(b01 + b0[2], r0[0], r1[1], r0[2]), at3(b11 + b0[2], r1[0], r1[1], r0[2]));
  const double c = lerp(sy, a, b);
  a = lerp(t, at3(b00 + b1[2], r0[0], r0[1], r1[2]), at3(b10 + b1[2], r1[0], r0[1], r1[2]));
  b = lerp(t, at3(b01 + b1[2], r0[0], r1[1], r1[2]), at3(b11 + b1[2], r1[0], r1[1], r1[2]));
  const double d = lerp(sy, a, b);
  return lerp(sz, c, d);
}

// hfA_Turbulence's loop.
inline double turbulence(const double x[3], double freq) {
  double t = 0;
  for (; freq >= 1.0; freq /= 2) {
    const double xt[3] = {x[0] * freq, x[1] * freq, x[2] * freq};
    t += std::fabs(2 * noise3(xt) - 1.0) / freq;
  }
  return t;
}

}  // namespace pf::field::testing
