// Models as pfrender draws them (tools/model): the --ortho contract (pixel centres at
// x0 + (i + 0.5)(x1 - x0)/W, row 0 at the bottom), 2D coverage, the world-z depth output against
// analytic surfaces, the PFM format, and bad model files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/glm.hpp>

#include "gl_context.h"
#include "model/model_file.h"

namespace {

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::filesystem::path p = std::filesystem::temp_directory_path() / name;
  std::ofstream(p) << text;
  return p.string();
}

std::vector<float> depthOf(const pf::test::GlContext& gl) {
  const float* d = gl.depth();
  return std::vector<float>(d, d + size_t(gl.width) * gl.height);
}

// quarter.vm: inside where max(x, y) < 0 and x^2 + y^2 < 0.5 (Fidget: negative inside).
TEST(Model, TwoDimensionalCoverageFollowsTheOrthoPixelCentres) {
  const pf::model::Model m = pf::model::loadModel(std::string(PF_SOURCE_DIR) + "/tests/data/models/fidget/quarter.vm");
  EXPECT_TRUE(m.two_dimensional);
  const int w = 40, h = 24;  // not square: the x and y extents map separately
  pf::test::GlContext gl(w, h);
  pf::model::ModelView v;
  v.width = w;
  v.height = h;
  v.box_min = {-1.0, -0.8, -1.0};
  v.box_max = {0.6, 0.4, 1.0};
  pf::model::drawModel(m, v);
  int inside = 0;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const double x = v.box_min.x + (i + 0.5) * (v.box_max.x - v.box_min.x) / w;
      const double y = v.box_min.y + (j + 0.5) * (v.box_max.y - v.box_min.y) / h;
      const double f = std::max(std::max(x, y), x * x + y * y - 0.5);
      if (std::fabs(f) < 1e-6) continue;
      EXPECT_EQ(gl.at(i, j)[0] == 255, f < 0) << i << ", " << j;
      inside += f < 0;
    }
  EXPECT_GT(inside, 100);
  // A 2D model's depth output is the box's top wherever it is inside.
  const std::vector<float> z = pf::model::worldDepth(m, v, depthOf(gl));
  for (int k = 0; k < w * h; ++k) {
    if (gl.px[size_t(k) * 4] == 255) {
      EXPECT_NEAR(z[k], 1.0, 1e-6);
    } else {
      EXPECT_TRUE(std::isnan(z[k]));
    }
  }
}

TEST(Model, OrthoDepthIsTheWorldZOfTheSurface) {
  // A sphere of radius 0.7 around (0.1, 0, 0), Fidget style.
  const std::string path = writeTemp("pf_model_sphere.vm",
                                     "x var-x\ny var-y\nz var-z\nc const 0.1\ndx sub x c\nx2 square dx\ny2 square y\n"
                                     "z2 square z\ns add x2 y2\nr2 add s z2\nr const 0.49\nout sub r2 r\n");
  const pf::model::Model m = pf::model::loadModel(path);
  EXPECT_FALSE(m.two_dimensional);
  const int n = 48;
  pf::test::GlContext gl(n, n);
  pf::model::ModelView v;
  v.width = v.height = n;
  v.ortho = true;
  v.method = GL_FIELD_METHOD_INTERVAL_EXT;
  pf::model::drawModel(m, v);
  const std::vector<float> z = pf::model::worldDepth(m, v, depthOf(gl));
  double max_err = 0;
  int hits = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -1 + (i + 0.5) * 2.0 / n - 0.1, y = -1 + (j + 0.5) * 2.0 / n;
      const double h2 = 0.49 - x * x - y * y;
      if (std::fabs(h2) < 1e-3) continue;
      const float got = z[size_t(j) * n + i];
      ASSERT_EQ(!std::isnan(got), h2 > 0) << i << ", " << j;
      if (h2 > 0) {
        max_err = std::max(max_err, std::fabs(got - std::sqrt(h2)));
        ++hits;
      }
    }
  EXPECT_GT(hits, 500);
  EXPECT_LT(max_err, 2e-6);  // the depth buffer's float precision over the box's depth
}

