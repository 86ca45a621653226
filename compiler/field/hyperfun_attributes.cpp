// HyperFun's attribute library (hfA_*) as tape builders: the functions that compute or write the
// s array -- the colour (or other photometric values) a model defines per point, which seed 000
// (Fryazinov and Pasko, "Shading") evaluates at the hit point with the shape and shades with.
// Each is HyperFun's code restated ([HFC] src/hflibrary_lib/hfA_*.c, shared/hyperfun.md a.6),
// its branches on the point as the tape's Select: a write into s is, per item, `condition ?
// new value : old value`, so the s items stay Reals like every array item and the model's final
// s becomes one tape per item (hyperfun_reader.cpp). HyperFun's calling convention reverses its
// argument array (f_a[0] is the last argument); the orders below are the calls' own, read off
// that reversal, and docs/hyperfun.md lists the quirks it exposes (hfA_Pulse's bounds, hfA_Cerp).
#include <cmath>

#include "compiler/field/hyperfun_library_internal.h"

namespace pf::field::hyperfun {

namespace {

using Items = std::vector<Real>;
Real K(double v) { return Real::known(v); }

// HyperFun's `f >= 0.0` as a tape value (1 or 0; 0 where f is NaN, as C's comparison).
Real atLeastZero(TapeAlgebra& m, Real f) { return m.lessEq(K(0.0), f); }

}  // namespace

// hfA_SetColor(f, s, r, g, b): where f >= 0, s[1..3] = (r, g, b); returns 1.
Real hfASetColor(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& s = atLeast(c, 1, 3);
  const Real inside = atLeastZero(m, c.reals[0]);
  for (size_t k = 0; k < 3; ++k) s[k] = m.select(inside, c.reals[2 + k], s[k]);
  return K(1.0);
}

// hfA_SetAttributes(f, s, s1): where f >= 0, the first min(|s|, |s1|) items of s become s1's.
Real hfASetAttributes(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& s = *c.arrays[1];
  const Items& s1 = *c.arrays[2];
  const Real inside = atLeastZero(m, c.reals[0]);
  for (size_t k = 0; k < std::min(s.size(), s1.size()); ++k) s[k] = m.select(inside, s1[k], s[k]);
  return K(1.0);
}

// hfA_Lerp(s, s1, s2, f, fmin, fmax): t = (f - fmin)/(fmax - fmin); s = s1 where t < 0, s2 where
// t > 1, (1 - t) s1 + t s2 between; returns t (not clamped). HyperFun registers hfA_Cerp with
// this same code, so hfA_Cerp is hfA_Lerp too.
Real hfALerp(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const size_t n = sameSizes(c, 0, 2);
  Items& s = *c.arrays[0];
  const Items &s1 = *c.arrays[1], &s2 = *c.arrays[2];
  const Real t = m.div(m.sub(c.reals[3], c.reals[4]), m.sub(c.reals[5], c.reals[4]));
  const Real below = m.less(t, K(0.0)), above = m.less(K(1.0), t);
  for (size_t k = 0; k < n; ++k) {
    const Real mixed = m.add(m.mul(m.sub(K(1.0), t), s1[k]), m.mul(t, s2[k]));
    s[k] = m.select(below, s1[k], m.select(above, s2[k], mixed));
  }
  return t;
}

// hfA_Clamp(f, a, b): a where f < a, else b where f > b, else f.
Real hfAClamp(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Real f = c.reals[0], a = c.reals[1], b = c.reals[2];
  return m.select(m.less(f, a), a, m.select(m.less(b, f), b, f));
}

// hfA_Pulse(f, p, q): 0 where f < q, else 0 where f > p, else 1. HyperFun's comment calls it
// (f, a, b) with a the lower bound, but its code takes the third argument as the lower bound
// and the second as the upper: what it computes is followed.
Real hfAPulse(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Real f = c.reals[0], upper = c.reals[1], lower = c.reals[2];
  return m.select(m.less(f, lower), K(0.0), m.select(m.less(upper, f), K(0.0), K(1.0)));
}

// hfA_Step(f, a): 0 where f < a, else 1.
Real hfAStep(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  return m.select(m.less(c.reals[0], c.reals[1]), K(0.0), K(1.0));
}

// hfA_SmoothStep(f, a, b): 1 where f > b, else 0 where f < a, else t^2 (3 - 2t) with
// t = (f - a)/(b - a).
Real hfASmoothStep(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Real f = c.reals[0], a = c.reals[1], b = c.reals[2];
  const Real t = m.div(m.sub(f, a), m.sub(b, a));
  const Real smooth = m.mul(m.square(t), m.sub(K(3.0), m.mul(K(2.0), t)));
  return m.select(m.less(b, f), K(1.0), m.select(m.less(f, a), K(0.0), smooth));
}

// hfA_Wave(v, c1, c2, freq): (1 + sin(freq v))/2 mapped onto [min(c1, c2), max(c1, c2)].
Real hfAWave(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Real v = c.reals[0], c1 = c.reals[1], c2 = c.reals[2], freq = c.reals[3];
  const Real wave = m.mul(m.add(K(1.0), m.sin(m.mul(freq, v))), K(0.5));
  const Real c1_above = m.less(c2, c1);
  const Real lo = m.select(c1_above, c2, c1), hi = m.select(c1_above, c1, c2);
  return m.add(m.mul(wave, m.sub(hi, lo)), lo);
}

// hfA_Union(f1, f2, s, s1, s2, op): the R-union f1 | f2 is returned; where it is > -1e-6, s
// takes s1 where only f1 >= 0, s2 where only f2 >= 0, and elsewhere (both inside, or both
// outside on the union's blend) by `op`, which must be known: 0 s1, 1 s2, 2 s1 + s2, 3 the
// smaller item, 4 the larger (any other op leaves s as it was).
Real hfAUnion(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Real f1 = c.reals[0], f2 = c.reals[1];
  const size_t n = sameSizes(c, 2, 4);
  Items& s = *c.arrays[2];
  const Items &s1 = *c.arrays[3], &s2 = *c.arrays[4];
  const double op = std::trunc(knownArg(c, 5, "it chooses how the attributes combine"));
  const Real united = m.unite(f1, f2);
  const Real applies = m.less(K(-kEps), united);
  const Real in1 = atLeastZero(m, f1), in2 = atLeastZero(m, f2);
  const Real only1 = m.mul(in1, m.sub(K(1.0), in2)), only2 = m.mul(in2, m.sub(K(1.0), in1));
  for (size_t k = 0; k < n; ++k) {
    Real both = s[k];
    if (op == 0.0) both = s1[k];
    if (op == 1.0) both = s2[k];
    if (op == 2.0) both = m.add(s1[k], s2[k]);
    if (op == 3.0) both = m.select(m.less(s2[k], s1[k]), s2[k], s1[k]);
    if (op == 4.0) both = m.select(m.less(s2[k], s1[k]), s1[k], s2[k]);
    s[k] = m.select(applies, m.select(only1, s1[k], m.select(only2, s2[k], both)), s[k]);
  }
  return united;
}

// hfA_Floor(v): C's (int) cast of v -- truncation towards zero, despite the name -- as a double
// (past int's range C's cast is undefined; primflow keeps truncating). hfA_Modulo(a, b):
// a - b (int)(a/b), plus b where that is negative. On the tape through floor (TapeAlgebra::trunc).
Real hfAFloor(LibraryCall& c) { return c.alg.trunc(c.reals[0]); }
Real hfAModulo(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Real a = c.reals[0], b = c.reals[1];
  const Real r = m.sub(a, m.mul(m.trunc(m.div(a, b)), b));
  return m.select(m.less(r, K(0.0)), m.add(r, b), r);
}

}  // namespace pf::field::hyperfun
