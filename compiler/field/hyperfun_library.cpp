// HyperFun's built-in maths, R-functions and hf* library as tape builders (hyperfun_library.h).
// The argument checks are in hyperfun_library_internal.h; the convolution surfaces over triangles,
// meshes, arcs and radius-sized segments in hyperfun_convolution.cpp.
#include "compiler/field/hyperfun_library.h"

#include <cmath>

#include "compiler/field/hyperfun_library_internal.h"

namespace pf::field::hyperfun {

// --- Helpers for the library functions ---------------------------------------------------------
namespace {

using Items = std::vector<Real>;
Real K(double v) { return Real::known(v); }

// |v|^p for a known or point-dependent p: a small whole p multiplies, any other p is exp(p*log|v|)
// (|v| = 0 then gives exp(-inf) = 0 for p > 0, as pow does).
Real absPower(TapeAlgebra& m, Real v, Real p) {
  if (p.is_known && p.value == std::floor(p.value) && p.value >= 1.0 && p.value <= 64.0) {
    const auto n = static_cast<uint64_t>(p.value);
    return m.integerPower(n % 2 == 0 ? v : m.abs(v), n);
  }
  return m.exp(m.mul(p, m.log(m.abs(v))));
}

// The point's offsets from a centre array: d[k] = x[k] - c[k].
struct Offsets {
  Real d[3];
};
Offsets offsets(LibraryCall& c, int point_arg, int centre_arg) {
  Items& x = items(c, point_arg, 3);
  Items& ctr = items(c, centre_arg, 3);
  return {{c.alg.sub(x[0], ctr[0]), c.alg.sub(x[1], ctr[1]), c.alg.sub(x[2], ctr[2])}};
}

// The two axes off axis `axis` (0 = X, 1 = Y, 2 = Z), in HyperFun's order.
void offAxes(int axis, int& u, int& v) {
  u = axis == 0 ? 1 : 0;
  v = axis == 2 ? 1 : 2;
}

// --- Built-in maths ----------------------------------------------------------------------------

double hfRound(double v) {
  const double ce = std::ceil(v);
  return ce - v > 0.5 ? ce - 1.0 : ce;
}
// HyperFun's mod(a, b) = fmod(round(a), round(b)), its round being ceil(v) - 1 where that is more
// than 0.5 below v. Known: in double. On the point: A - B trunc(A/B) of the rounded values, exact
// while |A| < 2^24 (A/B is then never rounded across an integer).
Real fMod(LibraryCall& c) {
  const Real a = c.reals[0], b = c.reals[1];
  if (a.is_known && b.is_known) return K(std::fmod(hfRound(a.value), hfRound(b.value)));
  TapeAlgebra& m = c.alg;
  auto round = [&m](Real v) {
    const Real ce = m.neg(m.floor(m.neg(v)));
    return m.select(m.less(K(0.5), m.sub(ce, v)), m.sub(ce, K(1.0)), ce);
  };
  const Real ra = round(a), rb = round(b);
  return m.sub(ra, m.mul(rb, m.trunc(m.div(ra, rb))));
}
// The integer parts, through the tape's floor: ceil(v) = -floor(-v); int truncates; frac = v - int(v).
Real fFloor(LibraryCall& c) { return c.alg.floor(c.reals[0]); }
Real fCeil(LibraryCall& c) { return c.alg.neg(c.alg.floor(c.alg.neg(c.reals[0]))); }
Real fInt(LibraryCall& c) { return c.alg.trunc(c.reals[0]); }
Real fFrac(LibraryCall& c) { return c.alg.sub(c.reals[0], c.alg.trunc(c.reals[0])); }

template <Real (TapeAlgebra::*Op)(Real)>
Real unary(LibraryCall& c) { return (c.alg.*Op)(c.reals[0]); }
template <Real (TapeAlgebra::*Op)(Real, Real)>
Real binary(LibraryCall& c) { return (c.alg.*Op)(c.reals[0], c.reals[1]); }
Real fLogd(LibraryCall& c) {
  const Real v = c.reals[0];
  return v.is_known ? K(std::log10(v.value)) : c.alg.mul(c.alg.log(v), K(1.0 / std::log(10.0)));
}
// The inverse trigonometric functions through the tape's atan (as the language's fields do,
// compiler/field/field_unit.cpp): asin v = atan(v / sqrt(1 - v^2)), acos v = pi/2 - asin v, and
// atan2(y, x) = 2 atan(y / (sqrt(x^2 + y^2) + x)) -- C's values except on atan2's cut, the
// negative x axis itself, where the quotient is 0/0 (NaN; a set of no area).
Real fAtan(LibraryCall& c) { return c.alg.atan(c.reals[0]); }
Real fAsin(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Real v = c.reals[0];
  return v.is_known ? K(std::asin(v.value)) : m.atan(m.div(v, m.sqrt(m.sub(K(1.0), m.square(v)))));
}
Real fAcos(LibraryCall& c) {
  const Real v = c.reals[0];
  return v.is_known ? K(std::acos(v.value)) : c.alg.sub(K(std::acos(0.0)), fAsin(c));
}
Real fAtan2(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Real y = c.reals[0], x = c.reals[1];
  if (y.is_known && x.is_known) return K(std::atan2(y.value, x.value));
  const Real r = m.sqrt(m.add(m.square(x), m.square(y)));
  return m.mul(K(2.0), m.atan(m.div(y, m.add(r, x))));
}
// HyperFun's sign as its code means it (the code returns 1 always): -1 for v < 0, else 1; of a
// point-dependent v, a Select on the tape.
Real fSign(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  return m.select(m.less(c.reals[0], K(0.0)), K(-1.0), K(1.0));
}

Real fTan(LibraryCall& c) {
  const Real v = c.reals[0];
  return v.is_known ? K(std::tan(v.value)) : c.alg.div(c.alg.sin(v), c.alg.cos(v));
}
Real fSinh(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Real v = c.reals[0];
  return v.is_known ? K(std::sinh(v.value)) : m.mul(m.sub(m.exp(v), m.exp(m.neg(v))), K(0.5));
}
Real fCosh(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Real v = c.reals[0];
  return v.is_known ? K(std::cosh(v.value)) : m.mul(m.add(m.exp(v), m.exp(m.neg(v))), K(0.5));
}
// tanh v = 1 - 2/(exp(2v) + 1): no inf/inf for large |v|.
Real fTanh(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Real v = c.reals[0];
  return v.is_known ? K(std::tanh(v.value)) : m.sub(K(1.0), m.div(K(2.0), m.add(m.exp(m.mul(K(2.0), v)), K(1.0))));
}

// --- Primitives --------------------------------------------------------------------------------

Real hfSphere(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Offsets o = offsets(c, 0, 1);
  return m.sub(m.sub(m.sub(m.square(c.reals[2]), m.square(o.d[0])), m.square(o.d[1])), m.square(o.d[2]));
}

Real hfEllipsoid(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Offsets o = offsets(c, 0, 1);
  Real f = K(1.0);
  for (int k = 0; k < 3; ++k) f = m.sub(f, m.square(m.div(o.d[k], c.reals[2 + k])));
  return f;
}

template <int Axis>
Real hfCylinder(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Offsets o = offsets(c, 0, 1);
  int u, v;
  offAxes(Axis, u, v);
  return m.sub(m.sub(m.square(c.reals[2]), m.square(o.d[u])), m.square(o.d[v]));
}

template <int Axis>
Real hfEllCyl(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Offsets o = offsets(c, 0, 1);
  int u, v;
  offAxes(Axis, u, v);
  return m.sub(m.sub(K(1.0), m.square(m.div(o.d[u], c.reals[2]))), m.square(m.div(o.d[v], c.reals[3])));
}

// r0^2 - |d|^2 - R^2 + 2R sqrt(off-axis squares)
template <int Axis>
Real hfTorus(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Offsets o = offsets(c, 0, 1);
  int u, v;
  offAxes(Axis, u, v);
  const Real R = c.reals[2], r0 = c.reals[3];
  const Real off = m.add(m.square(o.d[u]), m.square(o.d[v]));
  const Real d2 = m.add(m.add(m.square(o.d[0]), m.square(o.d[1])), m.square(o.d[2]));
  return m.add(m.sub(m.sub(m.square(r0), d2), m.square(R)), m.mul(m.mul(K(2.0), R), m.sqrt(off)));
}

// Axis offset squared minus the scaled off-axis squares: a double cone (radius a, b at height 1).
template <int Axis, bool Elliptic>
Real hfCone(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Offsets o = offsets(c, 0, 1);
  int u, v;
  offAxes(Axis, u, v);
  const Real a = c.reals[2], b = Elliptic ? c.reals[3] : c.reals[2];
  return m.sub(m.sub(m.square(o.d[Axis]), m.square(m.div(o.d[u], a))), m.square(m.div(o.d[v], b)));
}

// Slabs (x - v)(v + d - x) per axis, R-intersected (alpha = 0) as (sx & sy) & sz.
Real hfBlock(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& x = items(c, 0, 3);
  Items& vertex = items(c, 1, 3);
  Real slab[3];
  for (int k = 0; k < 3; ++k) {
    const Real d = c.reals[2 + k];
    if (d.is_known && d.value < 0.0)
      reject(2 + k, paramLabel(c, 2 + k) + " is negative (HyperFun returns -1111111111111 for such a block)");
    slab[k] = m.mul(m.sub(x[k], vertex[k]), m.sub(m.add(vertex[k], d), x[k]));
  }
  return m.intersect(m.intersect(slab[0], slab[1]), slab[2]);
}

// 1 - (|X|^(2/s2) + |Y|^(2/s2))^(s2/s1) - |Z|^(2/s1), X = dx/a and so on.
Real hfSuperEll(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Offsets o = offsets(c, 0, 1);
  for (int k = 2; k <= 6; ++k)
    if (c.reals[k].is_known && std::fabs(c.reals[k].value) < kEps)
      reject(k, paramLabel(c, k) + " is within 1e-6 of 0 (HyperFun returns -1111111111111 for such a superellipsoid)");
  const Real X = m.div(o.d[0], c.reals[2]), Y = m.div(o.d[1], c.reals[3]), Z = m.div(o.d[2], c.reals[4]);
  const Real s1 = c.reals[5], s2 = c.reals[6];
  const Real p = m.div(K(2.0), s2);
  const Real xy = absPower(m, m.add(absPower(m, X, p), absPower(m, Y, p)), m.div(s2, s1));
  return m.sub(m.sub(K(1.0), xy), absPower(m, Z, m.div(K(2.0), s1)));
}

Real squaredDistance(TapeAlgebra& m, const Items& x, Real cx, Real cy, Real cz) {
  return m.add(m.add(m.square(m.sub(x[0], cx)), m.square(m.sub(x[1], cy))), m.square(m.sub(x[2], cz)));
}

// Sum of b exp(-a r^2), minus T (Blinn).
Real hfBlobby(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& x = items(c, 0, 3);
  const size_t n = sameSizes(c, 1, 5);
  Items &x0 = *c.arrays[1], &y0 = *c.arrays[2], &z0 = *c.arrays[3], &a = *c.arrays[4], &b = *c.arrays[5];
  Real sum = K(0.0);
  for (size_t i = 0; i < n; ++i)
    sum = m.add(sum, m.mul(b[i], m.exp(m.mul(m.neg(a[i]), squaredDistance(m, x, x0[i], y0[i], z0[i])))));
  return m.sub(sum, c.reals[6]);
}

// Nishimura's metaballs, with u = r/d: 1 - 3u^2 up to u = 1/3, 1.5(1 - u)^2 up to 1, then 0.
// Without branches: with w = min(u, 1/3) and v = min(max(u, 1/3), 1), the term is
// 1.5(1 - v)^2 + 3(1/3 - w)(1/3 + w), which is each piece on its interval (the pieces meet at
// 2/3 for u = 1/3 and at 0 for u = 1, and the unused piece's part vanishes exactly there).
Real hfMetaball(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& x = items(c, 0, 3);
  const size_t n = sameSizes(c, 1, 5);
  Items &x0 = *c.arrays[1], &y0 = *c.arrays[2], &z0 = *c.arrays[3], &b = *c.arrays[4];
  const Real third = K(1.0 / 3.0);
  Real sum = K(0.0);
  for (size_t i = 0; i < n; ++i) {
    const double d = knownItem(c, 5, i, "HyperFun skips the balls whose d is not positive");
    if (!(d > 0.0)) continue;
    const Real u = m.div(m.sqrt(squaredDistance(m, x, x0[i], y0[i], z0[i])), K(d));
    const Real w = m.min(u, third);
    const Real v = m.min(m.max(u, third), K(1.0));
    const Real outer = m.mul(K(1.5), m.square(m.sub(K(1.0), v)));
    const Real g = m.add(outer, m.mul(K(3.0), m.mul(m.sub(third, w), m.add(third, w))));
    sum = m.add(sum, m.mul(b[i], g));
  }
  return m.sub(sum, c.reals[6]);
}

// Wyvill's soft objects: 1 - 22q/9 + 17q^2/9 - 4q^3/9 with q = r^2/d^2 up to r = d, then 0.
// That polynomial is (1 - q)^2 (1 - 4q/9), which is 0 at q = 1: with q clamped to 1 by min it is
// the piecewise definition without a branch.
Real hfSoft(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& x = items(c, 0, 3);
  const size_t n = sameSizes(c, 1, 4);
  Items &x0 = *c.arrays[1], &y0 = *c.arrays[2], &z0 = *c.arrays[3];
  Real sum = K(0.0);
  for (size_t i = 0; i < n; ++i) {
    const double d = knownItem(c, 4, i, "HyperFun counts a blob only where r <= d");
    if (!(d > 0.0)) continue;
    const Real q = m.min(m.div(squaredDistance(m, x, x0[i], y0[i], z0[i]), K(d * d)), K(1.0));
    sum = m.add(sum, m.mul(m.square(m.sub(K(1.0), q)), m.sub(K(1.0), m.mul(K(4.0 / 9.0), q))));
  }
  return m.sub(sum, c.reals[5]);
}

// Sum of Cauchy kernels 1/(1 + S^2 r^2)^2 around points, minus T.
Real hfConvPoint(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& x = items(c, 0, 3);
  const size_t n = c.arrays[2]->size();
  Items& vect = items(c, 1, 3 * n);
  Items& S = *c.arrays[2];
  Real sum = K(0.0);
  for (size_t i = 0; i < n; ++i) {
    const Real r2 = squaredDistance(m, x, vect[3 * i], vect[3 * i + 1], vect[3 * i + 2]);
    sum = m.add(sum, m.div(K(1.0), m.square(m.add(K(1.0), m.mul(m.square(S[i]), r2)))));
  }
  return m.sub(sum, c.reals[3]);
}

// Cauchy kernels along segments (TapeAlgebra::cauchySegment), minus T: hfConvLine's segments
// run from begin[i] to end[i]; hfConvCurve's through vect's N + 1 points in turn; S[i] each.
template <bool kCurve>
Real hfConvSegments(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& x = items(c, 0, 3);
  const int s_arg = kCurve ? 2 : 3;
  const size_t n = c.arrays[s_arg]->size();
  Items& S = *c.arrays[s_arg];
  Items& from = items(c, 1, kCurve ? 3 * (n + 1) : 3 * n);
  Items& to = kCurve ? from : items(c, 2, 3 * n);
  Real sum = K(0.0);
  for (size_t i = 0; i < n; ++i) {
    const size_t e = kCurve ? 3 * (i + 1) : 3 * i;
    const Real b[3] = {from[3 * i], from[3 * i + 1], from[3 * i + 2]};
    const Real en[3] = {to[e], to[e + 1], to[e + 2]};
    const Real xs[3] = {x[0], x[1], x[2]};
    sum = m.add(sum, m.cauchySegment(xs, b, en, S[i]));
  }
  return m.sub(sum, c.reals[kCurve ? 3 : 4]);
}

// Gardner's solid noise: a product of three two-term sine series.
Real hfNoiseG(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& x = items(c, 0, 3);
  const Real amp = c.reals[1], freq = c.reals[2], phase = c.reals[3];
  Real a2p[3], s[3];
  for (int k = 0; k < 3; ++k) {
    a2p[k] = m.mul(freq, x[k]);
    s[k] = m.sin(a2p[k]);
  }
  const Real a1d = m.div(amp, K(1.17));
  Real product = K(1.0);
  for (int k = 0; k < 3; ++k) {
    const int other = (k + 2) % 3;  // x takes sin(a2 z), y sin(a2 x), z sin(a2 y)
    const Real second = m.mul(a1d, m.sin(m.add(m.div(a2p[k], K(1.35)), m.mul(phase, s[other]))));
    product = m.mul(product, m.add(m.mul(amp, s[k]), second));
  }
  return product;
}

// --- SARDF distance primitives (Fayolle): distances, positive inside ----------------------------

// r0 - sqrt((sqrt(off-axis squares) - R)^2 + axial offset^2): the distance to the torus.
template <int Axis>
Real hfDTorus(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Offsets o = offsets(c, 0, 1);
  int u, v;
  offAxes(Axis, u, v);
  const Real ring = m.sub(m.sqrt(m.add(m.square(o.d[u]), m.square(o.d[v]))), c.reals[2]);
  return m.sub(c.reals[3], m.sqrt(m.add(m.square(ring), m.square(o.d[Axis]))));
}

// R - |axis x (center - x)| / |axis|: the distance to the line through center along axis.
Real hfDCylinder(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& x = items(c, 0, 3);
  Items& ctr = items(c, 1, 3);
  Items& a = items(c, 2, 3);
  Real to[3], cross2 = K(0.0), axis2 = K(0.0);
  for (int k = 0; k < 3; ++k) {
    to[k] = m.sub(ctr[k], x[k]);
    axis2 = m.add(axis2, m.square(a[k]));
  }
  if (axis2.is_known && axis2.value == 0.0)
    reject(2, paramLabel(c, 2) + " is the zero vector: the cylinder has no direction (HyperFun divides by 0)");
  for (int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    cross2 = m.add(cross2, m.square(m.sub(m.mul(a[k1], to[k2]), m.mul(a[k2], to[k1]))));
  }
  return m.sub(c.reals[3], m.sqrt(m.div(cross2, axis2)));
}

// With t = atan(R): -(sqrt(off-axis squares) cos t - |axial offset| sin t), the (signed) distance
// to the double cone of slope R around the axis.
template <int Axis>
Real hfDCone(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Offsets o = offsets(c, 0, 1);
  int u, v;
  offAxes(Axis, u, v);
  const Real t = m.atan(c.reals[2]);
  const Real radial = m.mul(m.sqrt(m.add(m.square(o.d[u]), m.square(o.d[v]))), m.cos(t));
  return m.sub(m.mul(m.abs(o.d[Axis]), m.sin(t)), radial);
}

// --- Blends ------------------------------------------------------------------------------------

template <bool Union>
Real hfBlend(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Real f1 = c.reals[0], f2 = c.reals[1];
  const Real set = Union ? m.unite(f1, f2) : m.intersect(f1, f2);
  const Real den = m.add(m.add(K(1.0), m.square(m.div(f1, c.reals[3]))), m.square(m.div(f2, c.reals[4])));
  return m.add(set, m.div(c.reals[2], den));
}

// --- Space mappings: they overwrite their first argument's items and return 1 ------------------

Real hfShift3D(LibraryCall& c) {
  Items& p = items(c, 0, 3);
  for (int k = 0; k < 3; ++k) p[k] = c.alg.sub(p[k], c.reals[1 + k]);
  return K(1.0);
}

Real hfScale3D(LibraryCall& c) {
  Items& p = items(c, 0, 3);
  for (int k = 0; k < 3; ++k) p[k] = c.alg.div(p[k], c.reals[1 + k]);
  return K(1.0);
}

Real hfStretch3D(LibraryCall& c) {
  Items& p = items(c, 0, 3);
  Items& x0 = items(c, 1, 3);
  for (int k = 0; k < 3; ++k) p[k] = c.alg.add(x0[k], c.alg.div(c.alg.sub(p[k], x0[k]), c.reals[2 + k]));
  return K(1.0);
}

// Rotates (p[u], p[v]) by theta: (u cos + v sin, -u sin + v cos). X turns (y, z), Y (z, x), Z (x, y).
void rotate(TapeAlgebra& m, Items& p, int axis, Real theta) {
  const int u = axis == 0 ? 1 : axis == 1 ? 2 : 0;
  const int v = axis == 0 ? 2 : axis == 1 ? 0 : 1;
  const Real ct = m.cos(theta), st = m.sin(theta);
  const Real ru = m.add(m.mul(p[u], ct), m.mul(p[v], st));
  const Real rv = m.add(m.neg(m.mul(p[u], st)), m.mul(p[v], ct));
  p[u] = ru;
  p[v] = rv;
}

template <int Axis>
Real hfRotate3D(LibraryCall& c) {
  rotate(c.alg, items(c, 0, 3), Axis, c.reals[1]);
  return K(1.0);
}

// theta = (1 - t) theta1 + t theta2, t = (p - c1)/(c2 - c1) along the axis (not clamped).
template <int Axis>
Real hfTwist(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& p = items(c, 0, 3);
  const Real t = m.div(m.sub(p[Axis], c.reals[1]), m.sub(c.reals[2], c.reals[1]));
  const Real theta = m.add(m.mul(m.sub(K(1.0), t), c.reals[3]), m.mul(t, c.reals[4]));
  rotate(m, p, Axis, theta);
  return K(1.0);
}

// scale = s1 below c1, s2 above c2, (1 - t) s1 + t s2 between: the same with t clamped to [0, 1].
// HyperFun replaces a scale within 1e-6 of 0 by 1; with s1 and s2 of one sign and at least 1e-6
// in magnitude no scale comes near 0, so that case is required rather than branched on.
template <int Axis>
Real hfTaper(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& p = items(c, 0, 3);
  constexpr std::string_view why = "primflow's tapes have no branches";
  const double c1 = knownArg(c, 1, why), c2 = knownArg(c, 2, why), s1 = knownArg(c, 3, why), s2 = knownArg(c, 4, why);
  if (!(c2 > c1))
    reject(2, paramLabel(c, 2) + " must be greater than " + paramLabel(c, 1) + " (a step taper is not supported)");
  if (!((s1 >= kEps && s2 >= kEps) || (s1 <= -kEps && s2 <= -kEps)))
    reject(3, "the scales must have one sign and be at least 1e-6 in magnitude (HyperFun replaces a scale near 0 by 1, "
              "which primflow does not support)");
  const Real t = m.min(m.max(m.div(m.sub(p[Axis], K(c1)), K(c2 - c1)), K(0.0)), K(1.0));
  const Real scale = m.add(m.mul(m.sub(K(1.0), t), K(s1)), m.mul(t, K(s2)));
  int u, v;
  offAxes(Axis, u, v);
  p[u] = m.div(p[u], scale);
  p[v] = m.div(p[v], scale);
  return K(1.0);
}

// For each (source, target) triple in turn: p -= w d, d = target - source, with weight w from
// s = sum_k ((p_k - target_k) / (b_k (1 + |d_k|)))^2: exp(-s), or (1 - rho)^3/(1 + rho) for
// rho = sqrt(s) <= 1 and 0 beyond -- rho clamped to 1 by min gives that 0 without a branch.
template <bool Cubic>
Real hfSpaceMap(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& p = items(c, 0, 3);
  const size_t n = c.arrays[1]->size();
  if (n % 3 != 0)
    reject(1, paramLabel(c, 1) + " must hold 3 items per control point; '" + c.array_names[1] + "' has " +
                  std::to_string(n));
  sameSizes(c, 1, 3);
  Items &source = *c.arrays[1], &target = *c.arrays[2], &b = *c.arrays[3];
  for (size_t i = 0; i < n; i += 3) {
    Real d[3], s = K(0.0);
    for (int k = 0; k < 3; ++k) {
      d[k] = m.sub(target[i + k], source[i + k]);
      const Real scaled = m.div(m.sub(p[k], target[i + k]), m.mul(b[i + k], m.add(K(1.0), m.abs(d[k]))));
      s = m.add(s, m.square(scaled));
    }
    Real w;
    if (Cubic) {
      const Real rho = m.min(m.sqrt(s), K(1.0));
      const Real one_minus = m.sub(K(1.0), rho);
      w = m.div(m.mul(m.square(one_minus), one_minus), m.add(K(1.0), rho));
    } else {
      w = m.exp(m.neg(s));
    }
    for (int k = 0; k < 3; ++k) p[k] = m.sub(p[k], m.mul(w, d[k]));
  }
  return K(1.0);
}

// Messages for the unsupported functions; '$' stands for the function's name.
constexpr std::string_view kNotYet = "'$' is not supported yet";
constexpr std::string_view kOnlyInR =
    "'$' is not supported: it calls back into R and exists only in HyperFun's R package";
constexpr LibraryFunction no(std::string_view name, std::string_view why) { return {name, "", "", nullptr, why}; }

const LibraryFunction kFunctions[] = {
    // Built-in maths ([HFC] int_global.c, functions 0-22).
    {"sqrt", "v", "R", unary<&TapeAlgebra::sqrt>, {}}, {"exp", "v", "R", unary<&TapeAlgebra::exp>, {}},
    {"log", "v", "R", unary<&TapeAlgebra::log>, {}}, {"logd", "v", "R", fLogd, {}},
    {"sin", "v", "R", unary<&TapeAlgebra::sin>, {}}, {"cos", "v", "R", unary<&TapeAlgebra::cos>, {}},
    {"tan", "v", "R", fTan, {}}, {"asin", "v", "R", fAsin, {}}, {"acos", "v", "R", fAcos, {}},
    {"atan", "v", "R", fAtan, {}}, {"abs", "v", "R", unary<&TapeAlgebra::abs>, {}},
    {"sinh", "v", "R", fSinh, {}}, {"cosh", "v", "R", fCosh, {}}, {"tanh", "v", "R", fTanh, {}},
    {"sign", "v", "R", fSign, {}}, {"mod", "a, b", "RR", fMod, {}},
    {"max", "a, b", "RR", binary<&TapeAlgebra::max>, {}}, {"min", "a, b", "RR", binary<&TapeAlgebra::min>, {}},
    {"atan2", "y, x", "RR", fAtan2, {}}, {"ceil", "v", "R", fCeil, {}},
    {"floor", "v", "R", fFloor, {}}, {"int", "v", "R", fInt, {}}, {"frac", "v", "R", fFrac, {}},
    // Primitives.
    {"hfSphere", "x, center, R", "AAR", hfSphere, {}},
    {"hfEllipsoid", "x, center, a, b, c", "AARRR", hfEllipsoid, {}},
    {"hfCylinderX", "x, center, R", "AAR", hfCylinder<0>, {}},
    {"hfCylinderY", "x, center, R", "AAR", hfCylinder<1>, {}},
    {"hfCylinderZ", "x, center, R", "AAR", hfCylinder<2>, {}},
    {"hfEllCylX", "x, center, a, b", "AARR", hfEllCyl<0>, {}},
    {"hfEllCylY", "x, center, a, b", "AARR", hfEllCyl<1>, {}},
    {"hfEllCylZ", "x, center, a, b", "AARR", hfEllCyl<2>, {}},
    {"hfTorusX", "x, center, R, r0", "AARR", hfTorus<0>, {}},
    {"hfTorusY", "x, center, R, r0", "AARR", hfTorus<1>, {}},
    {"hfTorusZ", "x, center, R, r0", "AARR", hfTorus<2>, {}},
    {"hfBlock", "x, vertex, dx, dy, dz", "AARRR", hfBlock, {}},
    {"hfConeX", "x, center, R", "AAR", hfCone<0, false>, {}},
    {"hfConeY", "x, center, R", "AAR", hfCone<1, false>, {}},
    {"hfConeZ", "x, center, R", "AAR", hfCone<2, false>, {}},
    {"hfEllConeX", "x, center, a, b", "AARR", hfCone<0, true>, {}},
    {"hfEllConeY", "x, center, a, b", "AARR", hfCone<1, true>, {}},
    {"hfEllConeZ", "x, center, a, b", "AARR", hfCone<2, true>, {}},
    {"hfSuperEll", "x, center, a, b, c, s1, s2", "AARRRRR", hfSuperEll, {}},
    {"hfBlobby", "x, x0, y0, z0, a, b, T", "AAAAAAR", hfBlobby, {}},
    {"hfMetaball", "x, x0, y0, z0, b, d, T", "AAAAAAR", hfMetaball, {}},
    {"hfSoft", "x, x0, y0, z0, d, T", "AAAAAR", hfSoft, {}},
    {"hfConvPoint", "x, vect, S, T", "AAAR", hfConvPoint, {}},
    {"hfConvLine", "x, begin, end, S, T", "AAAAR", hfConvSegments<false>, {}},
    {"hfConvCurve", "x, vect, S, T", "AAAR", hfConvSegments<true>, {}},
    {"hfNoiseG", "x, amp, freq, phase", "ARRR", hfNoiseG, {}},
    {"hfConvTriangle", "x, vect, S, T", "AAAR", hfConvTriangle, {}},
    {"hfConvMesh", "x, vect, tri, S, T", "AAAAR", hfConvMesh, {}},
    {"hfConvArc", "x, center, radius, theta, axis, angle, S, T", "AAAAAAAR", hfConvArc, {}},
    {"hfConvLineR", "x, begin, end, R", "AAAR", hfConvLineR, {}},
    // SARDF distance primitives.
    {"hfDTorusX", "x, center, R, r0", "AARR", hfDTorus<0>, {}},
    {"hfDTorusY", "x, center, R, r0", "AARR", hfDTorus<1>, {}},
    {"hfDTorusZ", "x, center, R, r0", "AARR", hfDTorus<2>, {}},
    {"hfDCylinder", "x, center, axis, R", "AAAR", hfDCylinder, {}},
    {"hfDConeX", "x, center, R", "AAR", hfDCone<0>, {}},
    {"hfDConeY", "x, center, R", "AAR", hfDCone<1>, {}},
    {"hfDConeZ", "x, center, R", "AAR", hfDCone<2>, {}},
    {"hfDEllipsoid", "x, center, a, b, c", "AARRR", hfDEllipsoid, {}},
    // SARDF operations (hyperfun_sardf.cpp).
    {"hfDUni", "f1, f2, r, alpha", "RRRR", hfDUni, {}},
    {"hfDInt", "f1, f2, r, alpha", "RRRR", hfDInt, {}},
    {"hfDSub", "f1, f2, r, alpha", "RRRR", hfDSub, {}},
    {"hfDBlendUni", "f1, f2, r", "RRR", hfDBlendUni, {}},
    {"hfDBlendInt", "f1, f2, r", "RRR", hfDBlendInt, {}},
    // Blends.
    {"hfBlendUni", "f1, f2, a0, a1, a2", "RRRRR", hfBlend<true>, {}},
    {"hfBlendInt", "f1, f2, a0, a1, a2", "RRRRR", hfBlend<false>, {}},
    // Space mappings.
    {"hfShift3D", "xt, dx, dy, dz", "ARRR", hfShift3D, {}},
    {"hfScale3D", "xt, sx, sy, sz", "ARRR", hfScale3D, {}},
    {"hfStretch3D", "xt, x0, sx, sy, sz", "AARRR", hfStretch3D, {}},
    {"hfRotate3DX", "xt, theta", "AR", hfRotate3D<0>, {}},
    {"hfRotate3DY", "xt, theta", "AR", hfRotate3D<1>, {}},
    {"hfRotate3DZ", "xt, theta", "AR", hfRotate3D<2>, {}},
    {"hfTwistX", "xt, x1, x2, theta1, theta2", "ARRRR", hfTwist<0>, {}},
    {"hfTwistY", "xt, y1, y2, theta1, theta2", "ARRRR", hfTwist<1>, {}},
    {"hfTwistZ", "xt, z1, z2, theta1, theta2", "ARRRR", hfTwist<2>, {}},
    {"hfTaperX", "xt, x1, x2, s1, s2", "ARRRR", hfTaper<0>, {}},
    {"hfTaperY", "xt, y1, y2, s1, s2", "ARRRR", hfTaper<1>, {}},
    {"hfTaperZ", "xt, z1, z2, s1, s2", "ARRRR", hfTaper<2>, {}},
    {"hfSpaceMapExp", "xt, source, target, b", "AAAA", hfSpaceMap<false>, {}},
    {"hfSpaceMapCubic", "xt, source, target, b", "AAAA", hfSpaceMap<true>, {}},
    // The attribute library (hyperfun_attributes.cpp): writes into s, or values for it.
    {"hfA_SetColor", "f, s, r, g, b", "RARRR", hfASetColor, {}},
    {"hfA_SetAttributes", "f, s, s1", "RAA", hfASetAttributes, {}},
    {"hfA_Lerp", "s, s1, s2, f, fmin, fmax", "AAARRR", hfALerp, {}},
    {"hfA_Cerp", "s, s1, s2, f, fmin, fmax", "AAARRR", hfALerp, {}},
    {"hfA_Clamp", "f, a, b", "RRR", hfAClamp, {}},
    {"hfA_Pulse", "f, upper, lower", "RRR", hfAPulse, {}},
    {"hfA_Step", "f, a", "RR", hfAStep, {}},
    {"hfA_SmoothStep", "f, a, b", "RRR", hfASmoothStep, {}},
    {"hfA_Wave", "v, c1, c2, freq", "RRRR", hfAWave, {}},
    {"hfA_Union", "f1, f2, s, s1, s2, op", "RRAAAR", hfAUnion, {}},
    {"hfA_Floor", "v", "R", hfAFloor, {}},
    {"hfA_Modulo", "a, b", "RR", hfAModulo, {}},
    {"hfA_CheckerBoard", "x, block_size, gap_size, output, input_block, input_gap", "AAAAAA", hfACheckerBoard, {}},
    {"hfA_Circles", "x, output, input_attr, input_map", "AAAA", hfACircles, {}},
    {"hfA_Crackles", "x, output, freq, input_attr, input_map", "AARAA", hfACrackles, {}},
    {"hfA_NoiseG", "x, freq, phase", "ARR", hfANoiseG, {}},
    {"hfA_NoiseP", "x", "A", hfANoiseP, {}},
    {"hfA_Turbulence", "x, freq", "AR", hfATurbulence, {}},
    {"hfA_LookUpTable", "t, output, input_attr, input_map", "RAAA", hfALookUpTable, {}},
    {"hfA_SmoothLookUpTable", "t, output, input_attr, input_map", "RAAA", hfASmoothLookUpTable, {}},
    {"hfA_Spline", "s, knots, x, xmin, xmax", "AARRR", hfASpline, {}},
    {"hfA_RGBToHSV", "rgb, hsv", "AA", hfARGBToHSV, {}},
    {"hfA_HSVToRGB", "hsv, rgb", "AA", hfAHSVToRGB, {}},
    // Registered in HyperFun but not supported yet.
    no("hfBezierVolume", kNotYet), no("hfSawtooth", kNotYet),
    no("hfR", kOnlyInR),
};

bool equalsLowercase(std::string_view name, std::string_view lowercase) {
  if (name.size() != lowercase.size()) return false;
  for (size_t i = 0; i < name.size(); ++i) {
    const char c = name[i] >= 'A' && name[i] <= 'Z' ? static_cast<char>(name[i] - 'A' + 'a') : name[i];
    if (c != lowercase[i]) return false;
  }
  return true;
}

}  // namespace

const LibraryFunction* findLibraryFunction(std::string_view lowercase_name) {
  for (const LibraryFunction& f : kFunctions)
    if (equalsLowercase(f.name, lowercase_name)) return &f;
  return nullptr;
}

}  // namespace pf::field::hyperfun
