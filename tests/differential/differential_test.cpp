// Differential tests: one GL-1.x source (fan_scene.inc) rendered by OSMesa, the reference, and
// by primflow; the images must agree. Labels: differential, conformance.
//   - coverage: exactly the same pixels covered, each by the same triangle (so in primflow no
//     pixel is drawn twice by the wrong triangle and none is missed), the rest left clear;
//   - Gouraud colours within 2/255 per channel;
//   - depth testing, in both drawing orders, and the depth buffer's values;
//   - primflow's output is byte-identical for 1, 2, 3 and 8 rasterizer threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "differential/scenes.h"

using pfdiff::Image;
using pfdiff::kSize;
using pfdiff::Scene;

namespace {

const char* sceneName(Scene s) {
  switch (s) {
    case Scene::FanIds: return "FanIds";
    case Scene::MeshIds: return "MeshIds";
    case Scene::FanGouraud: return "FanGouraud";
    case Scene::DepthFarThenNear: return "DepthFarThenNear";
    case Scene::DepthNearThenFar: return "DepthNearThenFar";
    case Scene::Showcase: return "Showcase";
    case Scene::DepthNever: return "DepthNever";
    case Scene::DepthLess: return "DepthLess";
    case Scene::DepthEqual: return "DepthEqual";
    case Scene::DepthLequal: return "DepthLequal";
    case Scene::DepthGreater: return "DepthGreater";
    case Scene::DepthNotequal: return "DepthNotequal";
    case Scene::DepthGequal: return "DepthGequal";
    case Scene::DepthAlways: return "DepthAlways";
    case Scene::DepthMaskOff: return "DepthMaskOff";
    case Scene::DepthRangeNarrow: return "DepthRangeNarrow";
    case Scene::StripGouraud: return "StripGouraud";
    case Scene::FanModeGouraud: return "FanModeGouraud";
    case Scene::QuadsGouraud: return "QuadsGouraud";
    case Scene::QuadStripGouraud: return "QuadStripGouraud";
    case Scene::PolygonGouraud: return "PolygonGouraud";
    case Scene::QuadMeshIds: return "QuadMeshIds";
    case Scene::PointsGouraud: return "PointsGouraud";
    case Scene::LinesStar: return "LinesStar";
    case Scene::LineStripGouraud: return "LineStripGouraud";
    case Scene::LineLoopGouraud: return "LineLoopGouraud";
    case Scene::CullBack: return "CullBack";
    case Scene::CullFrontCw: return "CullFrontCw";
    case Scene::CullBoth: return "CullBoth";
    case Scene::FlatModes: return "FlatModes";
    case Scene::ColorMasks: return "ColorMasks";
    case Scene::MatrixOps: return "MatrixOps";
    case Scene::NearClipCull: return "NearClipCull";
    case Scene::VertexArrays: return "VertexArrays";
    case Scene::LitDirectional: return "LitDirectional";
    case Scene::LitPointLights: return "LitPointLights";
    case Scene::LitSpot: return "LitSpot";
    case Scene::LitTwoSide: return "LitTwoSide";
    case Scene::LitLocalViewer: return "LitLocalViewer";
    case Scene::LitNormalize: return "LitNormalize";
    case Scene::LitColorMaterial: return "LitColorMaterial";
  }
  return "?";
}

const uint8_t* pixel(const Image& img, int x, int y) {
  return &img.rgba[(static_cast<size_t>(y) * img.width + x) * 4];
}

bool isClear(const uint8_t* p) {
  return p[0] == pfdiff::kClear[0] && p[1] == pfdiff::kClear[1] && p[2] == pfdiff::kClear[2] &&
         p[3] == pfdiff::kClear[3];
}

std::string rgba(const uint8_t* p) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "(%d, %d, %d, %d)", p[0], p[1], p[2], p[3]);
  return buf;
}

// The triangle whose ID colour the pixel has; kNoId for the clear colour; -2 for any other colour.
int idOf(const uint8_t* p, int triangles) {
  if (isClear(p)) return pfdiff::kNoId;
  int n = p[0] + 256 * p[1];
  int id = n - 1;
  if (id < 0 || id >= triangles || p[2] != ((id * 37) & 255) || p[3] != 255) return -2;
  return id;
}