// A HyperFun model with attributes (scenes/models/painted_ring.hf: a banded ring and a gold
// ball, hfA_Union) is drawn in its own colours, lit; a model without `s` is not coloured.
TEST(Model, HyperFunAttributesColourTheModel) {
  const pf::model::Model m = pf::model::loadModel(std::string(PF_SOURCE_DIR) + "/scenes/models/painted_ring.hf");
  EXPECT_TRUE(m.coloured);
  EXPECT_FALSE(pf::model::loadModel(std::string(PF_SOURCE_DIR) + "/tests/data/models/hyperfun/example.hf").coloured);
  const int n = 64;
  pf::test::GlContext gl(n, n);
  pf::model::ModelView v;
  v.width = v.height = n;
  v.ortho = true;
  v.box_min = {-7.0, -7.0, -4.0};
  v.box_max = {7.0, 7.0, 4.0};
  pf::model::drawModel(m, v);
  // The ball's top, (0, 0): gold (0.9, 0.72, 0.2) lit. The ring's top near (-5, 0): green 0.3,
  // red and blue from its waves, about (0.17, 0.3, 0.6): bluer than red there.
  const unsigned char* ball = gl.at(n / 2, n / 2);
  EXPECT_GT(ball[0], ball[2] + 80) << int(ball[0]) << " " << int(ball[1]) << " " << int(ball[2]);
  EXPECT_GT(ball[1], ball[2] + 50);
  const int ring_x = static_cast<int>((-5.0 + 7.0) / 14.0 * n);
  const unsigned char* ring = gl.at(ring_x, n / 2);
  EXPECT_GT(ring[2], ring[0] + 40) << int(ring[0]) << " " << int(ring[1]) << " " << int(ring[2]);
  EXPECT_LT(ring[1], ball[1]);
}

// A sampled field's file (tests/data/ball.pfgrid: a ball of radius 0.7 sampled at 12^3, tricubic):
// drawn over the grid's own box, its --ortho depth near the ball's; a truncated file named with
// its data line and byte offset.
TEST(Model, SampledFieldsAreDrawnOverTheirGrid) {
  const pf::model::Model m = pf::model::loadModel(std::string(PF_SOURCE_DIR) + "/tests/data/ball.pfgrid");
  EXPECT_EQ(m.format, pf::field::FieldFormat::Sampled);
  EXPECT_FALSE(m.two_dimensional);
  EXPECT_EQ(m.default_box_min, glm::dvec3(-1.0));
  EXPECT_EQ(m.default_box_max, glm::dvec3(1.0));
  const int n = 48;
  pf::test::GlContext gl(n, n);
  pf::model::ModelView v;
  v.width = v.height = n;
  v.ortho = true;
  v.box_min = m.default_box_min;
  v.box_max = m.default_box_max;
  pf::model::drawModel(m, v);
  const std::vector<float> z = pf::model::worldDepth(m, v, depthOf(gl));
  int hits = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -1 + (i + 0.5) * 2.0 / n, y = -1 + (j + 0.5) * 2.0 / n, h2 = 0.49 - x * x - y * y;
      if (h2 < 0.1) continue;  // (12 samples per axis, B-spline: a few hundredths off, judged away from the rim)
      const float got = z[size_t(j) * n + i];
      ASSERT_FALSE(std::isnan(got)) << i << ", " << j;
      EXPECT_NEAR(got, std::sqrt(h2), 0.06) << i << ", " << j;
      ++hits;
    }
  EXPECT_GT(hits, 300);
  try {
    pf::model::loadModel(std::string(PF_SOURCE_DIR) + "/tests/data/truncated.pfgrid");
    ADD_FAILURE() << "a truncated grid loaded";
  } catch (const pf::model::ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("truncated.pfgrid:5:1: error: the data ends at byte offset 40 of the 256"),
              std::string::npos)
        << e.what();
  }
}

// A HyperFun sphere whose radius grows with the time x[4]: --ortho depth against the formula.
TEST(Model, HyperFunModelsReadTheTime) {
  const std::string path =
      writeTemp("pf_model_time.hf", "my_model(x[4], a[1]) {\n  array c[3], p[3];\n  c = [0, 0, 0];\n"
                                    "  p[1] = x[1]; p[2] = x[2]; p[3] = x[3];\n"
                                    "  my_model = hfSphere(p, c, 0.5 + x[4]);\n}\n");
  for (double time : {0.0, 0.25}) {
    const pf::model::Model m = pf::model::loadModel(path, time);
    EXPECT_EQ(m.format, pf::field::FieldFormat::HyperFun);
    const int n = 32;
    pf::test::GlContext gl(n, n);
    pf::model::ModelView v;
    v.width = v.height = n;
    v.ortho = true;
    v.time = time;
    v.box_min = glm::dvec3(-1.0);
    v.box_max = glm::dvec3(1.0);
    pf::model::drawModel(m, v);
    const std::vector<float> z = pf::model::worldDepth(m, v, depthOf(gl));
    const double r = 0.5 + time;
    int hits = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = -1 + (i + 0.5) * 2.0 / n, y = -1 + (j + 0.5) * 2.0 / n, h2 = r * r - x * x - y * y;
        if (std::fabs(h2) < 1e-3) continue;
        const float got = z[size_t(j) * n + i];
        ASSERT_EQ(!std::isnan(got), h2 > 0) << i << ", " << j << " at time " << time;
        if (h2 > 0) {
          EXPECT_NEAR(got, std::sqrt(h2), 2e-6);
          ++hits;
        }
      }
    EXPECT_GT(hits, 100);
  }
}

