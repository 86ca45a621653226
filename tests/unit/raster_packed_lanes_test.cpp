// Packed lanes (PixelExecutor::runPackedBlock): a small instance's pixels run packed into whole
// blocks instead of on the aligned blocks its bound cuts. Every lane computes the same bits
// wherever it sits, so the image must be the same to the bit with packing off
// (PF_PACKED_LANES=0) -- for small triangles, lines and points, lit sphere impostors (per-pixel
// surface), spheres with a shared interpolator (run by the sub-executor on the same lanes) and
// an implicit surface (its rays are an aligned block's: it must never be packed).
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <bit>
#include <cstdlib>
#include <random>
#include <vector>

#include "api/src/context_state.h"
#include "gl_context.h"

namespace {

constexpr int kW = 200, kH = 150;

const char* kEyeRgb =
    "interpolator eye_rgb(float scale) {\n"
    "  interpolator_return(color(0.5 + P.x * scale, 0.5 + P.y * scale, -P.z * 0.1, 1.0));\n"
    "}\n";

constexpr const char* kBallVm =
    "x var-x\ny var-y\nz var-z\nx2 square x\ny2 square y\nz2 square z\ns add x2 y2\nr2 add s z2\n"
    "c const 0.81\nout sub r2 c\n";

struct Frame {
  std::vector<unsigned char> color;
  std::vector<float> depth;
  pf::FrameStats stats;
};

Frame drawScene() {
  pf::test::GlContext c(kW, kH);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 20.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslated(0.0, 0.0, -6.0);
  pfglRotated(15, 0.3, 1, 0.1);
  pfglEnable(GL_DEPTH_TEST);
  const GLfloat dir[4] = {-0.4f, 0.5f, 0.77f, 0.0f};
  pfglLightfv(GL_LIGHT0, GL_POSITION, dir);
  pfglEnable(GL_LIGHT0);
  pfglEnable(GL_COLOR_MATERIAL);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> pos(-3.0f, 3.0f), small(-0.25f, 0.25f), col(0.0f, 1.0f);

  // Small triangles, lit per vertex (some thin and long: many aligned blocks, few pixels).
  pfglEnable(GL_LIGHTING);
  pfglBegin(GL_TRIANGLES);
  for (int i = 0; i < 300; ++i) {
    const float x = pos(rng), y = pos(rng), z = pos(rng);
    const bool thin = i % 4 == 0;
    for (int k = 0; k < 3; ++k) {
      pfglColor3f(col(rng), col(rng), col(rng));
      pfglNormal3f(small(rng), small(rng), 1.0f);
      pfglVertex3f(x + (thin ? 6 : 1) * small(rng), y + small(rng), z + small(rng));
    }
  }
  pfglEnd();
  // Sphere impostors, lit per pixel from the surface they commit.
  const GLuint centre = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
  pfglBegin(pfglGetPrimitiveEXT("sphere_impostors"));
  for (int i = 0; i < 400; ++i) {
    pfglColor3f(col(rng), col(rng), col(rng));
    pfglRastParamfEXT(radius, 0.03f + 0.12f * col(rng));
    pfglRastParam3fEXT(centre, pos(rng), pos(rng), pos(rng));
    pfglSequencePointEXT();
  }
  pfglEnd();
  pfglDisable(GL_LIGHTING);
  // Spheres coloured by a shared interpolator of their surface point.
  EXPECT_NE(pfglCompilePrimitivesEXT(kEyeRgb), 0u);
  const GLenum sphere = pfglGetPrimitiveEXT("sphere");
  pfglMaterialInterpEXT(pfglGetParamNameEXT("color"), sphere, pfglGetInterpolatorEXT("eye_rgb"));
  pfglBegin(sphere);
  pfglRastParamfEXT(pfglGetParamNameEXT("scale"), 0.3f);
  for (int i = 0; i < 60; ++i) {
    pfglRastParamfEXT(radius, 0.05f + 0.1f * col(rng));
    pfglRastParam3fEXT(centre, pos(rng), pos(rng), pos(rng));
    pfglSequencePointEXT();
  }
  pfglEnd();
  // Lines and points.
  pfglBegin(GL_LINES);
  for (int i = 0; i < 60; ++i) {
    pfglColor3f(col(rng), col(rng), col(rng));
    pfglVertex3f(pos(rng), pos(rng), pos(rng));
    pfglVertex3f(pos(rng), pos(rng), pos(rng));
  }
  pfglEnd();
  pfglBegin(GL_POINTS);
  for (int i = 0; i < 100; ++i) {
    pfglColor3f(col(rng), col(rng), col(rng));
    pfglVertex3f(pos(rng), pos(rng), pos(rng));
  }
  pfglEnd();
  // A small implicit ball: FieldHit casts the rays of aligned blocks, so it is never packed.
  const GLuint field = pfglCompileFieldEXT(GL_FIELD_FIDGET_EXT, "ball.vm", kBallVm, 2.0f * 1.75f);
  EXPECT_NE(field, 0u);
  pfglPushMatrix();
  pfglTranslatef(1.0f, -0.5f, 1.0f);
  pfglScalef(0.15f, 0.15f, 0.15f);
  pfglColor3f(0.2f, 0.8f, 0.4f);
  pfglBegin(pfglGetPrimitiveEXT("implicit"));
  pfglRastParamfEXT(pfglGetParamNameEXT("field"), static_cast<float>(field));
  pfglRastParam3fEXT(pfglGetParamNameEXT("box_min"), -1, -1, -1);
  pfglRastParam3fEXT(pfglGetParamNameEXT("box_max"), 1, 1, 1);
  pfglRastParamfEXT(pfglGetParamNameEXT("method"), 0.0f);
  pfglRastParamfEXT(pfglGetParamNameEXT("steps"), 0.0f);
  pfglSequencePointEXT();
  pfglEnd();
  pfglPopMatrix();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  Frame f;
  f.color = c.px;
  f.depth.assign(c.depth(), c.depth() + kW * kH);
  f.stats = c.ctx->renderer.stats();
  return f;
}

}  // namespace

