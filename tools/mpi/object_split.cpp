// Splitting a scene's objects over ranks (object_split.h).
#include "object_split.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pf::split {

std::optional<Split> parseSplit(const std::string& name) {
  if (name == "round-robin") return Split::RoundRobin;
  if (name == "block") return Split::Block;
  if (name == "spatial") return Split::Spatial;
  return std::nullopt;
}

std::vector<uint64_t> objectsOfRank(Split split, uint64_t count, int rank, int ranks,
                                    const std::function<double(uint64_t)>& centre_x) {
  std::vector<uint64_t> mine;
  const uint64_t p = static_cast<uint64_t>(ranks), r = static_cast<uint64_t>(rank);
  // Cuts at i*n/p, computed without overflowing for any count a machine can hold.
  auto cut = [&](uint64_t i) {
    return static_cast<uint64_t>((static_cast<unsigned __int128>(i) * count) / p);
  };
  switch (split) {
    case Split::RoundRobin:
      for (uint64_t i = r; i < count; i += p) mine.push_back(i);
      break;
    case Split::Block:
      for (uint64_t i = cut(r); i < cut(r + 1); ++i) mine.push_back(i);
      break;
    case Split::Spatial: {
      std::vector<double> x(count);
      for (uint64_t i = 0; i < count; ++i) {
        x[i] = centre_x(i);
        if (std::isnan(x[i])) x[i] = HUGE_VAL;  // a strict order for the sort
      }
      std::vector<uint64_t> order(count);
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(), [&](uint64_t a, uint64_t b) { return x[a] < x[b]; });
      mine.assign(order.begin() + static_cast<std::ptrdiff_t>(cut(r)), order.begin() + static_cast<std::ptrdiff_t>(cut(r + 1)));
      std::sort(mine.begin(), mine.end());
      break;
    }
  }
  return mine;
}

glm::dvec3 objectCentre(const scene::Object& o) {
  glm::dvec3 sum(0.0);
  size_t n = 0;
  for (const glm::dvec3& v : o.vertices) sum += v, ++n;
  if (n == 0) {
    auto add = [&](const std::vector<scene::ParamValue>& params) {
      for (const scene::ParamValue& p : params)
        if (p.name == "center" && p.values.size() >= 3) sum += glm::dvec3(p.values[0], p.values[1], p.values[2]), ++n;
    };
    add(o.params);
    for (const auto& point : o.points) add(point);
  }
  const glm::dvec3 local = n ? sum / static_cast<double>(n) : sum;
  return glm::dvec3(o.transform * glm::dvec4(local, 1.0));
}

}  // namespace pf::split
