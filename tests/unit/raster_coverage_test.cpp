// Coverage of the triangles primitive against an exact reference, and determinism across
// thread counts. The reference decides each pixel centre in double precision with GL's rule
// (inside, or on a left or bottom edge); vertices sit on a 1/4-pixel grid under an
// orthographic projection onto the pixel grid, where that double computation is exact.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace {

struct Tri {
  std::array<double, 6> v;  // x0 y0 x1 y1 x2 y2 in window coordinates
};

// Does the triangle cover the pixel centre (px, py) by GL's rule? Exact for grid vertices.
bool covers(const Tri& t, double px, double py) {
  double x[3] = {t.v[0], t.v[2], t.v[4]}, y[3] = {t.v[1], t.v[3], t.v[5]};
  double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
  if (area == 0) return false;
  double s = area > 0 ? 1 : -1;
  for (int i = 0; i < 3; ++i) {
    int j = (i + 1) % 3;
    // Edge from vertex i to j, with the inside positive.
    double a = -(y[j] - y[i]) * s, b = (x[j] - x[i]) * s;
    double e = a * (px - x[i]) + b * (py - y[i]);
    if (e < 0) return false;
    if (e == 0 && !(a > 0 || (a == 0 && b > 0))) return false;
  }
  return true;
}

double snap(double v) { return std::round(v * 4.0) / 4.0; }

// Draws each triangle with a colour encoding its index + 1 (R = low byte, G = high byte).
std::vector<unsigned char> drawIds(const std::vector<Tri>& tris, int w, int h, int threads) {
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  std::vector<unsigned char> px(static_cast<size_t>(w) * h * 4);
  pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, w, h);
  pfglMatrixMode(GL_PROJECTION);
  pfglLoadIdentity();
  pfglOrtho(0, w, 0, h, -1, 1);
  pfglMatrixMode(GL_MODELVIEW);
  pfglLoadIdentity();
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglBegin(GL_TRIANGLES);
  for (size_t i = 0; i < tris.size(); ++i) {
    unsigned id = static_cast<unsigned>(i + 1);
    pfglColor4f((id & 255) / 255.0f, ((id >> 8) & 255) / 255.0f, 0.0f, 1.0f);
    for (int k = 0; k < 3; ++k) pfglVertex3f(static_cast<float>(tris[i].v[2 * k]), static_cast<float>(tris[i].v[2 * k + 1]), 0.0f);
  }
  pfglEnd();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  return px;
}

// A fan of n slivers around (cx, cy), vertices on the 1/4 grid; consecutive triangles share edges.
std::vector<Tri> fan(double cx, double cy, double r, int n) {
  std::vector<Tri> out;
  for (int i = 0; i < n; ++i) {
    double a0 = 2 * M_PI * i / n, a1 = 2 * M_PI * (i + 1) / n;
    out.push_back({{cx, cy, snap(cx + r * std::cos(a0)), snap(cy + r * std::sin(a0)),
                    snap(cx + r * std::cos(a1)), snap(cy + r * std::sin(a1))}});
  }
  // Make the shared vertices identical after snapping.
  for (int i = 0; i < n; ++i) {
    out[i].v[4] = out[(i + 1) % n].v[2];
    out[i].v[5] = out[(i + 1) % n].v[3];
  }
  return out;
}

// A jittered grid mesh: every interior edge shared by two triangles.
std::vector<Tri> mesh(int w, int h, int cells, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  std::vector<std::array<double, 2>> p((cells + 1) * (cells + 1));
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      bool border = i == 0 || j == 0 || i == cells || j == cells;
      double x = (i + (border ? 0 : jitter(rng))) * w / cells, y = (j + (border ? 0 : jitter(rng))) * h / cells;
      p[j * (cells + 1) + i] = {snap(x), snap(y)};
    }
  std::vector<Tri> out;
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      auto& a = p[j * (cells + 1) + i];
      auto& b = p[j * (cells + 1) + i + 1];
      auto& c = p[(j + 1) * (cells + 1) + i + 1];
      auto& d = p[(j + 1) * (cells + 1) + i];
      out.push_back({{a[0], a[1], b[0], b[1], c[0], c[1]}});
      out.push_back({{a[0], a[1], c[0], c[1], d[0], d[1]}});
    }
  return out;
}

