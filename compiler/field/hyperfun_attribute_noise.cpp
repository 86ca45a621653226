// HyperFun's Perlin noise as tape builders: hfA_NoiseP (noise3 of the point) and hfA_Turbulence
// (its octaves), each HyperFun's C code restated ([HFC] src/hflibrary_lib/perlin.h,
// hfA_noisep.c, hfA_turbulence.c). noise3 is Ebert et al.'s: the point's lattice cell hashed
// through the permutation p, a unit gradient g3 per corner, a cubic s-curve to blend the eight
// corners. Its table reads are the tape's look-up operations (FieldOp::NoisePerm ... NoiseGradZ,
// compiler/field/perlin_tables.h says which tables); everything else is arithmetic, in HyperFun's
// order of operations. A known point folds in double, as HyperFun computes.
#include <cmath>
#include <vector>

#include "compiler/field/hyperfun_library_internal.h"

namespace pf::field::hyperfun {

namespace {

using Items = std::vector<Real>;
Real K(double v) { return Real::known(v); }

constexpr double kNoiseBound = 1.75;      // > sqrt(3): |noise3| where every coordinate >= -4096
constexpr double kFarNoiseBound = 2600.0;  // > 9^3 2 sqrt(3): |noise3| anywhere

// perlin.h's setup_perlin for one coordinate v: t = v + 4096 (PERLIN_N), b0 = (int)t & 255,
// b1 = (b0 + 1) & 255, r0 = t - (int)t, r1 = r0 - 1.
struct LatticeAxis {
  Real b0, b1, r0, r1;
  Real below;  // 1 where v < -4096 (t < 0, where C's cast truncates upwards), else 0
};

LatticeAxis latticeAxis(TapeAlgebra& m, Real v) {
  if (v.is_known) {  // HyperFun's own double arithmetic
    const double t = v.value + 4096.0;
    const double whole = std::trunc(t);
    const double b0 = whole - 256.0 * std::floor(whole / 256.0);  // & 255 of a two's complement int
    return {K(b0), K(b0 == 255.0 ? 0.0 : b0 + 1.0), K(t - whole), K(t - whole - 1.0), K(t < 0.0 ? 1.0 : 0.0)};
  }
  // On the tape, in float, t = v + 4096 would round v's fraction to 2^-11. Where t >= 0 the whole
  // part is floor(v) + 4096 and the fraction v - floor(v), both exact (4096 is a multiple of 256,
  // so the cell is floor(v) & 255). Below (v < -4096) t itself is exact -- v's own spacing is
  // 2^-11 or coarser there -- and C's (int) truncates it towards zero.
  const Real below = m.less(v, K(-4096.0));
  const Real lower = m.floor(v);
  const Real t = m.add(v, K(4096.0));
  const Real whole = m.select(below, m.trunc(t), lower);
  const Real fraction = m.select(below, m.sub(t, whole), m.sub(v, lower));
  const Real b0 = m.sub(whole, m.mul(K(256.0), m.floor(m.div(whole, K(256.0)))));
  const Real b1 = m.select(m.less(b0, K(255.0)), m.add(b0, K(1.0)), K(0.0));
  return {b0, b1, fraction, m.sub(fraction, K(1.0)), below};
}

// s_curve(t) = t * t * (3 - 2 t); lerp(t, a, b) = a + t (b - a).
Real sCurve(TapeAlgebra& m, Real t) { return m.mul(m.mul(t, t), m.sub(K(3.0), m.mul(K(2.0), t))); }
Real lerp(TapeAlgebra& m, Real t, Real a, Real b) { return m.add(a, m.mul(t, m.sub(b, a))); }

// at3 with q = g3[corner]: rx q[0] + ry q[1] + rz q[2].
Real gradientDot(TapeAlgebra& m, Real corner, Real rx, Real ry, Real rz) {
  const Real qx = m.noiseTable(FieldOp::NoiseGradX, corner);
  const Real qy = m.noiseTable(FieldOp::NoiseGradY, corner);
  const Real qz = m.noiseTable(FieldOp::NoiseGradZ, corner);
  return m.add(m.add(m.mul(rx, qx), m.mul(ry, qy)), m.mul(rz, qz));
}

// perlin.h's noise3(vec).
Real noise3(TapeAlgebra& m, Real vx, Real vy, Real vz) {
  const LatticeAxis x = latticeAxis(m, vx), y = latticeAxis(m, vy), z = latticeAxis(m, vz);
  const Real i = m.noiseTable(FieldOp::NoisePerm, x.b0);
  const Real j = m.noiseTable(FieldOp::NoisePerm, x.b1);
  const Real b00 = m.noiseTable(FieldOp::NoisePerm, m.add(i, y.b0));
  const Real b10 = m.noiseTable(FieldOp::NoisePerm, m.add(j, y.b0));
  const Real b01 = m.noiseTable(FieldOp::NoisePerm, m.add(i, y.b1));
  const Real b11 = m.noiseTable(FieldOp::NoisePerm, m.add(j, y.b1));
  const Real t = sCurve(m, x.r0), sy = sCurve(m, y.r0), sz = sCurve(m, z.r0);

  // The four corners of the z = bz face, blended along x then y (one statement per step, so the
  // tape is built in HyperFun's order whatever order a compiler evaluates arguments in).
  auto face = [&](Real bz, Real rz) {
    Real u = gradientDot(m, m.add(b00, bz), x.r0, y.r0, rz);
    Real v = gradientDot(m, m.add(b10, bz), x.r1, y.r0, rz);
    const Real a = lerp(m, t, u, v);
    u = gradientDot(m, m.add(b01, bz), x.r0, y.r1, rz);
    v = gradientDot(m, m.add(b11, bz), x.r1, y.r1, rz);
    const Real b = lerp(m, t, u, v);
    return lerp(m, sy, a, b);
  };
  const Real c = face(z.b0, z.r0);
  const Real d = face(z.b1, z.r1);
  const Real noise = lerp(m, sz, c, d);
  // A bound noise3 never exceeds, as a clamp that changes no value: over a box spanning lattice
  // cells the table look-ups reach whole tables, and without it the interval form of noise in a
  // shape left nearly every box near the surface undecided. Where every coordinate is >= -4096,
  // each corner's term is a unit gradient dotted with an offset of length at most sqrt(3) and the
  // lerps' weights lie in [0, 1]: |noise3| < 1.75. Below -4096 HyperFun's truncation leaves
  // fractions in (-1, 0]: offsets up to 2 per axis (terms up to 2 sqrt(3)) and s-curve weights up
  // to 5, each lerp at most 9 times its operands: |noise3| < 9^3 2 sqrt(3) < 2600.
  if (noise.is_known) return noise;
  const Real far_out = m.max(m.max(x.below, y.below), z.below);
  const Real bound = m.select(far_out, K(kFarNoiseBound), K(kNoiseBound));
  return m.max(m.min(noise, bound), m.neg(bound));
}

}  // namespace

// hfA_NoiseP(x): noise3 of the point's first three items.
Real hfANoiseP(LibraryCall& c) {
  const Items& x = atLeast(c, 0, 3);
  return noise3(c.alg, x[0], x[1], x[2]);
}

// hfA_Turbulence(x, freq): for (t = 0; freq >= 1; freq /= 2) t += |2 noise3(x freq) - 1| / freq.
// The loop is unrolled when the model is compiled, so freq must be known then; a NaN freq runs no
// octave (t = 0, as in HyperFun), an infinite one never ends there and is refused here.
Real hfATurbulence(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Items& x = atLeast(c, 0, 3);
  double freq = knownArg(c, 1, "its octaves are unrolled when the model is compiled");
  if (std::isinf(freq))
    reject(1, paramLabel(c, 1) + " is infinite: HyperFun's loop halving it until it is below 1 never ends");
  Real sum = K(0.0);
  for (; freq >= 1.0; freq /= 2) {
    const Real xt = m.mul(x[0], K(freq)), yt = m.mul(x[1], K(freq)), zt = m.mul(x[2], K(freq));
    const Real n = noise3(m, xt, yt, zt);
    sum = m.add(sum, m.div(m.abs(m.sub(m.mul(K(2.0), n), K(1.0))), K(freq)));
  }
  return sum;
}

}  // namespace pf::field::hyperfun
