// Coarse depth culling (raster/coarse_depth.h): the verdict of a depth range against a block's
// stored range is checked against every pair of depths it covers, a tile's block ranges
// against a brute-force min/max of the buffer, and whole frames of the primitives that state
// depth_bound() -- sphere impostors, ray-cast spheres, triangles -- against the same frames with
// culling off: identical to the bit, under each depth function, a reversed depth range and the
// depth test off, with blocks culled where culling can apply and none where it cannot.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "rendered_frame.h"
#include "raster/coarse_depth.h"

namespace {

using pf::DepthFunc;

bool passes(DepthFunc f, float z, float d) {
  switch (f) {
    case DepthFunc::Never: return false;
    case DepthFunc::Less: return z < d;
    case DepthFunc::LessEqual: return z <= d;
    case DepthFunc::Greater: return z > d;
    case DepthFunc::GreaterEqual: return z >= d;
    case DepthFunc::Equal: return z == d;
    case DepthFunc::NotEqual: return z != d;
    case DepthFunc::Always: return true;
  }
  return true;
}

constexpr DepthFunc kFuncs[] = {DepthFunc::Never,   DepthFunc::Less,     DepthFunc::Equal,        DepthFunc::LessEqual,
                                DepthFunc::Greater, DepthFunc::NotEqual, DepthFunc::GreaterEqual, DepthFunc::Always};

}  // namespace

TEST(CoarseDepth, RangeVerdictIsExactlyWhetherNoPairPasses) {
  // Ranges with ends on a grid: every value of the grid inside both ranges is a pair to try,
  // and the ranges' ends are among them, so "no pair passes" is decided exactly -- except for
  // NotEqual, where the verdict never claims anything.
  const float grid[] = {-0.0f, 0.0f, 0.25f, 0.5f, 0.75f, 1.0f};
  int claims = 0;
  for (DepthFunc f : kFuncs)
    for (float zmin : grid)
      for (float zmax : grid)
        for (float dmin : grid)
          for (float dmax : grid) {
            if (zmax < zmin || dmax < dmin) continue;
            bool some_pass = false;
            for (float z : grid)
              for (float d : grid)
                if (z >= zmin && z <= zmax && d >= dmin && d <= dmax) some_pass = some_pass || passes(f, z, d);
            const bool fails = pf::depthRangeFails(f, zmin, zmax, dmin, dmax);
            if (fails) ++claims;
            if (f == DepthFunc::NotEqual || f == DepthFunc::Always)
              EXPECT_FALSE(fails);
            else
              EXPECT_EQ(fails, !some_pass) << static_cast<int>(f) << " z [" << zmin << ", " << zmax << "] d [" << dmin
                                           << ", " << dmax << "]";
          }
  EXPECT_GT(claims, 100);
  // NaN ends claim nothing.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (DepthFunc f : {DepthFunc::Less, DepthFunc::LessEqual, DepthFunc::Greater, DepthFunc::GreaterEqual,
                      DepthFunc::Equal}) {
    EXPECT_FALSE(pf::depthRangeFails(f, nan, nan, 0.5f, 0.5f));
    EXPECT_FALSE(pf::depthRangeFails(f, 0.5f, 0.5f, nan, nan));
  }
}

