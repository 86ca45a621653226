// Per-vertex lighting a batch at a time (api/src/vertex_lighting.h) against a call of
// LightingEquation::shade() per vertex -- what glVertex did before vertices were batched --
// on random lighting states, points, normals (unit, unnormalised, zero) and per-vertex
// materials (GL_COLOR_MATERIAL changes them vertex by vertex): the same bits, front and back,
// for batches of every length from 1 to LitPoints::kMax, written only to the rows gathered.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "api/src/vertex_lighting.h"
#include "tests/unit/random_lighting.h"

using namespace pf;

namespace {

Material randomMaterial(std::mt19937& rng) {
  std::uniform_real_distribution<float> pos(0.0f, 1.0f);
  auto colour = [&] { return glm::vec4(pos(rng), pos(rng), pos(rng), pos(rng)); };
  Material m;
  m.ambient = colour();
  m.diffuse = colour();
  m.specular = colour();
  m.emission = colour() * 0.3f;
  m.shininess = rng() % 3 == 0 ? 0.0f : (rng() % 2 ? 60.0f * pos(rng) : static_cast<float>(rng() % 129));
  return m;
}

bool sameBits(const float* a, const glm::vec4& b) { return std::memcmp(a, &b[0], sizeof(float) * 4) == 0; }

}  // namespace

TEST(VertexLighting, BatchesGiveTheBitsOfAShadeCallPerVertex) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int compared = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const LightingState lighting = test::randomLighting(rng);
    const LightingEquation equation(lighting);
    const bool two_sided = trial % 2 == 1;
    // Rows of 12 floats: something else (4), the front colour (4), the back colour (4).
    constexpr size_t kStride = 12;
    const int count = 1 + trial * 7 % VertexLightingBatch::kMax;  // 1 .. 64 vertices
    const int rows = count + 5;                                    // some rows not gathered
    std::vector<float> row_shading(rows * kStride, -7.0f);
    std::vector<int> row_of(count);
    std::vector<glm::vec3> eye(count), normal(count);
    std::vector<Material> front(count), back(count);
    VertexLightingBatch batch;
    for (int i = 0; i < count; ++i) {
      row_of[i] = i + (i > count / 2 ? 5 : 0);
      eye[i] = glm::vec3(u(rng), u(rng), -1.0f - 3.0f * (u(rng) + 1.0f));
      switch (i % 4) {
        case 0: normal[i] = glm::vec3(0.0f); break;                                  // no normal
        case 1: normal[i] = glm::vec3(3.0f * u(rng), u(rng), u(rng)); break;          // unnormalised
        default: normal[i] = glm::normalize(glm::vec3(u(rng), u(rng), u(rng) + 0.01f));
      }
      front[i] = randomMaterial(rng);
      back[i] = randomMaterial(rng);
      batch.add(static_cast<size_t>(row_of[i]), eye[i], normal[i], front[i], two_sided ? &back[i] : nullptr);
    }
    EXPECT_EQ(batch.full(), count == VertexLightingBatch::kMax);
    batch.flush(equation, {row_shading.data(), kStride, 4, two_sided ? 8 : -1});
    EXPECT_TRUE(batch.empty());
    std::vector<bool> gathered(rows, false);
    for (int i = 0; i < count; ++i) {
      gathered[row_of[i]] = true;
      const float* row = row_shading.data() + row_of[i] * kStride;
      const glm::vec4 want_front = equation.shade(front[i], eye[i], normal[i]);
      EXPECT_TRUE(sameBits(row + 4, want_front)) << "trial " << trial << " vertex " << i << " front";
      if (two_sided) {
        const glm::vec4 want_back = equation.shade(back[i], eye[i], -normal[i]);
        EXPECT_TRUE(sameBits(row + 8, want_back)) << "trial " << trial << " vertex " << i << " back";
      }
      ++compared;
    }
    // Nothing else written: the other channels of the gathered rows, and every other row.
    for (int r = 0; r < rows; ++r)
      for (size_t c = 0; c < kStride; ++c) {
        const bool colour = gathered[r] && (c >= 4 && c < (two_sided ? 12u : 8u));
        if (!colour) {
          EXPECT_EQ(row_shading[r * kStride + c], -7.0f) << "row " << r << " channel " << c;
        }
      }
  }
  EXPECT_GT(compared, 1000);
}
