// The shading pass (raster/shading.h) lights runs of pixels at once (LightingEquation::shadeRun
// over the G-buffer's planes). Against the pixel-at-a-time algorithm written out here -- the
// normal normalised, the face chosen for two-sided lighting, trackedMaterial(), then
// LightingEquation::shade() -- on random G-buffers: the same bytes, for every colour-material
// mode and face, positional, directional and spot lights, zero and unnormalised normals, unlit
// states with a colour parameter or a constant colour, and a colour mask.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "raster/limits.h"
#include "raster/shading.h"
#include "tests/unit/random_lighting.h"

using namespace pf;


TEST(ShadingPass, RunsGiveThePixelAtATimeBytes) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), pos(0.0f, 1.0f);
  constexpr size_t kPlane = static_cast<size_t>(kTileSize) * kTileSize;
  for (int trial = 0; trial < 20; ++trial) {
    // Two lighting states, three lit shading states and two unlit ones.
    std::vector<LightingState> lightings = {test::randomLighting(rng), test::randomLighting(rng)};
    std::vector<LightingEquation> equations(lightings.begin(), lightings.end());
    std::vector<ShadeState> shades(5);
    for (int k = 0; k < 5; ++k) {
      ShadeState& s = shades[static_cast<size_t>(k)];
      s.color_slot = k == 4 ? -1 : 0;
      for (float& c : s.constant_color) c = pos(rng);
      if (k < 3) {
        s.surface_slot = 4;
        s.lighting = k % 2;
      }
    }
    // The G-buffer: colour (4 slots), P and N (6): runs of random length and state, some empty;
    // in every other trial one state a row, with many gaps (the pass shades such a row as one
    // span, the gaps computed and not written).
    std::vector<float> planes(10 * kPlane);
    std::vector<float*> slots(10);
    for (int k = 0; k < 10; ++k) slots[static_cast<size_t>(k)] = planes.data() + static_cast<size_t>(k) * kPlane;
    std::vector<uint32_t> ids(kPlane);
    const bool one_state_rows = trial % 2 == 1;
    for (size_t i = 0; i < kPlane;) {
      const uint32_t id = rng() % (one_state_rows ? 3 : 7) == 0 ? 0u : 1u + rng() % 5;
      for (size_t end = std::min(kPlane, i + 1 + rng() % 20); i < end; ++i) ids[i] = id;
    }
    if (one_state_rows)
      for (size_t row = 0; row < kPlane; row += kTileSize) {
        const uint32_t id = 1u + rng() % 5;
        for (size_t i = row; i < row + kTileSize; ++i) ids[i] = ids[i] != 0 ? id : 0u;
      }
    for (size_t i = 0; i < kPlane; ++i) {
      for (int k = 0; k < 4; ++k) slots[static_cast<size_t>(k)][i] = pos(rng) * 1.2f - 0.1f;
      slots[4][i] = u(rng) * 2;
      slots[5][i] = u(rng) * 2;
      slots[6][i] = -2.0f - 3.0f * pos(rng);
      const int kind = static_cast<int>(rng() % 8);
      for (int k = 7; k < 10; ++k) slots[static_cast<size_t>(k)][i] = kind == 0 ? 0.0f : u(rng) * (kind == 1 ? 5.0f : 1.0f);
    }
    const uint8_t mask = trial % 3 == 0 ? 0x5 : 0xf;
    std::vector<uint8_t> got(kPlane * 4, 7), want(kPlane * 4, 7);
    const ShadeTarget target{got.data(), kTileSize, 0, 0, kTileSize, kTileSize, mask};
    EXPECT_EQ(shadeTile(ids.data(), slots.data(), shades.data(), lightings.data(), equations.data(), target),
              static_cast<uint64_t>(std::count_if(ids.begin(), ids.end(), [](uint32_t id) { return id != 0; })));

    // Pixel at a time.
    for (size_t i = 0; i < kPlane; ++i) {
      if (ids[i] == 0) continue;
      const ShadeState& s = shades[ids[i] - 1];
      float c[4];
      for (int k = 0; k < 4; ++k) c[k] = s.color_slot >= 0 ? slots[static_cast<size_t>(s.color_slot + k)][i] : s.constant_color[k];
      if (s.lighting >= 0) {
        const LightingState& l = lightings[static_cast<size_t>(s.lighting)];
        const glm::vec3 p(slots[4][i], slots[5][i], slots[6][i]);
        glm::vec3 n(slots[7][i], slots[8][i], slots[9][i]);
        if (glm::length(n) > 0.0f) n = glm::normalize(n);
        const int face = l.two_side && glm::dot(n, -p) < 0.0f ? 1 : 0;
        const glm::vec4 lit = equations[static_cast<size_t>(s.lighting)].shade(
            trackedMaterial(l, face, glm::vec4(c[0], c[1], c[2], c[3])), p, face ? -n : n);
        for (int k = 0; k < 4; ++k) c[k] = lit[k];
      }
      for (int k = 0; k < 4; ++k)
        if (mask & (1u << k)) want[i * 4 + static_cast<size_t>(k)] = toUnorm8(c[k]);
    }
    size_t differ = 0;
    for (size_t i = 0; i < got.size(); ++i) differ += got[i] != want[i];
    EXPECT_EQ(differ, 0u) << "trial " << trial;
  }
}

// The branch-free conversion the fragment operations vectorize gives toUnorm8's value for
// every float: all 2^32 bit patterns, in strides so that the test stays quick (every 61st
// pattern), plus the boundaries, infinities and NaNs exactly.
TEST(ShadingPass, SelectFormOfToUnorm8GivesTheSameValueForEveryFloat) {
  auto check = [](float c) { return toUnorm8Select(c) == static_cast<int>(toUnorm8(c)); };
  uint64_t wrong = 0;
  for (uint64_t b = 0; b <= 0xffffffffull; b += 61) {
    const uint32_t u = static_cast<uint32_t>(b);
    float c;
    std::memcpy(&c, &u, sizeof c);
    wrong += !check(c);
  }
  for (float c : {0.0f, -0.0f, 1.0f, 254.5f / 255.0f, 0.5f / 255.0f, std::nextafter(1.0f, 0.0f),
                  std::nextafter(1.0f, 2.0f), std::numeric_limits<float>::infinity(),
                  -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
                  std::numeric_limits<float>::denorm_min()})
    wrong += !check(c);
  EXPECT_EQ(wrong, 0u);
}
