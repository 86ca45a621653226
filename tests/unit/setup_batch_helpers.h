// Helpers of the batched-setup tests (setup_batch_test.cpp, setup_batch_images_test.cpp): a
// perspective state, random instances of any primitive (some of them broken), the built-ins.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "compiler/builtin_primitives.h"
#include "raster/raster_state.h"

namespace pf::test {

constexpr int kSize = 128;

inline glm::mat4 projection() { return glm::frustum(-0.5f, 0.5f, -0.5f, 0.5f, 1.0f, 20.0f); }
inline glm::mat4 modelview() {
  glm::mat4 m = glm::translate(glm::mat4(1), glm::vec3(0.1f, -0.2f, -6.0f));
  m = glm::rotate(m, glm::radians(40.0f), glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f)));
  return glm::scale(m, glm::vec3(1.3f));
}

inline RasterState testState(uint32_t iteration_cap = 65536) {
  RasterState s;
  s.vp_scale_x = s.vp_offset_x = s.vp_scale_y = s.vp_offset_y = kSize / 2.0f;
  s.vp_x1 = s.vp_y1 = kSize;
  s.depth_test = true;
  s.iteration_cap = iteration_cap;
  const glm::mat4 p = projection(), mv = modelview(), ip = glm::inverse(p), imv = glm::inverse(mv);
  std::copy_n(glm::value_ptr(p), 16, s.projection);
  std::copy_n(glm::value_ptr(ip), 16, s.inv_projection);
  std::copy_n(glm::value_ptr(mv), 16, s.modelview);
  std::copy_n(glm::value_ptr(imv), 16, s.inv_modelview);
  return s;
}

inline uint32_t u(float f) { return std::bit_cast<uint32_t>(f); }

// One instance's parameter block: values a primitive expects (points in clip coordinates, as
// the API delivers them), and with `degenerate` one value broken.
inline std::vector<uint32_t> instanceParams(const CompiledPrimitive& prim, int count, std::mt19937& rng, bool degenerate) {
  std::uniform_real_distribution<float> unit(0, 1), sym(-1, 1);
  std::vector<uint32_t> block(static_cast<size_t>(prim.paramFloats(count)), 0u);
  if (prim.sequence_points == 0) block[static_cast<size_t>(prim.count_slot)] = static_cast<uint32_t>(count);
  const glm::mat4 to_clip = projection() * modelview();
  std::vector<size_t> float_slots, point_slots;
  for (const ParamInfo& p : prim.params) {
    if (prim.sequence_points == 0 && !p.per_sequence_point && p.offset == prim.count_slot) continue;
    const int n = p.per_sequence_point ? count : 1;
    for (int i = 0; i < n; ++i) {
      const size_t at = static_cast<size_t>(prim.paramOffset(p, count, i));
      switch (p.type.base) {
        case BaseType::Point: {
          const glm::vec4 q = to_clip * glm::vec4(sym(rng) * 1.5f, sym(rng) * 1.5f, sym(rng) * 1.5f, 1.0f);
          for (int c = 0; c < 4 && c < p.components; ++c) block[at + c] = u(q[c]);
          point_slots.push_back(at);
          break;
        }
        case BaseType::Int:
          for (int c = 0; c < p.components; ++c) block[at + c] = static_cast<uint32_t>(rng() % 4);
          break;
        case BaseType::Bool:
          for (int c = 0; c < p.components; ++c) block[at + c] = rng() % 2;
          break;
        case BaseType::Color:
          for (int c = 0; c < p.components; ++c) block[at + c] = u(unit(rng));
          break;
        default:  // float, vector, normal, matrix: sizes and coefficients
          for (int c = 0; c < p.components; ++c) {
            block[at + c] = u(p.components == 1 ? 0.05f + 0.5f * unit(rng) : 0.1f + 0.7f * unit(rng) * (rng() % 5 ? 1 : -1));
            float_slots.push_back(at + c);
          }
      }
    }
  }
  if (degenerate) {
    const float broken[] = {0.0f, -0.2f, -0.0f, std::numeric_limits<float>::quiet_NaN(),
                            std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(), 1e30f,
                            1e-30f};
    const int what = static_cast<int>(rng() % 3);
    if (what == 0 && !float_slots.empty()) {
      block[float_slots[rng() % float_slots.size()]] = u(broken[rng() % 8]);
    } else if (what == 1 && !point_slots.empty()) {  // behind the eye
      const glm::vec4 behind = projection() * glm::vec4(sym(rng), sym(rng), 2.0f + unit(rng), 1.0f);
      const size_t at = point_slots[rng() % point_slots.size()];
      for (int c = 0; c < 4; ++c) block[at + c] = u(behind[c]);
    } else if (!point_slots.empty()) {
      block[point_slots[rng() % point_slots.size()] + rng() % 4] = u(broken[rng() % 8]);
    }
  }
  return block;
}

inline ChannelLayout splitLayout() {  // 4 perspective-linear channels, then 4 linear ones
  ChannelLayout l;
  l.count = 8;
  l.kind_begin[0] = 0, l.kind_end[0] = 4;
  l.kind_begin[1] = 4, l.kind_end[1] = 8;
  l.kind_begin[2] = l.kind_end[2] = 8;
  for (int c = 0; c < 8; ++c) l.gbuffer_slot.push_back(c);
  return l;
}

inline std::vector<const CompiledPrimitive*> everyBuiltin() {
  std::vector<const CompiledPrimitive*> all;
  for (const auto& p : builtinPrimitives().in_order) all.push_back(p.get());
  for (const auto& p : builtinPrimitives().interpolators) all.push_back(p.get());
  return all;
}

inline const CompiledPrimitive& builtin(const std::string& name) {
  for (const CompiledPrimitive* p : everyBuiltin())
    if (p->name == name) return *p;
  ADD_FAILURE() << "no built-in " << name;
  return *builtinPrimitives().in_order.front();
}

}  // namespace pf::test