// With PF_DIFF_DUMP=DIR in the environment, every rendered image is also written to
// DIR/<renderer>_<scene>.ppm (top row first) for looking at.
void dump(const Image& img, const std::string& name) {
  const char* dir = std::getenv("PF_DIFF_DUMP");
  if (!dir || !*dir || img.rgba.empty()) return;
  std::string path = std::string(dir) + "/" + name + ".ppm";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return;
  std::fprintf(f, "P6\n%d %d\n255\n", img.width, img.height);
  for (int y = img.height - 1; y >= 0; --y)
    for (int x = 0; x < img.width; ++x) std::fwrite(&img.rgba[(size_t(y) * img.width + x) * 4], 1, 3, f);
  std::fclose(f);
}

// OSMesa draws; a machine without a working OSMesa cannot run these tests at all.
Image reference(Scene s) {
  Image img = pfdiff::renderOsmesa(s, kSize, kSize);
  if (!img.ok) ADD_FAILURE() << "OSMesa could not render " << sceneName(s);
  dump(img, std::string("osmesa_") + sceneName(s));
  return img;
}

Image primflow(Scene s, int threads) {
  Image img = pfdiff::renderPrimflow(s, kSize, kSize, threads);
  if (!img.ok) ADD_FAILURE() << "primflow failed (no context or a GL error) on " << sceneName(s);
  dump(img, std::string("primflow_") + sceneName(s) + "_t" + std::to_string(threads));
  return img;
}

// Every pixel: the same triangle ID in both images.
void expectSameCoverage(Scene s, int triangles, int min_covered = kSize * kSize / 4) {
  Image ref = reference(s);
  Image got = primflow(s, 1);
  ASSERT_TRUE(ref.ok && got.ok);

  int mismatches = 0, foreign = 0, covered_ref = 0, covered_got = 0;
  std::map<int, int> count_ref, count_got;
  std::ostringstream examples;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      int a = idOf(pixel(ref, x, y), triangles);
      int b = idOf(pixel(got, x, y), triangles);
      ASSERT_NE(a, -2) << "OSMesa wrote a colour that is no ID at (" << x << ", " << y
                       << "): " << rgba(pixel(ref, x, y));
      if (b == -2) {
        if (++foreign <= 10)
          examples << "  (" << x << ", " << y << "): primflow " << rgba(pixel(got, x, y))
                   << " is no ID colour, OSMesa triangle " << a << "\n";
        continue;
      }
      count_ref[a]++;
      count_got[b]++;
      covered_ref += a != pfdiff::kNoId;
      covered_got += b != pfdiff::kNoId;
      if (a != b && ++mismatches <= 20)
        examples << "  (" << x << ", " << y << ") centre (" << x + 0.5 << ", " << y + 0.5
                 << "): OSMesa triangle " << a << ", primflow triangle " << b
                 << " (-1 = not covered)\n";
    }
  }
  EXPECT_EQ(foreign, 0) << "pixels of colours that are no triangle's ID colour\n" << examples.str();
  EXPECT_EQ(mismatches, 0) << "pixels covered by a different triangle (or by none) than in OSMesa; "
                           << "covered pixels: OSMesa " << covered_ref << ", primflow " << covered_got
                           << "\n" << examples.str();
  for (int id = 0; id < triangles; ++id)
    EXPECT_EQ(count_got[id], count_ref[id]) << "pixels of triangle " << id;
  EXPECT_GT(covered_ref, min_covered) << "the reference drew (almost) nothing";
}

// Every pixel: each channel within `tolerance` of OSMesa's.
void expectSameColours(const Image& ref, const Image& got, int tolerance, const char* what) {
  int bad = 0, worst = 0;
  std::ostringstream examples;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const uint8_t* a = pixel(ref, x, y);
      const uint8_t* b = pixel(got, x, y);
      int d = 0;
      for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
      worst = std::max(worst, d);
      if (d > tolerance && ++bad <= 20)
        examples << "  (" << x << ", " << y << "): OSMesa " << rgba(a) << ", primflow " << rgba(b) << "\n";
    }
  }
  EXPECT_EQ(bad, 0) << what << ": pixels off by more than " << tolerance
                    << "/255 in a channel (largest difference " << worst << ")\n" << examples.str();
}

}  // namespace

namespace pfdiff {
void PrintTo(Scene s, std::ostream* os) { *os << sceneName(s); }  // test names in ctest
}  // namespace pfdiff

TEST(Differential, FanCoverageMatchesOsmesa) { expectSameCoverage(Scene::FanIds, pfdiff::kFanTriangles); }