// A language field file (.pfl) holding two fields: the one named as the file is drawn -- a torus
// around z (HyperFun's library, a quartic: the analytic method), --ortho depth against the formula.
TEST(Model, LanguageFieldsAreDrawnByTheirFileName) {
  const std::string path = writeTemp(
      "pf_model_ring.pfl",
      "field float other(point p) { return 1.0 - length(p); }\n"
      "field float pf_model_ring(point p) { return hfTorusZ(p, point(0.0, 0.0, 0.0), 0.6, 0.3); }\n");
  const pf::model::Model m = pf::model::loadModel(path);
  EXPECT_EQ(m.format, pf::field::FieldFormat::Language);
  EXPECT_EQ(m.default_box_max, glm::dvec3(2.0));
  const int n = 40;
  pf::test::GlContext gl(n, n);
  pf::model::ModelView v;
  v.width = v.height = n;
  v.ortho = true;
  v.box_min = glm::dvec3(-1.0);
  v.box_max = glm::dvec3(1.0);
  pf::model::drawModel(m, v);
  const std::vector<float> z = pf::model::worldDepth(m, v, depthOf(gl));
  int hits = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -1 + (i + 0.5) * 2.0 / n, y = -1 + (j + 0.5) * 2.0 / n;
      const double ring = std::sqrt(x * x + y * y) - 0.6, h2 = 0.09 - ring * ring;
      if (std::fabs(h2) < 1e-3) continue;
      const float got = z[size_t(j) * n + i];
      ASSERT_EQ(!std::isnan(got), h2 > 0) << i << ", " << j;
      if (h2 > 0) {
        EXPECT_NEAR(got, std::sqrt(h2), 5e-6);
        ++hits;
      }
    }
  EXPECT_GT(hits, 300);
}

TEST(Model, PfmIsLittleEndianBottomToTop) {
  const std::string path = (std::filesystem::temp_directory_path() / "pf_model_test.pfm").string();
  std::string error;
  ASSERT_TRUE(pf::model::writePfm(path, 2, 1, {1.5f, std::nanf("")}, &error)) << error;
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string data = ss.str();
  ASSERT_EQ(data.substr(0, 12), "Pf\n2 1\n-1.0\n");
  ASSERT_EQ(data.size(), 12u + 8u);
  float first;
  std::memcpy(&first, data.data() + 12, 4);  // (the test machines are little-endian)
  EXPECT_EQ(first, 1.5f);
  EXPECT_FALSE(pf::model::writePfm("/nonexistent-dir/x.pfm", 1, 1, {0.0f}, &error));
}

TEST(Model, BadModelsAreReportedWithFileLineAndColumn) {
  auto error = [](const std::string& path) {
    try {
      pf::model::loadModel(path);
    } catch (const pf::model::ModelError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(error(writeTemp("pf_bad.vm", "x var-x\ny atan x x\n")).find("pf_bad.vm:2:3: error: unsupported operation 'atan'"),
            std::string::npos);
  EXPECT_NE(error("/nonexistent/model.vm").find("/nonexistent/model.vm: error: cannot open the model file"),
            std::string::npos);
  EXPECT_NE(error(writeTemp("pf_model.hf", "my_model(x[3], a[1]) {\n  r = 0;\n  while r < x[1] loop r = r + 1; endloop;\n"
                                          "  my_model = r;\n}\n"))
                .find("pf_model.hf:3:9: error: condition depends on the point x"),
            std::string::npos);
  const std::string bad_pfl =
      writeTemp("pf_bad_field.pfl", "field float f(point p) {\n  return p.x > 0.0 ? floor(p.y) : -1.0;\n}\n");
  EXPECT_NE(error(bad_pfl).find("pf_bad_field.pfl:2:22: error: 'floor (and fract, mod)' of a value that depends on the field's point"),
            std::string::npos) << error(bad_pfl);
}

}  // namespace
