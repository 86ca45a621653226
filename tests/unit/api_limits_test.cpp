// The API's tables end where primflow's id ranges do (docs/api.md, docs/reliability.md): past
// 32,768 parameter names (ids up to 0x3FFFF), 26,624 primitive modes (below the names) and
// 1,024 shared interpolators (below the modes), a new one is GL_OUT_OF_MEMORY and 0 -- never an
// id of the next range. Known names keep working.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <string>
#include <vector>

namespace {

struct Context {
  PFcontext ctx;
  std::vector<unsigned char> px = std::vector<unsigned char>(16 * 16 * 4);
  Context() {
    const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, 0};
    ctx = pfCreateContextAttribs(attribs);
    EXPECT_NE(ctx, nullptr);
    pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, 16, 16);
  }
  ~Context() {
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx);
  }
};

TEST(ApiLimits, ParameterNamesEndAt0x3FFFF) {
  Context c;
  GLuint last = 0;
  int made = 0;
  for (int i = 0; i < 40000; ++i) {
    const GLuint id = pfglGetParamNameEXT(("name" + std::to_string(i)).c_str());
    if (id == 0) {
      EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_OUT_OF_MEMORY)) << "name " << i;
      break;
    }
    ++made;
    EXPECT_GT(id, last);
    last = id;
  }
  EXPECT_EQ(last, 0x3FFFFu);
  EXPECT_EQ(made, 0x40000 - GL_FIRST_PARAM_NAME_EXT - 5);  // vertex, normal, texcoord, color, edge_flag first
  EXPECT_EQ(pfglGetParamNameEXT("name7"), static_cast<GLuint>(GL_FIRST_PARAM_NAME_EXT + 5 + 7));
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(ApiLimits, PrimitiveModesEndBelowTheParameterNames) {
  Context c;
  GLenum last = 0;
  for (int i = 0;; ++i) {
    const std::string src = "primitive many" + std::to_string(i) + "(varying float X, Y; inout varying float Z) { Z = 0.5; }\n";
    if (pfglCompilePrimitivesEXT(src.c_str()) == 0) {
      EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_OUT_OF_MEMORY)) << "primitive " << i;
      break;
    }
    last = pfglGetPrimitiveEXT(("many" + std::to_string(i)).c_str());
    ASSERT_LT(last, static_cast<GLenum>(GL_FIRST_PARAM_NAME_EXT)) << "primitive " << i;
  }
  EXPECT_EQ(last, static_cast<GLenum>(GL_FIRST_PARAM_NAME_EXT - 1));
  // A known name recompiles in its mode.
  EXPECT_NE(pfglCompilePrimitivesEXT("primitive many5(varying float X, Y; inout varying float Z) { Z = 0.25; }\n"), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(ApiLimits, SharedInterpolatorsEndBelowThePrimitiveModes) {
  Context c;
  GLenum last = 0;
  for (int i = 0;; ++i) {
    const std::string name = "lots" + std::to_string(i);
    const std::string src = "interpolator " + name + "(float s) { interpolator_return(vector(s)); }\n";
    if (pfglCompilePrimitivesEXT(src.c_str()) == 0) {
      EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_OUT_OF_MEMORY)) << "interpolator " << i;
      break;
    }
    last = pfglGetInterpolatorEXT(name.c_str());
    ASSERT_LT(last, static_cast<GLenum>(GL_FIRST_PRIMITIVE_MODE_EXT)) << "interpolator " << i;
  }
  EXPECT_EQ(last, static_cast<GLenum>(GL_FIRST_PRIMITIVE_MODE_EXT - 1));
}

}  // namespace