TEST(Differential, MeshCoverageMatchesOsmesa) { expectSameCoverage(Scene::MeshIds, pfdiff::kMeshTriangles); }

// Pixels well outside the fan (centre farther than radius + 2 from the fan's centre) keep the
// clear colour in both; and the named functions of the brief give the same pixels.
TEST(Differential, OutsideTheFanStaysClear) {
  std::vector<uint8_t> ref = renderFanOsmesa(kSize, kSize);
  std::vector<uint8_t> got = renderFanPrimflow(kSize, kSize, 1);
  ASSERT_EQ(ref.size(), size_t(kSize) * kSize * 4);
  ASSERT_EQ(got.size(), ref.size());
  int outside = 0, not_clear_ref = 0, not_clear_got = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      double dx = x + 0.5 - 128.5, dy = y + 0.5 - 128.5;
      if (std::sqrt(dx * dx + dy * dy) <= 102.0) continue;
      ++outside;
      size_t i = (size_t(y) * kSize + x) * 4;
      not_clear_ref += !isClear(&ref[i]);
      if (!isClear(&got[i]) && ++not_clear_got <= 5)
        ADD_FAILURE() << "primflow drew outside the fan at (" << x << ", " << y << "): " << rgba(&got[i]);
    }
  }
  EXPECT_GT(outside, 20000);
  EXPECT_EQ(not_clear_ref, 0);
  EXPECT_EQ(not_clear_got, 0);
  // The four corners, explicitly.
  for (int corner : {0, kSize - 1, (kSize - 1) * kSize, kSize * kSize - 1})
    EXPECT_TRUE(isClear(&got[size_t(corner) * 4])) << "corner pixel " << corner;
}

// The showcase: 18,000 small perspective triangles with depth-tested intersections. Colours
// within 2/255 except where two surfaces meet at almost the same depth (an implementation's own
// rounding decides those ties: at most 1 pixel in 1000); depth within 2^-16 where both agree.
TEST(Differential, ShowcaseMatchesOsmesa) {
  Image ref = reference(Scene::Showcase);
  Image got = primflow(Scene::Showcase, 2);
  ASSERT_TRUE(ref.ok && got.ok);
  int off = 0, covered = 0, depth_bad = 0;
  double worst_depth = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const uint8_t* a = pixel(ref, x, y);
      const uint8_t* b = pixel(got, x, y);
      int d = 0;
      for (int k = 0; k < 4; ++k) d = std::max(d, std::abs(int(a[k]) - int(b[k])));
      if (d > 2) {
        ++off;
        continue;
      }
      size_t i = size_t(y) * kSize + x;
      if (ref.depth.empty() || got.depth.empty() || ref.depth[i] >= 1.0) continue;
      ++covered;
      double dz = std::abs(ref.depth[i] - got.depth[i]);
      worst_depth = std::max(worst_depth, dz);
      if (dz > 1.0 / 65536) ++depth_bad;
    }
  EXPECT_GT(covered, kSize * kSize / 3) << "the showcase should cover much of the image";
  EXPECT_LE(off, kSize * kSize / 1000) << "pixels off by more than 2/255";
  EXPECT_EQ(depth_bad, 0) << "depth off by more than 2^-16 (largest " << worst_depth << ")";
}

TEST(Differential, QuadMeshCoverageMatchesOsmesa) { expectSameCoverage(Scene::QuadMeshIds, pfdiff::kMeshQuads); }

// Every polygon mode of glBegin (each a primitive in primitives/triangles.pfl calling
// `triangles`): the same pixels, colours within 2/255 -- which holds only if each mode splits its
// polygons along the same diagonals as Mesa and keeps a vertex order that rounds alike.
class DifferentialModes : public ::testing::TestWithParam<Scene> {};