// depthPassMask (four depths at a time where SSE2 is, one at a time at a row's end) is bit i
// = !depthRangeFails(func, zmin, zmax, d[i], d[i]), for every row length up to 64, stored
// depths at, between and outside the range's ends, NaN and infinities among them.
TEST(CoarseDepth, PassMaskIsTheRangeVerdictPerPixel) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const float values[] = {-0.0f, 0.0f, 0.25f, 0.3f, 0.5f, 0.7f, 0.75f, 1.0f, nan, inf, -inf};
  std::mt19937 rng(11);
  std::vector<float> d(64);
  int passed = 0, failed = 0;
  for (DepthFunc f : kFuncs)
    for (const auto& [zmin, zmax] : {std::pair{0.25f, 0.75f}, std::pair{0.5f, 0.5f}, std::pair{nan, nan},
                                     std::pair{0.0f, 1.0f}, std::pair{0.75f, 0.25f}})
      for (int n = 0; n <= 64; ++n)
        for (int trial = 0; trial < 3; ++trial) {
          for (float& v : d) v = values[rng() % std::size(values)];
          const uint64_t m = pf::depthPassMask(f, zmin, zmax, d.data(), n);
          for (int i = 0; i < 64; ++i) {
            const bool want = i < n && !pf::depthRangeFails(f, zmin, zmax, d[i], d[i]);
            ASSERT_EQ(((m >> i) & 1u) != 0, want) << static_cast<int>(f) << " [" << zmin << ", " << zmax << "] n "
                                                  << n << " i " << i << " d " << d[i];
            (want ? passed : failed) += i < n;
          }
        }
  EXPECT_GT(passed, 1000);
  EXPECT_GT(failed, 1000);
}

TEST(CoarseDepth, BlockRangesFollowTheBufferAsItIsWritten) {
  // A 100 x 70 buffer: the tile at (64, 64) is cut to 36 x 6 pixels; the one at (0, 0) is whole.
  constexpr int kW = 100, kH = 70;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> depth(static_cast<size_t>(kW) * kH);
  for (float& d : depth) d = u(rng);
  struct Tile {
    int x0, y0, w, h;
  };
  for (const Tile t : {Tile{0, 0, 64, 64}, Tile{64, 64, 36, 6}, Tile{64, 0, 36, 64}}) {
    pf::CoarseDepth coarse;
    coarse.startTile(depth.data(), kW, t.x0, t.y0, t.w, t.h, false);
    for (int round = 0; round < 3; ++round) {
      for (int by = 0; by * 8 < t.h; ++by)
        for (int bx = 0; bx * 8 < t.w; ++bx) {
          float lo = 2, hi = -1;
          for (int y = by * 8; y < std::min(by * 8 + 8, t.h); ++y)
            for (int x = bx * 8; x < std::min(bx * 8 + 8, t.w); ++x) {
              const float d = depth[static_cast<size_t>(t.y0 + y) * kW + t.x0 + x];
              lo = std::min(lo, d);
              hi = std::max(hi, d);
            }
          // The stored range is exactly [lo, hi]: Less culls [z, z] exactly when z >= hi,
          // Greater exactly when z <= lo.
          EXPECT_TRUE(coarse.fails(DepthFunc::Less, hi, hi, bx, by));
          EXPECT_FALSE(coarse.fails(DepthFunc::Less, std::nextafter(hi, 0.0f), hi, bx, by));
          EXPECT_TRUE(coarse.fails(DepthFunc::Greater, lo, lo, bx, by));
          EXPECT_FALSE(coarse.fails(DepthFunc::Greater, lo, std::nextafter(lo, 1.0f), bx, by));
        }
      // Write a random rectangle of the tile, nearer, and say so; the ranges must follow.
      const int px0 = static_cast<int>(u(rng) * (t.w - 1)), py0 = static_cast<int>(u(rng) * (t.h - 1));
      const int px1 = px0 + 1 + static_cast<int>(u(rng) * (t.w - px0 - 1));
      const int py1 = py0 + 1 + static_cast<int>(u(rng) * (t.h - py0 - 1));
      for (int y = py0; y < py1; ++y)
        for (int x = px0; x < px1; ++x) depth[static_cast<size_t>(t.y0 + y) * kW + t.x0 + x] *= 0.5f;
      coarse.written(px0, py0, px1, py1);
    }
    // A NaN under a block: no verdict there.
    depth[static_cast<size_t>(t.y0 + 1) * kW + t.x0 + 2] = std::numeric_limits<float>::quiet_NaN();
    coarse.written(2, 1, 3, 2);
    EXPECT_FALSE(coarse.fails(DepthFunc::Less, 5.0f, 5.0f, 0, 0));
    EXPECT_FALSE(coarse.fails(DepthFunc::Greater, -5.0f, -5.0f, 0, 0));
  }
}

