// Perspective: depth and colour of a receding triangle against a double-precision reference,
// and triangles with vertices behind the eye (w < 0), which 2D homogeneous rasterization
// handles without clipping.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <cmath>
#include <vector>

namespace {

constexpr int kW = 64, kH = 64;

struct Frame {
  std::vector<unsigned char> color = std::vector<unsigned char>(kW * kH * 4);
  std::vector<float> depth;
};

// Projection: frustum(-1, 1, -1, 1, 1, 100). Eye-space vertices, colours per vertex.
Frame draw(const float (*v)[3], const float (*c)[3], int count) {
  PFcontext ctx = pfCreateContext(GL_RGBA, 24);
  Frame f;
  pfMakeCurrent(ctx, f.color.data(), GL_UNSIGNED_BYTE, kW, kH);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-1, 1, -1, 1, 1, 100);
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglBegin(GL_TRIANGLES);
  for (int i = 0; i < count; ++i) {
    pfglColor3f(c[i][0], c[i][1], c[i][2]);
    pfglVertex3f(v[i][0], v[i][1], v[i][2]);
  }
  pfglEnd();
  GLint w, h, b;
  void* p;
  pfGetDepthBuffer(ctx, &w, &h, &b, &p);
  f.depth.assign(static_cast<float*>(p), static_cast<float*>(p) + kW * kH);
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  return f;
}

// The reference: intersect the eye ray through the pixel centre with the triangle's plane, in
// double. Returns false if the ray misses (or hits behind the near plane).
bool reference(const float (*v)[3], const float (*c)[3], double px, double py, double& depth, double rgb[3]) {
  // Ray direction through the pixel on the near plane z = -1.
  double dx = (px / kW) * 2 - 1, dy = (py / kH) * 2 - 1, dz = -1;
  double e1[3], e2[3], d[3] = {dx, dy, dz};
  for (int k = 0; k < 3; ++k) {
    e1[k] = v[1][k] - v[0][k];
    e2[k] = v[2][k] - v[0][k];
  }
  double pv[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]};
  double det = e1[0] * pv[0] + e1[1] * pv[1] + e1[2] * pv[2];
  if (std::fabs(det) < 1e-15) return false;
  double tv[3] = {-v[0][0], -v[0][1], -v[0][2]};
  double u = (tv[0] * pv[0] + tv[1] * pv[1] + tv[2] * pv[2]) / det;
  double qv[3] = {tv[1] * e1[2] - tv[2] * e1[1], tv[2] * e1[0] - tv[0] * e1[2], tv[0] * e1[1] - tv[1] * e1[0]};
  double w = (d[0] * qv[0] + d[1] * qv[1] + d[2] * qv[2]) / det;
  double t = (e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2]) / det;
  if (u < 0 || w < 0 || u + w > 1 || t < 1) return false;  // t < 1: in front of the near plane
  double ze = -t;  // eye z at the hit point (dz = -1)
  double n = 1, f = 100;
  double zndc = (-(f + n) / (f - n) * ze - 2 * f * n / (f - n)) / -ze;
  depth = zndc * 0.5 + 0.5;
  for (int k = 0; k < 3; ++k) rgb[k] = (1 - u - w) * c[0][k] + u * c[1][k] + w * c[2][k];
  return true;
}

// Compares everywhere except within `margin` pixels of an edge of the reference (float and
// double may disagree exactly on the edge of a perspective triangle).
void compare(const float (*v)[3], const float (*c)[3], const Frame& f, int* covered) {
  *covered = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      double depth, rgb[3];
      bool hit = reference(v, c, x + 0.5, y + 0.5, depth, rgb);
      // Probe the neighbourhood: skip pixels whose coverage is ambiguous.
      bool ambiguous = false;
      for (double ox : {-0.01, 0.01})
        for (double oy : {-0.01, 0.01}) {
          double d2, c2[3];
          if (reference(v, c, x + 0.5 + ox, y + 0.5 + oy, d2, c2) != hit) ambiguous = true;
        }
      if (ambiguous) continue;
      const unsigned char* p = &f.color[(y * kW + x) * 4];
      if (!hit) {
        EXPECT_EQ(p[3], 0) << "extra pixel " << x << "," << y;
        continue;
      }
      ++*covered;
      EXPECT_EQ(p[3], 255) << "missing pixel " << x << "," << y;
      EXPECT_NEAR(f.depth[y * kW + x], depth, 2e-6) << x << "," << y;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], rgb[k] * 255.0, 1.0) << "channel " << k << " at " << x << "," << y;
    }
}

}  // namespace

TEST(RasterPerspective, RecedingTriangleDepthAndColour) {
  const float v[3][3] = {{-3, -2, -2}, {4, -1, -20}, {-1, 5, -8}};
  const float c[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Frame f = draw(v, c, 3);
  int covered;
  compare(v, c, f, &covered);
  EXPECT_GT(covered, 500);
}

TEST(RasterPerspective, VertexBehindTheEyeIsClippedAtTheNearPlane) {
  // One vertex behind the eye (z > 0, so w < 0) and the near plane cutting the triangle.
  const float v[3][3] = {{-2, -1, -4}, {2, -1, -4}, {0, -0.5f, 3}};
  const float c[3][3] = {{1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
  Frame f = draw(v, c, 3);
  int covered;
  compare(v, c, f, &covered);
  EXPECT_GT(covered, 200);
}

TEST(RasterPerspective, TriangleEntirelyBehindTheEyeDrawsNothing) {
  const float v[3][3] = {{-1, -1, 2}, {1, -1, 2}, {0, 1, 3}};
  const float c[3][3] = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  Frame f = draw(v, c, 3);
  for (size_t i = 3; i < f.color.size(); i += 4) EXPECT_EQ(f.color[i], 0);
}