TEST_P(DifferentialModes, ImageMatchesOsmesa) {
  Image ref = reference(GetParam());
  Image got = primflow(GetParam(), 1);
  ASSERT_TRUE(ref.ok && got.ok);
  int drawn = 0;
  for (int i = 0; i < kSize * kSize; ++i) drawn += !isClear(&ref.rgba[size_t(i) * 4]);
  EXPECT_GT(drawn, 800) << "the reference drew (almost) nothing";
  expectSameColours(ref, got, 2, sceneName(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Modes, DifferentialModes,
                         ::testing::Values(Scene::StripGouraud, Scene::FanModeGouraud, Scene::QuadsGouraud,
                                           Scene::QuadStripGouraud, Scene::PolygonGouraud, Scene::PointsGouraud),
                         [](const ::testing::TestParamInfo<Scene>& info) { return sceneName(info.param); });

// Lines (primitives/lines.pfl): GL's diamond-exit rule. Expected deviation, with its reason:
// llvmpipe draws a line as a parallelogram with its own endpoint adjustments, not by the
// diamond rule, so the two disagree on a few pixels where a segment ends on the corner of a
// pixel's diamond -- common here, since every vertex is on the quarter-pixel grid (measured:
// 3 of 3750, 4 of 1620, 2 of 2037 pixels). Allowed: at most 1% of the drawn pixels covered
// differently; where both draw, colours within 2/255.
class DifferentialLines : public ::testing::TestWithParam<Scene> {};

TEST_P(DifferentialLines, CoverageWithinOnePercentAndColoursMatch) {
  Image ref = reference(GetParam());
  Image got = primflow(GetParam(), 1);
  ASSERT_TRUE(ref.ok && got.ok);
  int drawn = 0, differ = 0, colour_bad = 0;
  for (int i = 0; i < kSize * kSize; ++i) {
    const uint8_t* a = &ref.rgba[size_t(i) * 4];
    const uint8_t* b = &got.rgba[size_t(i) * 4];
    drawn += !isClear(a);
    if (isClear(a) != isClear(b)) {
      ++differ;
    } else if (!isClear(a)) {
      int d = 0;
      for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
      colour_bad += d > 2;
    }
  }
  EXPECT_GT(drawn, 1000) << "the reference drew (almost) nothing";
  EXPECT_LE(differ, drawn / 100) << "pixels drawn by one implementation only, of " << drawn;
  EXPECT_EQ(colour_bad, 0) << "pixels both drew, off by more than 2/255";
}

INSTANTIATE_TEST_SUITE_P(Lines, DifferentialLines,
                         ::testing::Values(Scene::LinesStar, Scene::LineStripGouraud, Scene::LineLoopGouraud),
                         [](const ::testing::TestParamInfo<Scene>& info) { return sceneName(info.param); });

// Face culling and winding on the ID fan, whose odd triangles are clockwise: exactly the
// pixels of the triangles OSMesa keeps.
TEST(Differential, CullBackMatchesOsmesa) { expectSameCoverage(Scene::CullBack, pfdiff::kFanTriangles, kSize * kSize / 8); }
TEST(Differential, CullFrontWithClockwiseFrontMatchesOsmesa) {
  expectSameCoverage(Scene::CullFrontCw, pfdiff::kFanTriangles, kSize * kSize / 8);
}
TEST(Differential, CullFrontAndBackDrawsNothing) {
  Image got = primflow(Scene::CullBoth, 1);
  ASSERT_TRUE(got.ok);
  Image ref = reference(Scene::CullBoth);
  ASSERT_TRUE(ref.ok);
  expectSameColours(ref, got, 0, "GL_FRONT_AND_BACK");
  for (int i = 0; i < kSize * kSize; ++i) ASSERT_TRUE(isClear(&got.rgba[size_t(i) * 4])) << "pixel " << i;
}

// Flat shading: every polygon and line mode takes GL's provoking vertex's colour (the last of a
// triangle, of a quad and of a segment; the first of a polygon) -- exact, but for lines'
// expected coverage deviation (see DifferentialLines), so colours where both drew; and colour
// masks on clears and drawing.
TEST(Differential, FlatShadingTakesTheProvokingVertex) {
  Image ref = reference(Scene::FlatModes);
  Image got = primflow(Scene::FlatModes, 1);
  ASSERT_TRUE(ref.ok && got.ok);
  int both = 0, wrong = 0, only_one = 0;
  for (int i = 0; i < kSize * kSize; ++i) {
    const uint8_t* a = &ref.rgba[size_t(i) * 4];
    const uint8_t* b = &got.rgba[size_t(i) * 4];
    if (isClear(a) != isClear(b)) {
      ++only_one;
      continue;
    }
    if (isClear(a)) continue;
    ++both;
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
    if (d > 1 && ++wrong <= 10)
      ADD_FAILURE() << "pixel (" << i % kSize << ", " << i / kSize << "): OSMesa " << rgba(a) << ", primflow " << rgba(b);
  }
  EXPECT_GT(both, 15000);
  EXPECT_EQ(wrong, 0);
  EXPECT_LE(only_one, 10) << "pixels covered by one only (lines' ends)";
}

TEST(Differential, ColorMasksMatchOsmesa) {
  Image ref = reference(Scene::ColorMasks);
  Image got = primflow(Scene::ColorMasks, 1);
  ASSERT_TRUE(ref.ok && got.ok);
  expectSameColours(ref, got, 2, "colour masks");
}

// Perspective, nested transforms through every matrix command, depth-tested cubes: colours
// within 2/255 except at most 1 pixel in 1000 (edge pixels the two decide differently after
// transforming in their own rounding).
TEST(Differential, MatrixOperationsMatchOsmesa) {
  Image ref = reference(Scene::MatrixOps);
  Image got = primflow(Scene::MatrixOps, 1);
  ASSERT_TRUE(ref.ok && got.ok);
  int off = 0, drawn = 0;
  for (int i = 0; i < kSize * kSize; ++i) {
    const uint8_t* a = &ref.rgba[size_t(i) * 4];
    const uint8_t* b = &got.rgba[size_t(i) * 4];
    drawn += !isClear(a);
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
    off += d > 2;
  }
  EXPECT_GT(drawn, kSize * kSize / 10);
  EXPECT_LE(off, kSize * kSize / 1000);
}

// Triangles from in front of the eye to behind it (w < 0), both windings, back faces culled.
TEST(Differential, NearPlaneCrossingTrianglesCullLikeOsmesa) {
  Image ref = reference(Scene::NearClipCull);
  Image got = primflow(Scene::NearClipCull, 1);
  ASSERT_TRUE(ref.ok && got.ok);
  int off = 0, drawn = 0;
  for (int i = 0; i < kSize * kSize; ++i) {
    const uint8_t* a = &ref.rgba[size_t(i) * 4];
    const uint8_t* b = &got.rgba[size_t(i) * 4];
    drawn += !isClear(a);
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
    off += d > 2;
  }
  EXPECT_GT(drawn, kSize * kSize / 20);
  EXPECT_LE(off, kSize * kSize / 1000);
}

// Vertex arrays: the ID mesh through glDrawElements covers exactly what OSMesa covers with the
// same arrays, and the same as immediate mode; the interleaved strip's colours within 2/255.
TEST(Differential, VertexArraysMatchOsmesaAndImmediateMode) {
  Image ref = reference(Scene::VertexArrays);
  Image got = primflow(Scene::VertexArrays, 1);
  Image immediate = primflow(Scene::MeshIds, 1);
  ASSERT_TRUE(ref.ok && got.ok && immediate.ok);
  expectSameColours(ref, got, 2, "vertex arrays");
  int mesh_pixels = 0;
  for (int y = 0; y < 236; ++y)  // below the strip: the mesh alone
    for (int x = 0; x < kSize; ++x) {
      EXPECT_EQ(rgba(pixel(got, x, y)), rgba(pixel(immediate, x, y))) << "(" << x << ", " << y << ")";
      mesh_pixels += !isClear(pixel(got, x, y));
    }
  EXPECT_GT(mesh_pixels, 40000);
}

// GL lighting, per vertex as GL does it, one feature per scene: colours within 2/255 but for at
// most 1 pixel in 1000 (silhouette pixels decided differently after the perspective transform).
class DifferentialLighting : public ::testing::TestWithParam<Scene> {};

TEST_P(DifferentialLighting, ImageMatchesOsmesa) {
  Image ref = reference(GetParam());
  Image got = primflow(GetParam(), 1);
  ASSERT_TRUE(ref.ok && got.ok);
  int off = 0, drawn = 0, worst = 0;
  std::ostringstream examples;
  for (int i = 0; i < kSize * kSize; ++i) {
    const uint8_t* a = &ref.rgba[size_t(i) * 4];
    const uint8_t* b = &got.rgba[size_t(i) * 4];
    drawn += !isClear(a);
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
    if (!isClear(a) && !isClear(b)) worst = std::max(worst, d);
    if (d > 2 && ++off <= 10) examples << "  (" << i % kSize << ", " << i / kSize << "): OSMesa " << rgba(a) << ", primflow " << rgba(b) << "\n";
  }
  EXPECT_GT(drawn, kSize * kSize / 8);
  EXPECT_LE(off, kSize * kSize / 1000) << "largest difference where both drew: " << worst << "\n" << examples.str();
}

INSTANTIATE_TEST_SUITE_P(Lighting, DifferentialLighting,
                         ::testing::Values(Scene::LitDirectional, Scene::LitPointLights, Scene::LitSpot, Scene::LitTwoSide,
                                           Scene::LitLocalViewer, Scene::LitNormalize, Scene::LitColorMaterial),
                         [](const ::testing::TestParamInfo<Scene>& info) { return sceneName(info.param); });

TEST(Differential, GouraudColoursWithinTwoLevels) {
  Image ref = reference(Scene::FanGouraud);
  Image got = primflow(Scene::FanGouraud, 1);
  ASSERT_TRUE(ref.ok && got.ok);
  expectSameColours(ref, got, 2, "Gouraud fan");
}

class DifferentialDepth : public ::testing::TestWithParam<Scene> {};

TEST_P(DifferentialDepth, ImageMatchesOsmesa) {
  Image ref = reference(GetParam());
  Image got = primflow(GetParam(), 1);
  ASSERT_TRUE(ref.ok && got.ok);
  expectSameColours(ref, got, 0, sceneName(GetParam()));
}

TEST_P(DifferentialDepth, DepthBufferMatchesOsmesa) {
  Image ref = reference(GetParam());
  Image got = primflow(GetParam(), 1);
  ASSERT_TRUE(ref.ok && got.ok);
  ASSERT_EQ(ref.depth.size(), size_t(kSize) * kSize) << "OSMesa's depth buffer could not be read";
  ASSERT_EQ(got.depth.size(), size_t(kSize) * kSize) << "pfGetDepthBuffer failed";
  // OSMesa keeps 24-bit integers, rounded to nearest; primflow floats.
  const double tolerance = 1.0 / (1 << 20);
  int bad = 0;
  double worst = 0;
  std::ostringstream examples;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      size_t i = size_t(y) * kSize + x;
      double d = std::abs(ref.depth[i] - got.depth[i]);
      worst = std::max(worst, d);
      if (d > tolerance && ++bad <= 20)
        examples << "  (" << x << ", " << y << "): OSMesa " << ref.depth[i] << ", primflow "
                 << got.depth[i] << "\n";
    }
  }
  EXPECT_EQ(bad, 0) << "depth values off by more than 2^-20 (largest difference " << worst << ")\n"
                    << examples.str();
}

