// AccuracyProbe (see accuracy_probe.h).
#include "pfview/accuracy_probe.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>

#include "compiler/field/field_source.h"
#include "field/field_reference.h"

namespace pf::view {

std::string AccuracyFigure::text() const {
  char buf[160];
  std::snprintf(buf, sizeof buf, "accuracy: %d of %d rays off, depth error <= %.2g", mismatches, rays,
                max_depth_error);
  return buf;
}

AccuracyProbe::AccuracyProbe(const model::Model& model, const model::ModelView& view)
    : box_min_(view.box_min), box_max_(view.box_max) {
  DiagnosticLog log;
  const std::optional<field::FieldTape> tape = field::compileFieldSource(
      model.format, model.path, model.text, {}, model.format == field::FieldFormat::HyperFun ? view.time : 0.0, log);
  if (!tape) throw model::ModelError(log.format());
  tape_ = *tape;
}

AccuracyFigure AccuracyProbe::measure(const scene::Camera& c, int width, int height, const float* depth) const {
  // The camera's matrices as scene drawing sets them (tools/scene/scene_draw.cpp, setCamera).
  const double aspect = static_cast<double>(width) / height;
  glm::dmat4 projection;
  if (c.ortho) {
    const double h = c.height / 2;
    projection = glm::ortho(-h * aspect, h * aspect, -h, h, c.near, c.far);
  } else {
    const double h = c.near * std::tan(glm::radians(c.fov_degrees) / 2);
    projection = glm::frustum(-h * aspect, h * aspect, -h, h, c.near, c.far);
  }
  const glm::dmat4 to_world = glm::inverse(projection * glm::lookAt(c.eye, c.target, c.up));
  AccuracyFigure fig;
  constexpr int kColumns = 16, kRows = 12;
  for (int r = 0; r < kRows; ++r)
    for (int q = 0; q < kColumns; ++q) {
      const int x = (2 * q + 1) * width / (2 * kColumns), y = (2 * r + 1) * height / (2 * kRows);
      auto unproject = [&](double window_z) {
        const glm::dvec4 p = to_world * glm::dvec4((x + 0.5) / width * 2 - 1, (y + 0.5) / height * 2 - 1,
                                                   window_z * 2 - 1, 1.0);
        return glm::dvec3(p) / p.w;
      };
      const glm::dvec3 o = unproject(0.0), d = unproject(1.0) - o;
      // The ray's span in the box (slabs), t in [0, 1] from the near to the far plane.
      double t0 = 0.0, t1 = 1.0;
      for (int k = 0; k < 3; ++k) {
        if (d[k] == 0.0) {
          if (o[k] < box_min_[k] || o[k] > box_max_[k]) t1 = -1.0;
          continue;
        }
        double a = (box_min_[k] - o[k]) / d[k], b = (box_max_[k] - o[k]) / d[k];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
      }
      if (!(t1 >= t0)) continue;
      ++fig.rays;
      const double want = field::testing::referenceHit(tape_, {o.x, o.y, o.z}, {d.x, d.y, d.z}, t0, t1, 2000);
      const float zw = depth[static_cast<size_t>(y) * width + x];
      const bool drawn = zw < 1.0f;
      if (drawn != std::isfinite(want)) {
        ++fig.mismatches;
        continue;
      }
      if (!drawn) continue;
      const glm::dvec3 got = unproject(zw), ref = o + d * want;
      fig.max_depth_error = std::max(fig.max_depth_error, glm::length(got - ref));
    }
  return fig;
}

}  // namespace pf::view
