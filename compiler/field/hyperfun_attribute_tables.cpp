// HyperFun's attribute tables and colour spaces as tape builders: hfA_LookUpTable,
// hfA_SmoothLookUpTable, hfA_Spline, hfA_RGBToHSV and hfA_HSVToRGB -- HyperFun's C code restated
// ([HFC] src/hflibrary_lib/hfA_*.c), argument orders read off its reversed f_a as in
// hyperfun_attributes.cpp. A table's choice of entry on a point-dependent value is a chain of
// Selects, the first match applied last; the spline's span is the tape's floor; HSV's hue wraps by
// floor. docs/hyperfun.md lists the quirks followed (a value below a table takes its last set;
// the spline's span at exactly xmax).
#include <cmath>

#include "compiler/field/hyperfun_library_internal.h"

namespace pf::field::hyperfun {

namespace {

using Items = std::vector<Real>;
Real K(double v) { return Real::known(v); }

// 1 where a == b exactly (C's ==), else 0.
Real equal(TapeAlgebra& m, Real a, Real b) { return m.mul(m.lessEq(a, b), m.lessEq(b, a)); }

// The shared look-up: `output` takes set i of `colormap` (dim items each, dim = |output|) at the
// first i < n - 1 with entry[i] <= t < entry[i + 1] -- blended towards set i + 1 by
// (t - entry[i]) / (entry[i + 1] - entry[i]) when `smooth` -- and the last set (n - 1) where no i
// matches, below the table included (HyperFun's `filled` flag is never set there).
Real lookUp(LibraryCall& c, bool smooth) {
  TapeAlgebra& m = c.alg;
  const Real t = c.reals[0];
  Items& out = *c.arrays[1];
  const Items& entry = atLeast(c, 3, 1);
  const size_t n = entry.size(), dim = out.size();
  const Items& colormap = atLeast(c, 2, dim * n);
  for (size_t j = 0; j < dim; ++j) {
    Real v = colormap[dim * (n - 1) + j];
    for (size_t k = 0; k + 1 < n; ++k) {
      const size_t i = n - 2 - k;  // the first match is applied last
      const Real hit = m.mul(m.lessEq(entry[i], t), m.less(t, entry[i + 1]));
      Real set = colormap[dim * i + j];
      if (smooth) {
        const Real l = m.div(m.sub(t, entry[i]), m.sub(entry[i + 1], entry[i]));
        set = m.add(m.mul(m.sub(K(1.0), l), set), m.mul(l, colormap[dim * (i + 1) + j]));
      }
      v = m.select(hit, set, v);
    }
    out[j] = v;
  }
  return K(1.0);
}

// The Catmull-Rom basis HyperFun's hfA_Spline uses (its CR matrix, rows c3, c2, c1, c0).
constexpr double kCatmullRom[4][4] = {
    {-0.5, 1.5, -1.5, 0.5}, {1.0, -2.5, 2.0, -0.5}, {-0.5, 0.0, 0.5, 0.0}, {0.0, 1.0, 0.0, 0.0}};

// Item i of span `span`'s cubic at local parameter u: ((c3 u + c2) u + c1) u + c0.
Real catmullRom(TapeAlgebra& m, const Items& knot, size_t n, size_t span, size_t i, Real u) {
  Real c[4];
  for (int row = 0; row < 4; ++row) {
    Real sum = K(0.0);
    for (size_t k = 0; k < 4; ++k) sum = m.add(sum, m.mul(K(kCatmullRom[row][k]), knot[(span + k) * n + i]));
    c[row] = sum;
  }
  return m.add(m.mul(m.add(m.mul(m.add(m.mul(c[0], u), c[1]), u), c[2]), u), c[3]);
}

}  // namespace

// hfA_LookUpTable(t, output, input_attr, input_map) and hfA_SmoothLookUpTable (the same
// arguments), as lookUp above describes.
Real hfALookUpTable(LibraryCall& c) { return lookUp(c, false); }
Real hfASmoothLookUpTable(LibraryCall& c) { return lookUp(c, true); }

// hfA_Spline(s, knots, x, xmin, xmax): |knots| / |s| = size colours of |s| items each; with
// u = (x - xmin)/(xmax - xmin): the first colour where u < 0, the last where u > 1, and between a
// Catmull-Rom spline through them: span = (int)(u (size - 3)), evaluated at u (size - 3) - span.
// At u = 1 exactly HyperFun takes span size - 6 (evaluated at 3); with fewer than 6 colours that
// span does not exist (HyperFun reads before the array) and primflow takes the last span at 1.
Real hfASpline(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  Items& s = *c.arrays[0];
  const size_t n = s.size();
  if (n == 0) reject(0, paramLabel(c, 0) + " must have at least 1 item");
  const Items& knot = atLeast(c, 1, 4 * n);
  const size_t size = knot.size() / n, spans = size - 3;
  const Real u = m.div(m.sub(c.reals[2], c.reals[3]), m.sub(c.reals[4], c.reals[3]));
  const Real scaled = m.mul(u, K(static_cast<double>(spans)));
  const Real span = m.floor(scaled);  // u in [0, 1] here: (int) is floor
  const Real below = m.less(u, K(0.0)), above = m.less(K(1.0), u);
  const size_t end_span = spans >= 3 ? spans - 3 : spans - 1;
  for (size_t i = 0; i < n; ++i) {
    const Real end_u = m.sub(scaled, K(static_cast<double>(end_span)));
    Real v = catmullRom(m, knot, n, end_span, i, end_u);  // span >= spans: u = 1 exactly
    for (size_t k = spans; k-- > 0;) {
      const Real local = m.sub(scaled, K(static_cast<double>(k)));
      v = m.select(m.less(span, K(static_cast<double>(k + 1))), catmullRom(m, knot, n, k, i, local), v);
    }
    s[i] = m.select(below, knot[i], m.select(above, knot[(size - 1) * n + i], v));
  }
  return K(1.0);
}

// hfA_RGBToHSV(rgb, hsv): v = max, s = (max - min)/max (0 where max <= 0), h in degrees from the
// channel that is the maximum (HyperFun's three `if`s, each adding its term: a tie with the next
// channel adds nothing for that channel), 0 where max = min.
Real hfARGBToHSV(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Items& rgb = atLeast(c, 0, 3);
  Items& hsv = atLeast(c, 1, 3);
  const Real r = rgb[0], g = rgb[1], b = rgb[2];
  auto lower = [&](Real p, Real q) { return m.select(m.less(p, q), p, q); };   // LocalMIN
  auto higher = [&](Real p, Real q) { return m.select(m.less(q, p), p, q); };  // LocalMAX
  const Real lo = lower(r, lower(g, b)), hi = higher(r, higher(g, b));
  const Real delta = m.sub(hi, lo);
  auto term = [&](Real channel, Real next, Real offset, Real p, Real q) {
    const Real when = m.mul(equal(m, hi, channel), m.sub(K(1.0), equal(m, hi, next)));
    return m.select(when, m.add(offset, m.div(m.sub(p, q), delta)), K(0.0));
  };
  const Real h = m.add(m.add(term(r, g, K(0.0), g, b), term(g, b, K(2.0), b, r)), term(b, r, K(4.0), r, g));
  hsv[0] = m.select(m.less(K(0.0), delta), m.mul(h, K(60.0)), K(0.0));
  hsv[1] = m.select(m.less(K(0.0), hi), m.div(delta, hi), K(0.0));
  hsv[2] = hi;
  return K(1.0);
}

// hfA_HSVToRGB(hsv, rgb): h wrapped by 360 -- HyperFun's loops leave h in [0, 360) from below and
// (0, 360] from above, here h - 360 floor(h/360) and h - 360 (ceil(h/360) - 1) -- then the
// piecewise-linear hue ramps capped at 1, rgb = (1 - s + s ramp) v.
Real hfAHSVToRGB(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Items& hsv = atLeast(c, 0, 3);
  Items& rgb = atLeast(c, 1, 3);
  const Real h0 = hsv[0], s = hsv[1], v = hsv[2];
  const Real turns = m.div(h0, K(360.0));
  const Real up = m.sub(h0, m.mul(K(360.0), m.floor(turns)));
  const Real down = m.sub(h0, m.mul(K(360.0), m.sub(m.neg(m.floor(m.neg(turns))), K(1.0))));
  const Real h = m.select(m.less(h0, K(0.0)), up, m.select(m.less(K(360.0), h0), down, h0));
  const Real first = m.less(h, K(120.0)), second = m.less(h, K(240.0));
  auto ramp = [&](Real a, Real b2, Real c3) { return m.select(first, a, m.select(second, b2, c3)); };
  auto sixtieth = [&](Real p) { return m.div(p, K(60.0)); };
  const Real ramps[3] = {
      ramp(sixtieth(m.sub(K(120.0), h)), K(0.0), sixtieth(m.sub(h, K(240.0)))),
      ramp(sixtieth(h), sixtieth(m.sub(K(240.0), h)), K(0.0)),
      ramp(K(0.0), sixtieth(m.sub(h, K(120.0))), sixtieth(m.sub(K(360.0), h)))};
  for (int i = 0; i < 3; ++i) {
    const Real capped = m.select(m.less(ramps[i], K(1.0)), ramps[i], K(1.0));
    rgb[i] = m.mul(m.add(m.sub(K(1.0), s), m.mul(s, capped)), v);
  }
  return K(1.0);
}

}  // namespace pf::field::hyperfun