TEST(CoarseDepth, AClearedTileIsMeasuredOnlyWhereEveryPixelWasDrawn) {
  // After a clear to the far plane, a block with an undrawn pixel keeps that depth: no verdict
  // without measuring. Once every pixel of it (those inside the framebuffer: this tile is cut to
  // 20 x 12) is marked drawn, it is measured.
  constexpr int kW = 84, kH = 76;
  std::vector<float> depth(static_cast<size_t>(kW) * kH, 1.0f);
  pf::CoarseDepth coarse;
  coarse.startTile(depth.data(), kW, 64, 64, 20, 12, true);
  uint64_t* committed = coarse.committedPixels();
  // Draw block (1, 0) (pixels 8..15 x 0..7 of the tile) nearer, all but one pixel.
  for (int y = 0; y < 8; ++y)
    for (int x = 8; x < 16; ++x) depth[static_cast<size_t>(64 + y) * kW + 64 + x] = 0.25f;
  committed[1] = ~0ull & ~(1ull << 9);
  coarse.written(8, 0, 16, 8);
  EXPECT_FALSE(coarse.fails(DepthFunc::Less, 0.5f, 0.5f, 1, 0));
  committed[1] = ~0ull;
  EXPECT_TRUE(coarse.fails(DepthFunc::Less, 0.5f, 0.5f, 1, 0));
  // Block (2, 1) holds pixels 16..19 x 8..11 only: those four columns and rows are all it needs.
  for (int y = 8; y < 12; ++y)
    for (int x = 16; x < 20; ++x) depth[static_cast<size_t>(64 + y) * kW + 64 + x] = 0.25f;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) committed[1 * pf::CoarseDepth::kBlocksPerSide + 2] |= 1ull << (y * 8 + x);
  coarse.written(16, 8, 20, 12);
  EXPECT_TRUE(coarse.fails(DepthFunc::Less, 0.5f, 0.5f, 2, 1));
  // Block (0, 0), never drawn: no verdict, even for a range behind the clear.
  EXPECT_FALSE(coarse.fails(DepthFunc::Less, 2.0f, 2.0f, 0, 0));
}

namespace {

constexpr int kSize = 160;

using Frame = pf::test::RenderedFrame;

// A dense cloud of lit sphere impostors over a few triangles, two frames (the second with the
// first's depth left in place, so whole instances find their blocks already nearer), drawn with
// `func` (switched to `second_func`, if it is not 0, half-way through each frame's spheres),
// `clear_z` and glDepthRange(near, far).
// `primitive` draws the spheres; with `redraw_equal` the second frame draws the first's spheres
// again under GL_EQUAL, in other colours, so each pixel's depth must lie in its bound.
Frame drawCloud(bool cull, GLenum func, double clear_z, double near, double far, bool depth_test = true,
                GLenum second_func = 0, int size = kSize, const char* primitive = "sphere_impostors",
                bool redraw_equal = false) {
  return pf::test::renderFrame(size, 2, [&](pf::Renderer& r) { r.setDepthCulling(cull); }, [&] {
    pfglMatrixMode(GL_PROJECTION);
    pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 12.0);
    pfglMatrixMode(GL_MODELVIEW);
    pfglTranslated(0.0, 0.0, -5.0);
    if (depth_test) pfglEnable(GL_DEPTH_TEST);
    pfglDepthFunc(func);
    pfglDepthRange(near, far);
    pfglClearDepth(clear_z);
    pfglEnable(GL_LIGHTING);
    pfglEnable(GL_LIGHT0);
    pfglEnable(GL_COLOR_MATERIAL);
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const GLuint centre = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
    const GLenum impostors = pfglGetPrimitiveEXT(primitive);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> pos(-1.6f, 1.6f), col(0.0f, 1.0f);
    for (int frame = 0; frame < 2; ++frame) {
      if (frame == 1 && redraw_equal) {
        rng.seed(3);
        pfglDepthFunc(GL_EQUAL);
      }
      pfglBegin(GL_TRIANGLES);
      pfglColor3f(0.3f, 0.3f, 0.9f);
      pfglNormal3f(0, 0, 1);
      pfglVertex3f(-2, -2, -0.5f);
      pfglVertex3f(2, -2, 0.5f);
      pfglVertex3f(0, 2, 0.0f);
      pfglEnd();
      pfglBegin(impostors);
      for (int i = 0; i < 3000; ++i) {
        if (i == 1500 && second_func) {
          pfglEnd();
          pfglDepthFunc(second_func);
          pfglBegin(impostors);
        }
        const float r = col(rng), g = col(rng), b = col(rng);
        if (frame == 1 && redraw_equal)
          pfglColor3f(1 - r, 1 - g, 1 - b);
        else
          pfglColor3f(r, g, b);
        pfglRastParamfEXT(radius, 0.05f + 0.15f * col(rng));
        pfglRastParam3fEXT(centre, pos(rng), pos(rng), pos(rng));
        pfglSequencePointEXT();
      }
      pfglEnd();
      pfglFinish();
      pfglDepthFunc(func);
    }
  });
}

