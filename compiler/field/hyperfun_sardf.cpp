// HyperFun's SARDF operations (Fayolle's signed approximate real distance functions, [HFC]
// sardf.c, hfSardef*.c, hfDBlend*.c, hfDEllipsoid.c) as tape builders: hfDUni, hfDInt, hfDSub,
// hfDBlendUni, hfDBlendInt and hfDEllipsoid.
//
// Unlike the R-functions, these are piecewise: which formula applies depends on the signs and
// the ratio of the two operands, so on the point. Each piece is built on the tape and the
// tape's Select keeps, per point, the one HyperFun's branches would take (every piece is
// computed; only the chosen one's value passes). The pieces, with x = f1, y = f2:
//
// Union (hfDUni(f1, f2, R, alpha)), by quadrant of (x, y):
//   * x and y both within 1e-7 of 0: 0; one of them within 1e-7: the other if positive, else 0;
//   * x < 0 < y: y;  y < 0 < x: x  (the operand inside is the distance);
//   * x, y > 0, "angle approach": with t = tan(alpha) and g = x / y, between the lines g = t and
//     g = 1/t the smaller root of (t^2 + 2t - 1) d^2 - 2t(x + y) d + x^2 + y^2 = 0 (the formula
//     (-b - sqrt(b^2 - 4ac)) / 2a as written); g >= 1/t: x; g <= t: y;
//   * x, y < 0 within the "bounded" region (x >= -R, or y >= -R, or both >= -2R with
//     (x + 2R)^2 + (y + 2R)^2 >= R^2): between the parabolas x = -y^2/4R and y = -x^2/4R,
//     -m^2 where m is a root of the quartic m^4 - 4s m^3 - 4R m^2 - 4s(x + y) m - (x^2 + y^2)
//     (s = sqrt R); beyond the parabolas x or y (the nearer), else 0;
//   * x, y < 0 outside it, in the stripe |y - x| <= R: the circular blend
//     (x + y + 2R - sqrt(2R^2 - (x - y)^2)) / 2 (HyperFun's quadratic solved); outside the
//     stripe the larger of x and y.
// Which root m: HyperFun takes the second value its quartic solver lists; over the region where
// this branch applies the quartic has four real roots, one negative and three positive, and
// that value is always the middle positive one, the largest root below s (checked on 90,000
// random points over R from 0.05 to 4). The quartic is concave on [0, s] (its second derivative
// 4(3m^2 - 6sm - 2s^2) is negative there) and negative at s, so Newton's method started at
// m = s decreases monotonically to exactly that root; 16 steps reach it to 1e-7 of s at every
// point checked (14 at most). The Newton steps keep m differentiable in x and y, so the
// gradient form sees the implicit derivative.
//
// Intersection: hfDInt(x, y, R, alpha) = -hfDUni(-x, -y, R, alpha) -- sardf.c writes it out
// with every sign mirrored (bounded in quadrant 1, angle approach in quadrant 3), piece for piece
// the union's on the negated operands. Subtraction: hfDSub(f1, f2, ...) = hfDInt(f1, -f2, ...).
// hfDBlendUni / hfDBlendInt(f1, f2, r): the stripe blend alone (0 where the quadratic has no
// root, which inside the stripe never happens), the larger (smaller) operand outside it.
#include <cmath>

#include "compiler/field/hyperfun_library_internal.h"

