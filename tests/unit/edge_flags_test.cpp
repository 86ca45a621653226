// Edge flags (GL 1.5 section 2.6.2) where GL and OSMesa part: GL says triangle strips, fans and
// quad strips ignore them, and primflow does; OSMesa applies them to every polygon mode (the
// conformance case edge_flags compares the rest with OSMesa). Counted here: the pixels an
// unfilled strip draws are the same with its flags false as true, while a GL_TRIANGLES
// triangle loses its edges whose first vertex's flag is false.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include "gl_context.h"

namespace {

// Pixels not black after drawing `mode` with `n` vertices unfilled, edge flags `flag`.
int drawnPixels(GLenum mode, const float (*v)[2], int n, GLboolean flag, GLenum polygon_mode) {
  pf::test::GlContext c(64, 64);
  pfglViewport(0, 0, 64, 64);
  pfglMatrixMode(GL_PROJECTION);
  pfglLoadIdentity();
  pfglOrtho(0, 64, 0, 64, -1, 1);
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglPolygonMode(GL_FRONT_AND_BACK, polygon_mode);
  pfglColor3f(1, 1, 1);
  pfglBegin(mode);
  for (int k = 0; k < n; ++k) {
    pfglEdgeFlag(k == 0 ? GL_TRUE : flag);
    pfglVertex2fv(v[k]);
  }
  pfglEnd();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  int drawn = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) drawn += c.at(x, y)[0] != 0;
  return drawn;
}

const float kStrip[6][2] = {{3.1f, 4.2f}, {10.3f, 30.1f}, {22.2f, 5.3f}, {30.1f, 32.2f}, {44.3f, 6.1f}, {52.2f, 33.3f}};

}  // namespace

TEST(EdgeFlags, StripsFansAndQuadStripsIgnoreThem) {
  for (GLenum mode : {GLenum{GL_TRIANGLE_STRIP}, GLenum{GL_TRIANGLE_FAN}, GLenum{GL_QUAD_STRIP}})
    for (GLenum polygon_mode : {GLenum{GL_LINE}, GLenum{GL_POINT}}) {
      const int all = drawnPixels(mode, kStrip, 6, GL_TRUE, polygon_mode);
      EXPECT_GT(all, 0);
      EXPECT_EQ(drawnPixels(mode, kStrip, 6, GL_FALSE, polygon_mode), all) << mode << " " << polygon_mode;
    }
}

TEST(EdgeFlags, TrianglesLoseTheirUnflaggedEdges) {
  // Vertex 0 flagged, 1 and 2 not: only the edge 0 -> 1 is drawn (its pixels from x 3 to 59,
  // one a column), and under GL_POINT only vertex 0.
  const float tri[3][2] = {{3.5f, 4.5f}, {60.5f, 6.5f}, {30.5f, 58.5f}};
  const int all = drawnPixels(GL_TRIANGLES, tri, 3, GL_TRUE, GL_LINE);
  const int one = drawnPixels(GL_TRIANGLES, tri, 3, GL_FALSE, GL_LINE);
  EXPECT_GT(all, one);
  EXPECT_GE(one, 55);
  EXPECT_LE(one, 58);
  EXPECT_EQ(drawnPixels(GL_TRIANGLES, tri, 3, GL_FALSE, GL_POINT), 1);
  EXPECT_EQ(drawnPixels(GL_TRIANGLES, tri, 3, GL_TRUE, GL_POINT), 3);
}
