// HyperFun's convolution surfaces over triangles (hfConvTriangle, hfConvMesh), circular arcs
// (hfConvArc) and radius-sized segments (hfConvLineR) as tape builders: the Cauchy kernel
// 1/(1 + S^2 r^2)^2 integrated over each primitive in closed form, with no branch on the point.
//
// The closed forms are derived here (outlines in the comments), after McCormack and Sherstyuk,
// "Creating and rendering convolution surfaces" (Computer Graphics Forum 17(2), 1998), which
// integrates the Cauchy kernel over segments, arcs and triangles. They are written to stay finite
// wherever the point is -- in a triangle's plane, on its edges and at its vertices, on an arc's
// axis, on the arc -- and they give the values HyperFun's library computes, up to the
// normalisation HyperFun uses (found by comparing HyperFun's numbers with quadrature, and stated
// at each function). tests/field/hyperfun_convolution_test.cpp checks each against quadrature in
// double.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compiler/field/hyperfun_library_internal.h"

namespace pf::field::hyperfun {
namespace {

using Items = std::vector<Real>;
Real K(double v) { return Real::known(v); }

// Three Reals: a point or a direction, each coordinate known or on the tape.
struct Vec {
  Real v[3];
};

Vec vecAt(const Items& a, size_t at) { return {{a[at], a[at + 1], a[at + 2]}}; }
bool known(const Vec& a) { return a.v[0].is_known && a.v[1].is_known && a.v[2].is_known; }

Vec minus(TapeAlgebra& m, const Vec& a, const Vec& b) {
  return {{m.sub(a.v[0], b.v[0]), m.sub(a.v[1], b.v[1]), m.sub(a.v[2], b.v[2])}};
}
Vec plus(TapeAlgebra& m, const Vec& a, const Vec& b) {
  return {{m.add(a.v[0], b.v[0]), m.add(a.v[1], b.v[1]), m.add(a.v[2], b.v[2])}};
}
Vec scaled(TapeAlgebra& m, const Vec& a, Real s) { return {{m.mul(a.v[0], s), m.mul(a.v[1], s), m.mul(a.v[2], s)}}; }
Vec cross(TapeAlgebra& m, const Vec& a, const Vec& b) {
  Vec r;
  for (int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    r.v[k] = m.sub(m.mul(a.v[k1], b.v[k2]), m.mul(a.v[k2], b.v[k1]));
  }
  return r;
}
Real squaredLength(TapeAlgebra& m, const Vec& a) {
  return m.add(m.add(m.square(a.v[0]), m.square(a.v[1])), m.square(a.v[2]));
}
// (x - p) . v as x . v - p . v: the known part folds, and a known 0 in v drops its terms.
Real offsetDot(TapeAlgebra& m, const Vec& x, const Vec& p, const Vec& v) {
  Real xv = K(0.0), pv = K(0.0);
  for (int k = 0; k < 3; ++k) {
    if (v.v[k].is_known && v.v[k].value == 0.0) continue;
    xv = m.add(xv, m.mul(x.v[k], v.v[k]));
    pv = m.add(pv, m.mul(p.v[k], v.v[k]));
  }
  return m.sub(xv, pv);
}
// a / |a|; a vector of length 0 (possible only on the tape) becomes 0, not NaN.
Vec unit(TapeAlgebra& m, const Vec& a, Real& length) {
  length = m.max(m.sqrt(squaredLength(m, a)), K(1e-30));
  return scaled(m, a, m.div(K(1.0), length));
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

// --- Triangles ---------------------------------------------------------------------------------
//
// I = integral over the triangle of dA / (1 + S^2 r^2)^2. Let w be the point's distance to the
// triangle's plane and x0 its projection, so that 1 + S^2 r^2 = q + S^2 rho^2 with q = 1 + S^2 w^2
// and rho the distance in the plane from x0. Split the triangle into the three signed triangles
// (x0, P, Q) over its edges P -> Q (their signed areas add up to the triangle's wherever x0 is).
// Over one of them, in polar coordinates about x0:
//   integral d(theta) integral_0^R(theta) rho d(rho) / (q + S^2 rho^2)^2
//     = integral d(theta) (1/q - 1/(q + S^2 R^2)) / (2 S^2).
// Along the edge's line, at signed distance p from x0 (positive when x0 is on the triangle's side)
// and with t the position along the edge from the foot of that perpendicular, R^2 = p^2 + t^2 and
// d(theta) = p dt / (p^2 + t^2). By partial fractions,
//   p / ((p^2 + t^2)(q + S^2 p^2 + S^2 t^2)) = (p/q) (1/(p^2 + t^2) - S^2 / (m^2 + S^2 t^2)),
// m^2 = q + S^2 p^2 = 1 + S^2 (squared distance from the point to the edge's line); the first
// part cancels the 1/q term and the edge contributes
//   p / (2 S q m) [atan(a1) - atan(a0)],   a_i = S t_i / m,  t0, t1 the edge's ends.
// The difference of arctangents is the argument of (1 + i a1)(1 - i a0), whose half-angle form
// 2 atan((a1 - a0) / (sqrt((1 + a0^2)(1 + a1^2)) + 1 + a0 a1)) holds for every a0 < a1. With the
// kernel's denominators at the edge's ends, K_i = 1 + S^2 |x - V_i|^2 = m^2 (1 + a_i^2), and its
// length L = t1 - t0 that is
//   2 atan(S L m / (sqrt(K0 K1) + (K0 + K1 - S^2 L^2) / 2)),
// one arctangent per edge of a positive denominator (m^2 times the one above), at least 1 where
// the point is far from the edge (no cancellation there), the numerator S L m exact.
// q >= 1 and m >= 1, so each term is finite everywhere; on an edge's line p = 0 and it adds 0.
//
// HyperFun's hfConvTriangle computes S^3 I (its closed form, compared with quadrature over the
// triangle at random points and S, is S^3 times the integral to 15 digits), so the value is
//   (S^2 / q) sum over edges of (p / m) atan(S L m / (sqrt(K0 K1) + (K0 + K1 - S^2 L^2) / 2)).
// A triangle whose area is below 1e-12 of its longest edge squared adds 0 (the integral is at most
// S^3 times the area; HyperFun divides 0 by 0 there). Far from the triangle, in its plane, the
// three edges' terms cancel to a value smaller by (distance / size)^2 or so, and float rounding
// shows: the relative error grows from 1e-7 near the triangle to about 1e-4 at 30 triangle sizes
// away, where the value itself is ~1e-6 (an absolute error below 1e-9).
Real cauchyTriangle(TapeAlgebra& m, const Vec& x, const Vec corner[3], Real s) {
  const Vec twice_area = cross(m, minus(m, corner[1], corner[0]), minus(m, corner[2], corner[0]));
  if (known(corner[0]) && known(corner[1]) && known(corner[2])) {
    double longest = 0.0;
    for (int i = 0; i < 3; ++i) longest = std::max(longest, squaredLength(m, minus(m, corner[(i + 1) % 3], corner[i])).value);
    if (!(std::sqrt(squaredLength(m, twice_area).value) > 1e-12 * longest)) return K(0.0);
  }
  Real unused;
  const Vec normal = unit(m, twice_area, unused);
  const Real s2 = m.square(s);
  const Real w2 = m.square(offsetDot(m, x, corner[0], normal));
  Real kernel[3];
  for (int i = 0; i < 3; ++i) kernel[i] = m.add(K(1.0), m.mul(s2, squaredLength(m, minus(m, x, corner[i]))));
  Real sum = K(0.0);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    Real length;
    const Vec along = unit(m, minus(m, corner[j], corner[i]), length);
    const Real p = offsetDot(m, x, corner[i], cross(m, normal, along));
    const Real edge_m = m.sqrt(m.add(K(1.0), m.mul(s2, m.add(w2, m.square(p)))));
    const Real half = m.mul(m.sub(m.add(kernel[i], kernel[j]), m.mul(s2, m.square(length))), K(0.5));
    const Real den = m.add(m.sqrt(m.mul(kernel[i], kernel[j])), half);
    const Real angle = m.atan(m.div(m.mul(m.mul(s, length), edge_m), den));
    sum = m.add(sum, m.mul(m.div(p, edge_m), angle));
  }
  return m.div(m.mul(s2, sum), m.add(K(1.0), m.mul(s2, w2)));
}

// --- Arcs --------------------------------------------------------------------------------------
//
// HyperFun's hfConvArc integrates over the arc's ANGLE, not its length: its value is
//   integral_0^Theta d(phi) / (1 + S^2 |x - c - r u(phi)|^2)^2,
// the arc-length integral divided by r (compared with quadrature at random points, to 15 digits).
// In the frame of one piece of the arc, centred on the piece's middle direction m with tangent t
// and half-width h (phi = phi_mid + omega, |omega| <= h), write X = (x - c).m, Y = (x - c).t,
// b = 1 + S^2 (r^2 + |x - c|^2) and a = 2 r S^2: the denominator is D(omega)^2 with
//   D(omega) = b - a (X cos omega + Y sin omega) = 1 + S^2 |x - c - r u(omega)|^2 >= 1.
// With rho^2 = X^2 + Y^2 and k^2 = b^2 - a^2 rho^2 = (b - a rho)(b + a rho) > 0, where
// b -+ a rho = 1 + S^2 ((r -+ rho)^2 + Z^2) (Z the offset along the arc's normal; both >= 1):
//   d/d(omega) [sin(omega - psi) / D] = (k^2 - b D) / (a rho D^2)  (X = rho cos psi, Y = rho sin psi)
// so 1/D^2 = (a / k^2) d/d(omega) [(X sin omega - Y cos omega) / D] + (b / k^2) / D. The tangent
// half-angle substitution tau = tan(omega/2) turns 1/D into 2 / ((b + a X) tau^2 - 2 a Y tau +
// (b - a X)), a quadratic with discriminant -4 k^2 < 0, whose integral is an arctangent:
//   integral 1/D d(omega) = (2/k) atan(((b + a X) tau - a Y) / k).
// Over the piece, with T = tan(h/2) and B = b + a X = 1 + S^2 |x - c + r m|^2:
//   a [(X sin h - Y cos h) / D(h) + (X sin h + Y cos h) / D(-h)] / k^2
//   + (2b / k^3) [atan((B T - a Y) / k) + atan((B T + a Y) / k)].
// Every denominator is at least 1. r = 0 gives Theta / (1 + S^2 |x - c|^2)^2 (HyperFun's value
// too); Theta = 0 gives 0. A piece spans at most 180 degrees, so |T| <= 1.
Real cauchyArcPiece(TapeAlgebra& m, const Vec& x, const Vec& centre, Real r, Real s2, const Vec& mid,
                    const Vec& tangent, const Vec& normal, double h) {
  const Real px = offsetDot(m, x, centre, mid), py = offsetDot(m, x, centre, tangent);
  const Real pz2 = m.square(offsetDot(m, x, centre, normal));
  const Real rho = m.sqrt(m.add(m.square(px), m.square(py)));
  const Real near = m.add(K(1.0), m.mul(s2, m.add(m.square(m.sub(r, rho)), pz2)));  // b - a rho
  const Real far = m.add(K(1.0), m.mul(s2, m.add(m.square(m.add(r, rho)), pz2)));   // b + a rho
  const Real k2 = m.mul(near, far), k = m.sqrt(k2);
  const Real b = m.mul(m.add(near, far), K(0.5));
  const Real a = m.mul(m.mul(K(2.0), r), s2);
  // D at the piece's ends and B, each 1 + S^2 (a squared distance), from differences.
  auto kernelAt = [&](const Vec& offset) {
    return m.add(K(1.0), m.mul(s2, squaredLength(m, minus(m, x, plus(m, centre, scaled(m, offset, r))))));
  };
  const Real ch = K(std::cos(h)), sh = K(std::sin(h));
  const Real d_plus = kernelAt(plus(m, scaled(m, mid, ch), scaled(m, tangent, sh)));
  const Real d_minus = kernelAt(minus(m, scaled(m, mid, ch), scaled(m, tangent, sh)));
  const Real big_b = kernelAt(scaled(m, mid, K(-1.0)));
  const Real xs = m.mul(px, sh), yc = m.mul(py, ch);
  const Real rational = m.div(m.mul(a, m.add(m.div(m.sub(xs, yc), d_plus), m.div(m.add(xs, yc), d_minus))), k2);
  const Real bt = m.mul(big_b, K(std::tan(h / 2.0))), ay = m.mul(a, py);
  const Real angles = m.add(m.atan(m.div(m.sub(bt, ay), k)), m.atan(m.div(m.add(bt, ay), k)));
  return m.add(rational, m.div(m.mul(m.mul(K(2.0), b), angles), m.mul(k2, k)));
}

// HyperFun's degrees: its PI is 3.141592, so a degree is 3.141592/180 radians (a relative
// difference of 2e-7 in every angle, kept so that the values are HyperFun's).
constexpr double kHyperFunRadian = 3.141592 / 180.0;

}  // namespace

// Sum over triangles (9 items of vect per item of S) of S^3 times the Cauchy kernel's integral
// over the triangle, minus T.
Real hfConvTriangle(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Vec x = vecAt(items(c, 0, 3), 0);
  Items& S = *c.arrays[2];
  Items& vect = items(c, 1, 9 * S.size());
  Real sum = K(0.0);
  for (size_t i = 0; i < S.size(); ++i) {
    const Vec corner[3] = {vecAt(vect, 9 * i), vecAt(vect, 9 * i + 3), vecAt(vect, 9 * i + 6)};
    sum = m.add(sum, cauchyTriangle(m, x, corner, S[i]));
  }
  return m.sub(sum, c.reals[3]);
}

// hfConvTriangle over triangles whose corners are vertices of vect (3 items each), numbered from 1
// by tri (3 items per item of S). The numbers must be known when the model is compiled.
Real hfConvMesh(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Vec x = vecAt(items(c, 0, 3), 0);
  Items& S = *c.arrays[3];
  items(c, 2, 3 * S.size());  // tri
  Items& vect = *c.arrays[1];
  if (vect.size() % 3 != 0)
    reject(1, paramLabel(c, 1) + " must hold 3 items per vertex; '" + c.array_names[1] + "' has " +
                  std::to_string(vect.size()));
  const size_t vertices = vect.size() / 3;
  Real sum = K(0.0);
  for (size_t i = 0; i < S.size(); ++i) {
    Vec corner[3];
    for (size_t j = 0; j < 3; ++j) {
      const double index = knownItem(c, 2, 3 * i + j, "it numbers a vertex of 'vect'");
      if (!(index == std::floor(index) && index >= 1.0 && index <= static_cast<double>(vertices)))
        reject(2, "item " + std::to_string(3 * i + j + 1) + " of " + paramLabel(c, 2) + " is " + number(index) +
                      ", which is not a vertex number: they are whole numbers from 1 to " + std::to_string(vertices) +
                      " (the vertices of '" + c.array_names[1] + "')");
      corner[j] = vecAt(vect, 3 * (static_cast<size_t>(index) - 1));
    }
    sum = m.add(sum, cauchyTriangle(m, x, corner, S[i]));
  }
  return m.sub(sum, c.reals[4]);
}

// Sum over arcs of the Cauchy kernel integrated over the arc's angle (cauchyArcPiece), minus T.
// Arc n has centre center[3n..], radius radius[n] and spans theta[n] degrees from the +x axis of
// the frame turned by angle[n] degrees about axis[3n..]; it lies in that frame's xy plane.
// HyperFun's quirks, all reproduced, in its order for each arc (so that aliased arrays behave as
// in HyperFun): angle[n] += 1e-6, written back into the caller's array; 1e-6 added to each axis
// component (not written back), the axis then normalised (its length at least 1e-6); theta[n]
// clamped to 360, and an arc over 180 degrees split into 180 degrees and the rest, theta[n] set
// to 180 -- both written back, so a later call sees at most 180. theta must be known (the clamp
// and the split are branches) and not negative.
Real hfConvArc(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Vec x = vecAt(items(c, 0, 3), 0);
  Items& S = *c.arrays[6];
  const size_t n = S.size();
  Items& centre = items(c, 1, 3 * n);
  Items& radius = items(c, 2, n);
  Items& theta = items(c, 3, n);
  Items& axis = items(c, 4, 3 * n);
  Items& angle = items(c, 5, n);
  Real sum = K(0.0);
  for (size_t i = 0; i < n; ++i) {
    const Vec ctr = vecAt(centre, 3 * i);
    const Real r = radius[i];
    angle[i] = m.add(angle[i], K(kEps));
    const Real turn = m.mul(angle[i], K(kHyperFunRadian));
    Vec u{{m.add(axis[3 * i], K(kEps)), m.add(axis[3 * i + 1], K(kEps)), m.add(axis[3 * i + 2], K(kEps))}};
    const Real length = m.max(m.sqrt(squaredLength(m, u)), K(kEps));
    u = scaled(m, u, m.div(K(1.0), length));
    double degrees = knownItem(c, 3, i, "HyperFun clamps it to 360 and splits an arc over 180 degrees in two");
    if (degrees < 0.0)
      reject(3, "item " + std::to_string(i + 1) + " of " + paramLabel(c, 3) + " is negative (" + number(degrees) +
                    "): HyperFun's integral then runs backwards");
    if (degrees > 360.0) theta[i] = K(degrees = 360.0);
    if (degrees > 180.0) theta[i] = K(180.0);
    // The frame turned by `turn` about u (Rodrigues): e_j cos + (u x e_j) sin + u u_j (1 - cos).
    const Real ct = m.cos(turn), st = m.sin(turn), one_c = m.sub(K(1.0), ct);
    Vec frame[3];
    for (int j = 0; j < 3; ++j) {
      Vec e{{K(0.0), K(0.0), K(0.0)}};
      e.v[j] = K(1.0);
      frame[j] = plus(m, plus(m, scaled(m, e, ct), scaled(m, cross(m, u, e), st)), scaled(m, u, m.mul(u.v[j], one_c)));
    }
    const Real s2 = m.square(S[i]);
    const double end = degrees * kHyperFunRadian, split = 180.0 * kHyperFunRadian;
    const double bounds[3] = {0.0, std::min(end, split), end};
    for (int piece = 0; piece < 2; ++piece) {
      const double h = (bounds[piece + 1] - bounds[piece]) / 2.0, middle = bounds[piece] + h;
      if (!(h > 0.0)) continue;
      const Real cm = K(std::cos(middle)), sm = K(std::sin(middle));
      const Vec mid = plus(m, scaled(m, frame[0], cm), scaled(m, frame[1], sm));
      const Vec tangent = minus(m, scaled(m, frame[1], cm), scaled(m, frame[0], sm));
      sum = m.add(sum, cauchyArcPiece(m, x, ctr, r, s2, mid, tangent, frame[2], h));
    }
  }
  return m.sub(sum, c.reals[7]);
}

// hfConvLine's segment integral (TapeAlgebra::cauchySegment) from begin to end, 3 items per
// segment, with S = 1 for R >= 1 and 1/R below; the segments' sum clamped to 1 (HyperFun clamps
// its running sum; the terms are positive, so that is min(sum, 1)); minus T, one segment's
// integral at a point at distance R from its begin point, perpendicular to it -- cauchySegment's
// closed form with h = 0: l / (2 p^2 (1 + S^2 (R^2 + l^2))) + atan(S l / p) / (2 S p^3), p^2 =
// 1 + S^2 R^2. HyperFun recomputes T for every segment and keeps the last: l is the last
// segment's length. R must be known (the choice of S is a branch on it).
Real hfConvLineR(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& x = items(c, 0, 3);
  const double radius = knownArg(c, 3, "HyperFun chooses the kernel's width S by comparing R with 1");
  if (radius == 0.0) reject(3, paramLabel(c, 3) + " is 0: HyperFun's kernel width S = 1/R would be infinite");
  Items& to = *c.arrays[2];
  if (to.size() % 3 != 0)
    reject(2, paramLabel(c, 2) + " must hold 3 items per segment; '" + c.array_names[2] + "' has " +
                  std::to_string(to.size()));
  Items& from = items(c, 1, to.size());
  const Real s = K(radius >= 1.0 ? 1.0 : 1.0 / radius);
  const Real xs[3] = {x[0], x[1], x[2]};
  Real sum = K(0.0), length2 = K(0.0);
  for (size_t i = 0; i < to.size(); i += 3) {
    const Real b[3] = {from[i], from[i + 1], from[i + 2]};
    const Real e[3] = {to[i], to[i + 1], to[i + 2]};
    sum = m.add(sum, m.cauchySegment(xs, b, e, s));
    length2 = K(0.0);
    for (int k = 0; k < 3; ++k) length2 = m.add(length2, m.square(m.sub(e[k], b[k])));
  }
  const Real l = m.sqrt(length2);
  const Real p2 = K(1.0 + s.value * s.value * radius * radius), p = m.sqrt(p2);
  const Real q2 = m.add(p2, m.mul(m.square(s), m.square(l)));
  const Real threshold = m.add(m.div(l, m.mul(m.mul(K(2.0), p2), q2)),
                               m.div(m.atan(m.div(m.mul(s, l), p)), m.mul(m.mul(K(2.0), s), m.mul(p, p2))));
  return m.sub(m.min(sum, K(1.0)), threshold);
}

}  // namespace pf::field::hyperfun