void expectSameImages(const Frame& culled, const Frame& plain) {
  EXPECT_EQ(plain.stats.blocks_depth_culled, 0u);
  EXPECT_EQ(plain.stats.pixels_depth_culled, 0u);
  pf::test::expectIdenticalFrames(culled, plain);
}

}  // namespace

TEST(CoarseDepth, ImpostorFramesAreTheSameToTheBitWithCullingOff) {
  struct Case {
    GLenum func;
    double clear_z, near, far;
  };
  for (const Case k : {Case{GL_LESS, 1.0, 0.0, 1.0}, Case{GL_LEQUAL, 1.0, 0.0, 1.0}, Case{GL_GREATER, 0.0, 1.0, 0.0},
                       Case{GL_GEQUAL, 0.0, 1.0, 0.0}, Case{GL_LESS, 1.0, 0.2, 0.7}}) {
    SCOPED_TRACE(::testing::Message() << "func 0x" << std::hex << k.func << std::dec << " range " << k.near << ".."
                                      << k.far);
    const Frame culled = drawCloud(true, k.func, k.clear_z, k.near, k.far);
    const Frame plain = drawCloud(false, k.func, k.clear_z, k.near, k.far);
    expectSameImages(culled, plain);
    // A dense cloud: most of its blocks are behind what is already drawn; so are many pixels
    // of the small spheres that run packed.
    EXPECT_GT(culled.stats.blocks_depth_culled, culled.stats.blocks_run / 4);
    EXPECT_GT(culled.stats.pixels_depth_culled, 1000u);
    EXPECT_LT(culled.stats.blocks_run, plain.stats.blocks_run);
  }
}

TEST(CoarseDepth, RayCastSphereFramesAreTheSameToTheBitWithCullingOff) {
  // `sphere` (primitives/sphere.pfl) bounds its depths by its object-space cube's: redrawn under
  // GL_EQUAL, a pixel whose depth fell outside would be lost.
  for (const bool redraw : {false, true})
    for (const auto& [func, clear_z, near, far] :
         {std::tuple{GL_LESS, 1.0, 0.0, 1.0}, std::tuple{GL_GREATER, 0.0, 1.0, 0.0}, std::tuple{GL_LEQUAL, 1.0, 0.2, 0.7}}) {
      SCOPED_TRACE(::testing::Message() << "func 0x" << std::hex << func << std::dec << " range " << near << ".." << far
                                        << (redraw ? ", redrawn under GL_EQUAL" : ""));
      const Frame culled = drawCloud(true, func, clear_z, near, far, true, 0, kSize, "sphere", redraw);
      const Frame plain = drawCloud(false, func, clear_z, near, far, true, 0, kSize, "sphere", redraw);
      expectSameImages(culled, plain);
      EXPECT_GT(culled.stats.blocks_depth_culled, culled.stats.blocks_run / 4);
      EXPECT_GT(culled.stats.pixels_depth_culled, 1000u);
    }
}

