// The look-up tables of HyperFun's Perlin noise (its perlin.h: the noise3 of Ebert et al.,
// "Texturing and Modeling", with Perlin's 1985 permutation p and unit gradients g3), as the field
// tape's four table operations read them (FieldOp::NoisePerm, NoiseGradX/Y/Z). hfA_NoiseP and
// hfA_Turbulence (compiler/field/hyperfun_attribute_noise.cpp) build noise3 on the tape from them;
// every evaluator looks them up here.
//
// HyperFun fills its tables at the first noise call by its init(), from the C library's rand()
// seeded with the time -- so HyperFun draws another texture every run, and no table is "the"
// right one. primflow runs the same init() once, draw for draw (g1, then g2, then g3 of each i;
// then the shuffle of p), with the C++ standard's std::minstd_rand at its default seed in place
// of rand(): the same texture on every machine and every run (docs/hyperfun.md).
#pragma once

#include "compiler/field/field_tape.h"

namespace pf::field {

// Entries of each table: PERLIN_B + PERLIN_B + 2 (the second half repeats the first).
constexpr int kPerlinTableSize = 514;

struct PerlinTables {
  int perm[kPerlinTableSize];          // p: a permutation of 0..255, then repeated
  double grad[kPerlinTableSize][3];    // g3: unit vectors (HyperFun's doubles), then repeated
  float values[4][kPerlinTableSize];   // the tape's tables: p, then g3's x, y and z, as floats
  float lowest[4], highest[4];         // each table's least and greatest entry
};

// The tables, built at the first call (thread-safe).
const PerlinTables& perlinTables();

// Which of the four tables a table operation reads (0: p, 1-3: g3's components).
constexpr int perlinTableOf(FieldOp op) { return static_cast<int>(op) - static_cast<int>(FieldOp::NoisePerm); }

// The entry a table operation reads at index a: floor(a) clamped to [0, kPerlinTableSize - 1]
// (HyperFun's indices are whole numbers in range; the clamp only keeps other values defined).
// NaN gives NaN.
float perlinTableValue(FieldOp op, float a);

// The least and greatest entry over the indices [lo, hi] reach (as perlinTableValue rounds and
// clamps them); `nan` when either end is NaN.
struct PerlinRange {
  float lo, hi;
  bool nan;
};
PerlinRange perlinTableRange(FieldOp op, float lo, float hi);

}  // namespace pf::field
