// Which of a scene's objects each rank draws (pfrender-mpi): sort-last compositing lets any
// split be composited, as PixelFlow's renderers each drew "a fraction of the primitives"
// (Molnar et al. 1992, cited in seed 003 section 1). A rank always draws its objects in the
// scene's order. The composite equals one process drawing rank 0's objects, then rank 1's, ...
// (equal depths go to the lower rank), so it equals the scene drawn in its own order wherever
// no two objects on different ranks, in the opposite order, meet at exactly the same depth --
// always for `block`, whose ranks hold consecutive objects in order.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace pf::split {

enum class Split {
  RoundRobin,  // object i to rank i mod p: every rank gets a similar mix (load balance)
  Block,       // objects [i*n/p, (i+1)*n/p) to rank i: submission order kept across ranks
  Spatial,     // sorted by the x of their world centre, then cut into p runs of equal count:
               // each rank's image covers a slab of the screen (compresses well)
};

std::optional<Split> parseSplit(const std::string& name);

// The objects rank `rank` of `ranks` draws, ascending. centre_x(i) is object i's world x
// (called for every object, for Spatial only).
std::vector<uint64_t> objectsOfRank(Split split, uint64_t count, int rank, int ranks,
                                    const std::function<double(uint64_t)>& centre_x);

// A scene object's world centre: the mean of its vertices, else of its "center" parameters,
// else its origin, through its transform.
glm::dvec3 objectCentre(const scene::Object& object);

}  // namespace pf::split