TEST(CoarseDepth, BlockRangesFollowWhatWasDrawnWhenTheDepthFunctionTurns) {
  // Under GL_LESS the stored depths only fall, so a block's farthest depth measured before
  // draws stays a safe (if loose) bound for GL_LESS; its nearest does not, and GL_GREATER
  // reads that one: a block range not measured again after the first spheres' writes would
  // cull the later spheres behind them.
  const Frame culled = drawCloud(true, GL_LESS, 1.0, 0.0, 1.0, true, GL_GREATER);
  const Frame plain = drawCloud(false, GL_LESS, 1.0, 0.0, 1.0, true, GL_GREATER);
  expectSameImages(culled, plain);
  EXPECT_GT(culled.stats.blocks_depth_culled, 0u);
}

TEST(CoarseDepth, AFramebufferCutMidBlockIsCulledExactly) {
  // 157 pixels: the right and top tiles end inside a block, whose rows the per-pixel tests must
  // read only as far as the framebuffer (ASan watches the last row).
  const Frame culled = drawCloud(true, GL_LESS, 1.0, 0.0, 1.0, true, 0, 157);
  const Frame plain = drawCloud(false, GL_LESS, 1.0, 0.0, 1.0, true, 0, 157);
  expectSameImages(culled, plain);
  EXPECT_GT(culled.stats.blocks_depth_culled, 0u);
}

TEST(CoarseDepth, NothingIsCulledWhereTheDepthTestCannotRejectARange) {
  // GL_ALWAYS and GL_NOTEQUAL pass somewhere in any range; with the depth test off nothing is
  // tested at all.
  for (GLenum func : {GL_ALWAYS, GL_NOTEQUAL}) {
    const Frame f = drawCloud(true, func, 1.0, 0.0, 1.0);
    EXPECT_EQ(f.stats.blocks_depth_culled, 0u);
    expectSameImages(f, drawCloud(false, func, 1.0, 0.0, 1.0));
  }
  const Frame off = drawCloud(true, GL_LESS, 1.0, 0.0, 1.0, false);
  EXPECT_EQ(off.stats.blocks_depth_culled, 0u);
  // GL_NEVER: nothing passes, so every block of every bounded instance is culled, and nothing
  // of the impostors is drawn.
  const Frame never = drawCloud(true, GL_NEVER, 1.0, 0.0, 1.0);
  EXPECT_GT(never.stats.blocks_depth_culled, 0u);
  expectSameImages(never, drawCloud(false, GL_NEVER, 1.0, 0.0, 1.0));
}