namespace pf::field::hyperfun {
namespace {

Real K(double v) { return Real::known(v); }

// Logic on 1/0 conditions.
Real both(TapeAlgebra& m, Real a, Real b) { return m.min(a, b); }
Real either(TapeAlgebra& m, Real a, Real b) { return m.max(a, b); }

constexpr int kQuarticNewtonSteps = 16;

// The stripe blend of two outside values: (x + y + 2r - sqrt(2r^2 - (x - y)^2)) / 2 for
// |y - x| <= r, else the larger.
Real stripeUnion(TapeAlgebra& m, Real x, Real y, Real r) {
  const Real inside = both(m, m.lessEq(y, m.add(x, r)), m.lessEq(m.sub(x, r), y));
  const Real circle = m.mul(K(0.5), m.sub(m.add(m.add(x, y), m.mul(K(2.0), r)),
                                          m.sqrt(m.sub(m.mul(K(2.0), m.square(r)), m.square(m.sub(x, y))))));
  // Outside the stripe: x where y < x - r, y where y > x + r.
  return m.select(inside, circle, m.select(m.less(y, m.sub(x, r)), x, y));
}

// The union's piece for x, y < 0 in the bounded region between the parabolas: -m^2, m the
// quartic's largest root below sqrt(R), by Newton from sqrt(R) (see the header).
Real boundedQuarticPiece(TapeAlgebra& m, Real x, Real y, Real R) {
  const Real s = m.sqrt(R);
  const Real sum = m.add(x, y), sq = m.add(m.square(x), m.square(y));
  const Real c3 = m.mul(K(-4.0), s), c2 = m.mul(K(-4.0), R), c1 = m.mul(m.mul(K(-4.0), s), sum);
  Real root = s;
  for (int k = 0; k < kQuarticNewtonSteps; ++k) {
    // q = (((m + c3) m + c2) m + c1) m - sq;  q' = ((4m + 3c3) m + 2c2) m + c1
    const Real q = m.sub(m.mul(m.add(m.mul(m.add(m.mul(m.add(root, c3), root), c2), root), c1), root), sq);
    const Real dq = m.add(m.mul(m.add(m.mul(m.add(m.mul(K(4.0), root), m.mul(K(3.0), c3)), root), m.mul(K(2.0), c2)), root), c1);
    root = m.sub(root, m.div(q, dq));
  }
  return m.neg(m.square(root));
}

// hfDUni's value (the header's pieces), alpha and R as given (known or not).
Real sardfUnion(TapeAlgebra& m, Real x, Real y, Real R, Real alpha) {
  const Real zero = K(0.0), tiny = K(1e-7);
  const Real small_x = m.less(m.abs(x), tiny), small_y = m.less(m.abs(y), tiny);
  const Real x_pos = m.less(zero, x), y_pos = m.less(zero, y);

  // Quadrant 1: the angle approach.
  const Real t = m.div(m.sin(alpha), m.cos(alpha));
  const Real g = m.div(x, y);
  const Real a = m.sub(m.add(m.square(t), m.mul(K(2.0), t)), K(1.0));
  const Real b = m.mul(m.mul(K(-2.0), t), m.add(x, y));
  const Real c = m.add(m.square(x), m.square(y));
  const Real root = m.div(m.sub(m.neg(b), m.sqrt(m.sub(m.square(b), m.mul(m.mul(K(4.0), a), c)))), m.mul(K(2.0), a));
  const Real between = both(m, m.less(g, m.div(K(1.0), t)), m.less(t, g));
  const Real q1 = m.select(between, root, m.select(m.lessEq(m.div(K(1.0), t), g), x, y));

  // Quadrant 3: bounded between the parabolas, else the stripe.
  const Real two_r = m.mul(K(2.0), R);
  const Real lim2 = m.add(m.square(m.add(x, two_r)), m.square(m.add(y, two_r)));
  const Real bounded = either(m, either(m, m.lessEq(m.neg(R), x), m.lessEq(m.neg(R), y)),
                              both(m, both(m, m.lessEq(m.neg(two_r), x), m.lessEq(m.neg(two_r), y)),
                                   m.lessEq(m.square(R), lim2)));
  const Real four_r = m.mul(K(4.0), R);
  const Real xx = m.neg(m.div(m.square(x), four_r)), yy = m.neg(m.div(m.square(y), four_r));
  const Real in_angle = both(m, m.lessEq(x, yy), m.lessEq(y, xx));
  const Real beyond = m.select(m.less(xx, y), y, m.select(m.less(yy, x), x, zero));
  const Real q3_bounded = m.select(in_angle, boundedQuarticPiece(m, x, y, R), beyond);
  const Real q3 = m.select(bounded, q3_bounded, stripeUnion(m, x, y, R));

  const Real off_axes = m.select(x_pos, m.select(y_pos, q1, x), m.select(y_pos, y, q3));
  const Real on_x_axis = m.select(y_pos, y, zero);  // x within 1e-7 of 0
  const Real on_y_axis = m.select(x_pos, x, zero);
  return m.select(small_x, m.select(small_y, zero, on_x_axis), m.select(small_y, on_y_axis, off_axes));
}

Real sardfIntersection(TapeAlgebra& m, Real x, Real y, Real R, Real alpha) {
  return m.neg(sardfUnion(m, m.neg(x), m.neg(y), R, alpha));
}

// hfDEllipsoid's iteration: Newton on the closest-point equation's parameter t; HyperFun stops
// when the polynomial is within 1e-6 of 0 (at most 128 steps). The tape runs a fixed number of
// steps, each kept only where the previous had not yet stopped -- 32: over points within 6 of
// ellipsoids with half-axes 0.3 to 3, HyperFun's loop stops within 16 (in double).
constexpr int kEllipsoidNewtonSteps = 32;

}  // namespace

Real hfDUni(LibraryCall& c) { return sardfUnion(c.alg, c.reals[0], c.reals[1], c.reals[2], c.reals[3]); }
Real hfDInt(LibraryCall& c) { return sardfIntersection(c.alg, c.reals[0], c.reals[1], c.reals[2], c.reals[3]); }
Real hfDSub(LibraryCall& c) {
  return sardfIntersection(c.alg, c.reals[0], c.alg.neg(c.reals[1]), c.reals[2], c.reals[3]);
}
Real hfDBlendUni(LibraryCall& c) { return stripeUnion(c.alg, c.reals[0], c.reals[1], c.reals[2]); }
Real hfDBlendInt(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  return m.neg(stripeUnion(m, m.neg(c.reals[0]), m.neg(c.reals[1]), c.reals[2]));
}

// The signed distance to the ellipsoid with half-axes a, b, c about center: the closest surface
// point is (a^2 x_k + t center_k) / (t + a^2) (likewise b, c) for the root t of
// (t + a^2)^2 (t + b^2)^2 (t + c^2)^2 - a^2 u^2 (t + b^2)^2 (t + c^2)^2 - ... = 0 (u, v, w: the
// offsets from the centre), found by Newton from t = 0 inside and t = max(a, b, c) |offset|
// outside; positive inside.
Real hfDEllipsoid(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  std::vector<Real>& x = items(c, 0, 3);
  std::vector<Real>& ctr = items(c, 1, 3);
  const Real axes[3] = {c.reals[2], c.reals[3], c.reals[4]};
  for (int k = 0; k < 3; ++k)
    if (axes[k].is_known && std::fabs(axes[k].value) < kEps)
      reject(2 + k, paramLabel(c, 2 + k) + " is within 1e-6 of 0 (HyperFun returns its error value -1111111111111)");
  Real d[3], a2[3], a2d2[3], ratio2 = K(0.0), len2 = K(0.0);
  for (int k = 0; k < 3; ++k) {
    d[k] = m.sub(x[k], ctr[k]);
    a2[k] = m.square(axes[k]);
    a2d2[k] = m.mul(a2[k], m.square(d[k]));
    ratio2 = m.add(ratio2, m.square(m.div(d[k], axes[k])));
    len2 = m.add(len2, m.square(d[k]));
  }
  const Real inside = m.less(ratio2, K(1.0));
  const Real largest = m.max(m.max(axes[0], axes[1]), axes[2]);
  Real t = m.select(inside, K(0.0), m.mul(largest, m.sqrt(len2)));
  for (int step = 0; step < kEllipsoidNewtonSteps; ++step) {
    const Real p = m.add(t, a2[0]), q = m.add(t, a2[1]), r = m.add(t, a2[2]);
    const Real p2 = m.square(p), q2 = m.square(q), r2 = m.square(r);
    const Real s = m.sub(m.sub(m.sub(m.mul(m.mul(p2, q2), r2), m.mul(a2d2[0], m.mul(q2, r2))), m.mul(a2d2[1], m.mul(p2, r2))),
                         m.mul(a2d2[2], m.mul(p2, q2)));
    const Real pq = m.mul(p, q), pr = m.mul(p, r), qr = m.mul(q, r), pqr = m.mul(pq, r);
    const Real ds = m.mul(K(2.0), m.sub(m.sub(m.sub(m.mul(pqr, m.add(m.add(qr, pr), pq)), m.mul(a2d2[0], m.mul(qr, m.add(q, r)))),
                                             m.mul(a2d2[1], m.mul(pr, m.add(p, r)))),
                                       m.mul(a2d2[2], m.mul(pq, m.add(p, q)))));
    t = m.select(m.less(m.abs(s), K(1e-6)), t, m.sub(t, m.div(s, ds)));
  }
  Real dist2 = K(0.0);
  for (int k = 0; k < 3; ++k) {
    const Real closest = m.div(m.add(m.mul(a2[k], x[k]), m.mul(t, ctr[k])), m.add(t, a2[k]));
    dist2 = m.add(dist2, m.square(m.sub(closest, x[k])));
  }
  const Real distance = m.sqrt(dist2);
  return m.select(inside, distance, m.neg(distance));
}

}  // namespace pf::field::hyperfun
