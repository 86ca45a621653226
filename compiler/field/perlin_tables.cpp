// HyperFun's Perlin noise tables, built by its init() with a fixed generator (perlin_tables.h).
#include "compiler/field/perlin_tables.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace pf::field {

namespace {

constexpr int kB = 256;  // PERLIN_B

// HyperFun's init(), rand() being std::minstd_rand's draws (values in [1, 2^31 - 2], as rand()'s
// are non-negative ints): g1 and g2 are drawn only to keep g3's draws where HyperFun has them.
PerlinTables build() {
  PerlinTables t{};
  std::minstd_rand draw;
  auto component = [&] { return static_cast<double>(static_cast<int>(draw() % (kB + kB)) - kB) / kB; };
  int i = 0;
  for (i = 0; i < kB; ++i) {
    t.perm[i] = i;
    (void)component();  // g1[i]
    (void)component(), (void)component();  // g2[i]
    double* g = t.grad[i];
    for (int j = 0; j < 3; ++j) g[j] = component();
    const double s = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);  // normalize3
    for (int j = 0; j < 3; ++j) g[j] = g[j] / s;
  }
  while (--i) {
    const int j = static_cast<int>(draw() % kB);
    std::swap(t.perm[i], t.perm[j]);
  }
  for (i = 0; i < kB + 2; ++i) {
    t.perm[kB + i] = t.perm[i];
    for (int j = 0; j < 3; ++j) t.grad[kB + i][j] = t.grad[i][j];
  }
  for (int k = 0; k < kPerlinTableSize; ++k) {
    t.values[0][k] = static_cast<float>(t.perm[k]);
    for (int j = 0; j < 3; ++j) t.values[1 + j][k] = static_cast<float>(t.grad[k][j]);
  }
  for (int table = 0; table < 4; ++table) {
    const float* v = t.values[table];
    t.lowest[table] = *std::min_element(v, v + kPerlinTableSize);
    t.highest[table] = *std::max_element(v, v + kPerlinTableSize);
  }
  return t;
}

int clampedIndex(float a) {
  const float f = std::floor(a);
  if (!(f > 0.0f)) return 0;
  if (f >= static_cast<float>(kPerlinTableSize - 1)) return kPerlinTableSize - 1;
  return static_cast<int>(f);
}

}  // namespace

const PerlinTables& perlinTables() {
  static const PerlinTables tables = build();
  return tables;
}

float perlinTableValue(FieldOp op, float a) {
  if (a != a) return a;
  return perlinTables().values[perlinTableOf(op)][clampedIndex(a)];
}

PerlinRange perlinTableRange(FieldOp op, float lo, float hi) {
  if (lo != lo || hi != hi) return {0.0f, 0.0f, true};
  const PerlinTables& t = perlinTables();
  const int table = perlinTableOf(op);
  const int first = clampedIndex(lo), last = clampedIndex(hi);
  // A wide range: the table's own extremes (sound, and the usual case once an index spans cells).
  if (last - first >= 64) return {t.lowest[table], t.highest[table], false};
  const float* v = t.values[table];
  float l = v[first], h = v[first];
  for (int k = first + 1; k <= last; ++k) l = std::min(l, v[k]), h = std::max(h, v[k]);
  return {l, h, false};
}

}  // namespace pf::field