// Every pixel: the id primflow drew equals the one triangle the reference says covers it
// (0 where none does). Returns the number of pixels some triangle covers.
int compareWithReference(const std::vector<Tri>& tris, const std::vector<unsigned char>& px, int w, int h) {
  int covered = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      unsigned want = 0;
      int count = 0;
      for (size_t i = 0; i < tris.size(); ++i)
        if (covers(tris[i], x + 0.5, y + 0.5)) {
          want = static_cast<unsigned>(i + 1);
          ++count;
        }
      EXPECT_LE(count, 1) << "the reference itself must not cover a pixel twice at " << x << "," << y;
      const unsigned char* p = &px[(static_cast<size_t>(y) * w + x) * 4];
      unsigned got = p[0] | (p[1] << 8);
      EXPECT_EQ(got, want) << "pixel " << x << "," << y;
      if (want) ++covered;
      if (got != want) return -1;  // one report is enough
    }
  return covered;
}

}  // namespace

TEST(RasterCoverage, FanOfSliversMatchesExactReference) {
  auto tris = fan(64.0, 64.0, 60.0, 96);
  auto px = drawIds(tris, 128, 128, 2);
  int covered = compareWithReference(tris, px, 128, 128);
  EXPECT_GT(covered, 10000);
}

TEST(RasterCoverage, JitteredMeshIsWatertight) {
  // Fully covers the framebuffer: every pixel exactly once. Power-of-two sizes keep the
  // projection exact, so the grid vertices stay on the grid in window coordinates.
  auto tris = mesh(128, 64, 16, 7u);
  auto px = drawIds(tris, 128, 64, 2);
  EXPECT_EQ(compareWithReference(tris, px, 128, 64), 128 * 64);
}

TEST(RasterCoverage, NonPowerOfTwoViewportIsStillWatertight) {
  // Off the exact grid the decisions may differ from the real-number ones within float
  // rounding of an edge, but shared edges still give every pixel to exactly one triangle.
  auto tris = mesh(96, 80, 12, 7u);
  auto px = drawIds(tris, 96, 80, 2);
  for (size_t i = 0; i < px.size(); i += 4) {
    unsigned id = px[i] | (px[i + 1] << 8);
    EXPECT_TRUE(id >= 1 && id <= tris.size()) << "pixel " << (i / 4) % 96 << "," << (i / 4) / 96 << " missed";
  }
}

TEST(RasterCoverage, DegenerateTrianglesDrawNothing) {
  std::vector<Tri> tris = {{{10, 10, 10, 10, 10, 10}}, {{0, 0, 10, 10, 20, 20}}, {{5, 5, 30, 5, 17.5, 5}}};
  auto px = drawIds(tris, 32, 32, 1);
  for (size_t i = 0; i < px.size(); i += 4) EXPECT_EQ(px[i], 0);
}

TEST(RasterCoverage, HugeTriangleCoversEverythingOnce) {
  std::vector<Tri> tris = {{{-1e6, -1e6, 1e6, -1e6, 0, 1e6}}};
  auto px = drawIds(tris, 70, 70, 2);
  for (size_t i = 0; i < px.size(); i += 4) EXPECT_EQ(px[i], 1);
}

TEST(RasterDeterminism, IdenticalImagesForAnyThreadCount) {
  auto tris = mesh(200, 150, 30, 11u);
  auto base = drawIds(tris, 200, 150, 1);
  for (int threads : {2, 3, 8}) EXPECT_EQ(drawIds(tris, 200, 150, threads), base) << threads << " threads";
}