TEST(PackedLanes, ImagesAreTheSameToTheBitWithPackingOff) {
  ::setenv("PF_PACKED_LANES", "0", 1);
  const Frame aligned = drawScene();
  ::unsetenv("PF_PACKED_LANES");
  ::setenv("PF_GANG_BLOCKS", "0", 1);
  const Frame alone = drawScene();  // each instance's pixels in blocks of their own
  ::unsetenv("PF_GANG_BLOCKS");
  const Frame ganged = drawScene();  // small instances' pixels sharing blocks (raster/gang_block.h)
  EXPECT_EQ(aligned.stats.blocks_packed, 0u);
  EXPECT_EQ(alone.stats.blocks_ganged, 0u);
  // Packing happened, and ran fewer blocks; gangs fewer still.
  EXPECT_GT(alone.stats.blocks_packed, 200u);
  EXPECT_LT(alone.stats.blocks_run, aligned.stats.blocks_run);
  EXPECT_GT(ganged.stats.blocks_ganged, 50u);
  EXPECT_LT(ganged.stats.blocks_run, alone.stats.blocks_run);
  for (const Frame* packed : {&alone, &ganged}) {
    EXPECT_EQ(packed->stats.lanes_committed, aligned.stats.lanes_committed);
    ASSERT_EQ(packed->color.size(), aligned.color.size());
    size_t colour_diff = 0, depth_diff = 0, drawn = 0;
    for (size_t i = 0; i < packed->color.size(); ++i) colour_diff += packed->color[i] != aligned.color[i];
    for (size_t i = 0; i < packed->depth.size(); ++i) {
      depth_diff += std::bit_cast<uint32_t>(packed->depth[i]) != std::bit_cast<uint32_t>(aligned.depth[i]);
      drawn += packed->depth[i] < 1.0f;
    }
    EXPECT_EQ(colour_diff, 0u);
    EXPECT_EQ(depth_diff, 0u);
    EXPECT_GT(drawn, static_cast<size_t>(kW * kH / 5));  // the scene is not empty
  }
}
