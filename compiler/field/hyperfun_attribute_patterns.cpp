// HyperFun's procedural attribute patterns as tape builders: hfA_CheckerBoard, hfA_Circles,
// hfA_Crackles and hfA_NoiseG -- solid textures of the point x, each HyperFun's C code restated
// ([HFC] src/hflibrary_lib/hfA_*.c and pattern.h), argument orders read off its reversed f_a as in
// hyperfun_attributes.cpp. Their integer parts (the checker cell, the fraction of a radius,
// Crackles' 1000-step cycle) use the tape's floor; their writes into s are, per item, `condition ?
// new value : old value`. docs/hyperfun.md lists the quirks followed (Circles' and Crackles' write
// of 1.1 into their own colour table, Crackles' last match winning).
#include <cmath>
#include <numbers>

#include "compiler/field/hyperfun_library_internal.h"

namespace pf::field::hyperfun {

namespace {

using Items = std::vector<Real>;
Real K(double v) { return Real::known(v); }

// 1 where both are 1 (0/1 operands).
Real both(TapeAlgebra& m, Real a, Real b) { return m.mul(a, b); }

// pattern.h's Noise: Gardner's series with amplitude 1 at frequency `freq` and phase `phase`,
// Sx Sy Sz mapped from [-c^3, c^3] (c = 2.17/1.17) onto [0, 1].
Real gardner(TapeAlgebra& m, Real x, Real y, Real z, Real phase, Real freq) {
  const Real ax = m.mul(freq, x), ay = m.mul(freq, y), az = m.mul(freq, z);
  const Real sx = m.sin(ax), sy = m.sin(ay), sz = m.sin(az);
  const double a1d = 1.0 / 1.17;
  const Real sx2 = m.mul(K(a1d), m.sin(m.add(m.div(ax, K(1.35)), m.mul(phase, sz))));
  const Real sy2 = m.mul(K(a1d), m.sin(m.add(m.div(ay, K(1.35)), m.mul(phase, sx))));
  const Real sz2 = m.mul(K(a1d), m.sin(m.add(m.div(az, K(1.35)), m.mul(phase, sy))));
  const Real ss = m.mul(m.mul(m.add(sx, sx2), m.add(sy, sy2)), m.add(sz, sz2));
  const double c = 2.17 / 1.17, c_min = std::pow(-c, 3.0), c_max = -c_min;
  return m.div(m.sub(ss, K(c_min)), K(c_max - c_min));
}

// Circles' and Crackles' table: `color[n_prob] = 1.1` (a write into the caller's attribute table,
// at item n_prob + 1, when it has one -- HyperFun writes past a shorter array), then s takes the
// colour set i where prob[i] <= v < prob[i + 1] (i < n_prob - 1). `first_wins`: Circles stops at
// the first such i, Crackles lets the last win; where none holds s is left as it was.
void tableColour(LibraryCall& c, int out, int colours, int probs, Real v, bool first_wins) {
  TapeAlgebra& m = c.alg;
  Items& rgb = *c.arrays[out];
  Items& colour = *c.arrays[colours];
  const Items& prob = *c.arrays[probs];
  const size_t n = prob.size(), dim = rgb.size();
  if (n >= 2) atLeast(c, colours, dim * (n - 1));
  if (colour.size() > n) colour[n] = K(1.1);
  if (n < 2) return;
  for (size_t k = 0; k + 1 < n; ++k) {
    const size_t i = first_wins ? n - 2 - k : k;  // the winner is applied last
    const Real hit = both(m, m.lessEq(prob[i], v), m.less(v, prob[i + 1]));
    for (size_t j = 0; j < dim; ++j) rgb[j] = m.select(hit, colour[dim * i + j], rgb[j]);
  }
}

}  // namespace

// hfA_CheckerBoard(x, block_size, gap_size, output, input_block, input_gap): the cell of period
// block + gap on each axis is floor(x / (block + gap)); output takes input_block's items where x
// lies strictly inside the cell's block (x > corner, x < corner + block on all three axes), else
// input_gap's. HyperFun does nothing when the two input arrays differ in size: primflow says so.
Real hfACheckerBoard(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Items& x = atLeast(c, 0, 3);
  const Items& block = atLeast(c, 1, 3);
  const Items& gap = atLeast(c, 2, 3);
  const size_t n = c.arrays[4]->size();
  items(c, 5, n);
  Items& out = atLeast(c, 3, n);
  const Items &in_block = *c.arrays[4], &in_gap = *c.arrays[5];
  Real inside = K(1.0);
  for (size_t i = 0; i < 3; ++i) {
    const Real period = m.add(gap[i], block[i]);
    const Real corner = m.mul(period, m.floor(m.div(x[i], period)));
    inside = both(m, inside, both(m, m.less(corner, x[i]), m.less(x[i], m.add(corner, block[i]))));
  }
  for (size_t k = 0; k < n; ++k) out[k] = m.select(inside, in_block[k], in_gap[k]);
  return K(1.0);
}

// hfA_Circles(x, output, input_attr, input_map): v = fmod(|x|, 1) -- concentric shells of width 1
// about the origin -- chooses a colour set from the table (the first interval holding v).
Real hfACircles(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Items& x = atLeast(c, 0, 3);
  const Real r = m.sqrt(m.add(m.add(m.square(x[0]), m.square(x[1])), m.square(x[2])));
  tableColour(c, 1, 2, 3, m.sub(r, m.floor(r)), true);  // r >= 0: fmod(r, 1) = r - floor(r), exactly
  return K(1.0);
}

// hfA_Crackles(x, output, freq, input_attr, input_map): with phase = (|x1| + |x2| + |x3|)/3 and
// n(a, b, c) the Gardner noise above, w = (2 n(x1, x1, x3) - 1) + (2 n(x2, x2, x1) - 1) +
// (2 n(x3, x3, x2) - 1); v = (1 + sin(2 pi i / 1000))/2 with i = (int)(1000 (w - floor w)); v chooses
// a colour set from the table (the last interval holding v).
Real hfACrackles(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Items& x = atLeast(c, 0, 3);
  const Real freq = c.reals[2];
  const Real phase = m.div(m.add(m.add(m.abs(x[0]), m.abs(x[1])), m.abs(x[2])), K(3.0));
  auto centred = [&](Real a, Real b, Real cc) { return m.sub(m.mul(gardner(m, a, b, cc, phase, freq), K(2.0)), K(1.0)); };
  const Real w = m.add(m.add(centred(x[0], x[0], x[2]), centred(x[1], x[1], x[0])), centred(x[2], x[2], x[1]));
  const Real steps = m.floor(m.mul(m.sub(w, m.floor(w)), K(1000.0)));  // >= 0: (int) is floor
  const Real v = m.mul(m.add(K(1.0), m.sin(m.mul(steps, K(2.0 * std::numbers::pi / 1000.0)))), K(0.5));
  tableColour(c, 1, 3, 4, v, false);
  return K(1.0);
}

// hfA_NoiseG(x, freq, phase): Gardner's solid noise with amplitude 1, mapped onto [0, 1] (the
// returned value; s is not written).
Real hfANoiseG(LibraryCall& c) {
  TapeAlgebra& m = c.alg;
  const Items& x = atLeast(c, 0, 3);
  return gardner(m, x[0], x[1], x[2], c.reals[2], c.reals[1]);
}

}  // namespace pf::field::hyperfun