// Triangles state depth_bound() too (primitives/triangles.pfl: the z plane at the snapped
// vertices, widened past its rounding; some vertices a hair off pixel centres, snapped onto
// them). Drawn twice, the second pass with GL_EQUAL in another
// colour, every pixel of the first is redrawn only if its depth lies in the bound: a small
// triangle's pixels are each tested against the bound (packed lanes), so a bound that misses
// one pixel's depth by an ulp loses that pixel.
namespace {

enum class Projection { Ortho, Frustum };

Frame drawTriangles(bool cull, Projection projection, GLenum func, double clear_z, double near, double far,
                    unsigned seed) {
  return pf::test::renderFrame(kSize, 2, [&](pf::Renderer& r) { r.setDepthCulling(cull); }, [&] {
    pfglMatrixMode(GL_PROJECTION);
    if (projection == Projection::Ortho)
      pfglOrtho(-1, 1, -1, 1, -1, 1);
    else
      pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 12.0);
    pfglMatrixMode(GL_MODELVIEW);
    if (projection == Projection::Frustum) pfglTranslated(0.0, 0.0, -3.0);
    pfglEnable(GL_DEPTH_TEST);
    pfglDepthRange(near, far);
    pfglClearDepth(clear_z);
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    // Positions in normalised units: some on pixel centres (each pixel 2 / kSize wide), sizes
    // from a pixel to a third of the frame, depths spread from flat to as steep as the view
    // volume allows across a few pixels.
    struct Tri {
      float v[3][3];
    };
    std::vector<Tri> tris;
    const float pixel = 2.0f / kSize;
    for (int i = 0; i < 1500; ++i) {
      const float size = i % 3 == 0 ? pixel * (1 + 3 * u(rng)) : i % 3 == 1 ? pixel * (5 + 40 * u(rng)) : 0.7f * u(rng);
      const float cx = 2 * u(rng) - 1, cy = 2 * u(rng) - 1, cz = 1.6f * u(rng) - 0.8f;
      const float slope = i % 4 == 0 ? 0.0f : (u(rng) - 0.5f) * (i % 4 == 1 ? 0.1f : 2.0f) / size;
      Tri t;
      for (int k = 0; k < 3; ++k) {
        float x = cx + size * (u(rng) - 0.5f), y = cy + size * (u(rng) - 0.5f);
        if (i % 5 == 0) {  // within 1/1024 pixel of a pixel centre: snapped onto it
          const float off = (u(rng) - 0.5f) * pixel / 512;
          x = (std::floor((x + 1) / pixel) + 0.5f) * pixel - 1 + off;
          y = (std::floor((y + 1) / pixel) + 0.5f) * pixel - 1 - off;
        }
        t.v[k][0] = x;
        t.v[k][1] = y;
        t.v[k][2] = std::clamp(cz + slope * (x - cx) * (k == 2 ? -1.0f : 1.0f), -0.99f, 0.99f);
      }
      tris.push_back(t);
    }
    for (int pass = 0; pass < 2; ++pass) {
      pfglDepthFunc(pass == 0 ? func : GL_EQUAL);
      pfglBegin(GL_TRIANGLES);
      for (const Tri& t : tris) {
        pfglColor3f(u(rng), u(rng), u(rng));
        for (const auto& p : t.v) pfglVertex3f(p[0], p[1], p[2]);
      }
      pfglEnd();
      pfglFinish();
    }
  });
}

}  // namespace

TEST(CoarseDepth, TriangleFramesAreTheSameToTheBitWithCullingOff) {
  struct Case {
    Projection projection;
    GLenum func;
    double clear_z, near, far;
  };
  unsigned seed = 1;
  for (const Case k : {Case{Projection::Ortho, GL_LESS, 1.0, 0.0, 1.0}, Case{Projection::Frustum, GL_LESS, 1.0, 0.0, 1.0},
                       Case{Projection::Ortho, GL_LEQUAL, 1.0, 0.0, 1.0}, Case{Projection::Ortho, GL_GREATER, 0.0, 1.0, 0.0},
                       Case{Projection::Frustum, GL_GEQUAL, 0.0, 1.0, 0.0}, Case{Projection::Frustum, GL_LESS, 1.0, 0.2, 0.7}}) {
    SCOPED_TRACE(::testing::Message() << "projection " << static_cast<int>(k.projection) << " func 0x" << std::hex
                                      << k.func << std::dec << " range " << k.near << ".." << k.far);
    const Frame culled = drawTriangles(true, k.projection, k.func, k.clear_z, k.near, k.far, seed);
    const Frame plain = drawTriangles(false, k.projection, k.func, k.clear_z, k.near, k.far, seed);
    ++seed;
    expectSameImages(culled, plain);
    EXPECT_GT(culled.stats.blocks_depth_culled, 0u);
    EXPECT_GT(culled.stats.pixels_depth_culled, 0u);
    EXPECT_LT(culled.stats.blocks_run, plain.stats.blocks_run);
  }
}