// Both drawing orders give the same picture.
TEST(Differential, DepthOrderDoesNotMatter) {
  Image a = primflow(Scene::DepthFarThenNear, 1);
  Image b = primflow(Scene::DepthNearThenFar, 1);
  ASSERT_TRUE(a.ok && b.ok);
  expectSameColours(a, b, 0, "far-then-near against near-then-far");
}

INSTANTIATE_TEST_SUITE_P(Orders, DifferentialDepth,
                         ::testing::Values(Scene::DepthFarThenNear, Scene::DepthNearThenFar, Scene::DepthNever,
                                           Scene::DepthLess, Scene::DepthEqual, Scene::DepthLequal,
                                           Scene::DepthGreater, Scene::DepthNotequal, Scene::DepthGequal,
                                           Scene::DepthAlways, Scene::DepthMaskOff, Scene::DepthRangeNarrow),
                         [](const ::testing::TestParamInfo<Scene>& info) { return sceneName(info.param); });

class DifferentialThreads : public ::testing::TestWithParam<Scene> {};

TEST_P(DifferentialThreads, ByteIdenticalForAnyThreadCount) {
  Image one = primflow(GetParam(), 1);
  ASSERT_TRUE(one.ok);
  for (int threads : {2, 3, 8}) {
    Image many = primflow(GetParam(), threads);
    ASSERT_TRUE(many.ok);
    size_t differing = 0;
    for (size_t i = 0; i < one.rgba.size(); ++i) differing += one.rgba[i] != many.rgba[i];
    EXPECT_EQ(differing, 0u) << threads << " threads: bytes differing from 1 thread";
    EXPECT_TRUE(one.depth == many.depth) << threads << " threads: the depth buffer differs from 1 thread";
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, DifferentialThreads,
                         ::testing::Values(Scene::FanIds, Scene::MeshIds, Scene::FanGouraud,
                                           Scene::DepthFarThenNear, Scene::DepthNearThenFar, Scene::Showcase,
                                           Scene::StripGouraud, Scene::QuadsGouraud, Scene::PolygonGouraud),
                         [](const ::testing::TestParamInfo<Scene>& info) { return sceneName(info.param); });
