// pfrender-mpi's splits of a scene's objects over ranks (tools/mpi/object_split.h): every split
// gives each object to exactly one rank, each rank's objects in scene order; block keeps the
// scene's order across ranks (the split whose composite is the scene's own image, ties
// included), spatial cuts by the objects' centres. After PixelFlow's renderers each drawing a
// fraction of the primitives (Molnar et al. 1992, cited in seed 003 section 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "mpi/object_split.h"

using pf::split::Split;

namespace {

TEST(ObjectSplit, EverySplitPartitionsTheObjectsInSceneOrder) {
  for (Split split : {Split::RoundRobin, Split::Block, Split::Spatial})
    for (int ranks : {1, 2, 3, 4, 7})
      for (uint64_t count : {0u, 1u, 5u, 14u, 100u}) {
        std::vector<int> owner(count, -1);
        for (int r = 0; r < ranks; ++r) {
          const auto mine = pf::split::objectsOfRank(split, count, r, ranks, [](uint64_t i) { return -double(i % 5); });
          EXPECT_TRUE(std::is_sorted(mine.begin(), mine.end()));
          for (uint64_t i : mine) {
            ASSERT_LT(i, count);
            EXPECT_EQ(owner[i], -1) << "object " << i << " on two ranks";
            owner[i] = r;
          }
          // Shares differ by at most one object.
          EXPECT_LE(mine.size(), count / ranks + 1);
          EXPECT_GE(mine.size(), count / ranks);
        }
        for (int o : owner) EXPECT_NE(o, -1);
      }
}

TEST(ObjectSplit, BlockKeepsOrderAcrossRanksAndSpatialCutsByCentre) {
  // Block: every object of rank r comes before every object of rank r + 1.
  const auto a = pf::split::objectsOfRank(Split::Block, 10, 0, 3, nullptr);
  const auto b = pf::split::objectsOfRank(Split::Block, 10, 1, 3, nullptr);
  ASSERT_FALSE(a.empty());
  ASSERT_FALSE(b.empty());
  EXPECT_LT(a.back(), b.front());
  // Spatial: rank 0 gets the objects with the smallest x.
  const auto left = pf::split::objectsOfRank(Split::Spatial, 6, 0, 2, [](uint64_t i) { return i % 2 ? -1.0 : 1.0; });
  EXPECT_EQ(left, (std::vector<uint64_t>{1, 3, 5}));
  // A NaN centre does not break the sort.
  const auto nan = pf::split::objectsOfRank(Split::Spatial, 4, 1, 2, [](uint64_t i) { return i == 2 ? std::nan("") : double(i); });
  EXPECT_EQ(nan, (std::vector<uint64_t>{2, 3}));
}

TEST(ObjectSplit, ParsesItsNames) {
  EXPECT_EQ(pf::split::parseSplit("round-robin"), Split::RoundRobin);
  EXPECT_EQ(pf::split::parseSplit("block"), Split::Block);
  EXPECT_EQ(pf::split::parseSplit("spatial"), Split::Spatial);
  EXPECT_FALSE(pf::split::parseSplit("diagonal"));
}

TEST(ObjectSplit, ObjectCentreIsItsVerticesOrCentresThroughItsTransform) {
  pf::scene::Object o;
  o.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0}};
  o.transform[3] = glm::dvec4(10, 0, 0, 1);
  EXPECT_EQ(pf::split::objectCentre(o), glm::dvec3(11, 1, 0));
  pf::scene::Object s;
  s.points = {{{"center", {1, 1, 1}, ""}}, {{"center", {3, 1, 1}, ""}}};
  EXPECT_EQ(pf::split::objectCentre(s), glm::dvec3(2, 1, 1));
}

}  // namespace
