// The `matrix` type (docs/language.md, "Matrices"): constructors, products with matrices,
// points, vectors and normals, transpose / determinant / inverse, rows and elements at constant
// and run-time indices, matrix parameters, the context's transforms as matrices, and the
// errors. Values are checked against the same algebra in double (glm) on one 8x8 block, in
// both execution modes (runBlock compares the SIMD executor with the reference interpreter).
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <string>

#include "compile_helpers.h"
#include "gl_context.h"

using namespace pf;
using namespace pf::test;

namespace {

float laneX(int i) { return static_cast<float>(i % 8) + 0.5f; }
float laneY(int i) { return static_cast<float>(i / 8) + 0.5f; }

// The 16 numbers of kM, row by row, as the language's matrix(...) takes them.
const double kM[4][4] = {{2.0, 0.5, -1.0, 3.0}, {0.25, 1.5, 0.75, -2.0}, {-0.5, 1.0, 3.0, 0.5}, {0.0, 0.1, -0.2, 1.25}};
const char* kMSource =
    "matrix(2.0, 0.5, -1.0, 3.0,  0.25, 1.5, 0.75, -2.0,  -0.5, 1.0, 3.0, 0.5,  0.0, 0.1, -0.2, 1.25)";

// glm is column-major: m[c][r]. This builds glm's matrix from rows.
glm::dmat4 fromRows(const double r[4][4]) {
  glm::dmat4 m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m[j][i] = r[i][j];
  return m;
}

// Runs `body` (which sets `float z` from X, Y) as a primitive on one block; returns the depths.
std::vector<float> runBody(const std::string& body, const std::string& params = "",
                           const std::vector<float>& values = {}) {
  Compiled c = compile("primitive p(" + params + "varying float X, Y; inout varying float Z) {\n" + body +
                       "\n  Z = z;\n}\n");
  EXPECT_TRUE(c.ok) << c.diagnostics;
  if (!c.ok) return {};
  BlockRun r = runBlock(*c.find("p"), values, {}, 0, true, 1e9f);
  return r.depth;
}

void expectLanes(const std::vector<float>& got, const std::function<double(double x, double y)>& want,
                 double tolerance = 2e-5) {
  ASSERT_EQ(got.size(), 64u);
  for (int i = 0; i < 64; ++i) {
    const double w = want(laneX(i), laneY(i));
    EXPECT_NEAR(got[i], w, tolerance * std::max(1.0, std::abs(w))) << "lane " << i;
  }
}

}  // namespace

TEST(Matrices, TimesPointVectorAndNormal) {
  const glm::dmat4 m = fromRows(kM);
  // m * point(X, Y, 1, 1): all four rows; the result's components weighted to one number.
  expectLanes(runBody(std::string("  matrix m = ") + kMSource + ";\n"
                      "  point q = m * point(X, Y, 1.0, 1.0);\n"
                      "  float z = q.x + 10.0 * q.y + 100.0 * q.z + 1000.0 * q.w;"),
              [&](double x, double y) {
                const glm::dvec4 q = m * glm::dvec4(x, y, 1, 1);
                return q.x + 10 * q.y + 100 * q.z + 1000 * q.w;
              });
  // m * vector: the upper 3x3, no translation.
  expectLanes(runBody(std::string("  matrix m = ") + kMSource + ";\n"
                      "  vector v = m * vector(X, Y, 2.0);\n"
                      "  float z = v.x + 10.0 * v.y + 100.0 * v.z;"),
              [&](double x, double y) {
                const glm::dvec3 v = glm::dmat3(m) * glm::dvec3(x, y, 2);
                return v.x + 10 * v.y + 100 * v.z;
              });
  // m * normal: the inverse transpose of the upper 3x3 (normals stay normal to transformed
  // surfaces).
  expectLanes(runBody(std::string("  matrix m = ") + kMSource + ";\n"
                      "  normal n = m * normal(X, Y, 2.0);\n"
                      "  float z = n.x + 10.0 * n.y + 100.0 * n.z;"),
              [&](double x, double y) {
                const glm::dvec3 n = glm::transpose(glm::inverse(glm::dmat3(m))) * glm::dvec3(x, y, 2);
                return n.x + 10 * n.y + 100 * n.z;
              });
}

TEST(Matrices, ProductsTransposeDeterminantInverse) {
  const glm::dmat4 m = fromRows(kM);
  // A matrix depending on X and Y (varying), times the constant one, transposed: element [1][2].
  const std::string setup = std::string("  matrix m = ") + kMSource + ";\n" +
                            "  matrix v = matrix(1.0);\n  v[0][3] = X;\n  v[2][1] = Y;\n";
  auto varyingMatrix = [](double x, double y) {
    glm::dmat4 v(1.0);
    v[3][0] = x;  // row 0, column 3
    v[1][2] = y;  // row 2, column 1
    return v;
  };
  expectLanes(runBody(setup + "  matrix p = transpose(m * v);\n  float z = p[1][2] + 10.0 * p[3][0];"),
              [&](double x, double y) {
                const glm::dmat4 p = glm::transpose(m * varyingMatrix(x, y));
                return p[2][1] + 10 * p[0][3];
              });
  expectLanes(runBody(setup + "  float z = determinant(m * v);"),
              [&](double x, double y) { return glm::determinant(m * varyingMatrix(x, y)); });
  // inverse: every element of inverse(m * v), weighted.
  expectLanes(runBody(setup + "  matrix i = inverse(m * v);\n  float z = 0.0;\n"
                              "  for (int r = 0; r < 4; r += 1)\n"
                              "    for (int c = 0; c < 4; c += 1) z += i[r][c] * float(1 + r * 4 + c);"),
              [&](double x, double y) {
                const glm::dmat4 i = glm::inverse(m * varyingMatrix(x, y));
                double z = 0;
                for (int r = 0; r < 4; ++r)
                  for (int c = 0; c < 4; ++c) z += i[c][r] * (1 + r * 4 + c);
                return z;
              },
              1e-4);
  // Sums, differences and scaling are elementwise; matrix(s) is s times the identity.
  expectLanes(runBody(setup + "  matrix s = (m + v) * 2.0 - matrix(X) / 4.0;\n  float z = s[0][0] + 10.0 * s[0][3];"),
              [&](double x, double) {
                const glm::dmat4 s = (m + varyingMatrix(x, 0)) * 2.0 - glm::dmat4(x) / 4.0;
                return s[0][0] + 10 * s[3][0];
              });
}

TEST(Matrices, RowsAndElementsAtRunTimeIndices) {
  // Row X mod 4 as a point, its element Y mod 4: reading m[r][c] at varying indices; outside
  // the matrix, zero.
  expectLanes(runBody(std::string("  matrix m = ") + kMSource + ";\n"
                      "  int r = int(X);\n  int c = int(Y);\n"
                      "  point row = m[r % 5];\n  float z = row[c % 5];"),
              [&](double x, double y) {
                const int r = static_cast<int>(x) % 5, c = static_cast<int>(y) % 5;
                return r < 4 && c < 4 ? kM[r][c] : 0.0;
              });
  // Writing one element at a varying index changes only that element.
  expectLanes(runBody(std::string("  matrix m = ") + kMSource + ";\n"
                      "  m[int(Y) % 4][int(X) % 4] = 100.0;\n"
                      "  float z = m[1][2] + m[3][3];"),
              [&](double x, double y) {
                double m[4][4];
                for (int r = 0; r < 4; ++r)
                  for (int c = 0; c < 4; ++c) m[r][c] = kM[r][c];
                m[static_cast<int>(y) % 4][static_cast<int>(x) % 4] = 100.0;
                return m[1][2] + m[3][3];
              });
}

TEST(Matrices, MatrixParameterRowByRow) {
  std::vector<float> values;
  for (const auto& row : kM)
    for (double v : row) values.push_back(static_cast<float>(v));
  const glm::dmat4 m = fromRows(kM);
  expectLanes(runBody("  point q = xf[0] * point(X, Y, 0.5, 1.0);\n  float z = q.x + 10.0 * q.z;",
                      "matrix xf[1]; ", values),
              [&](double x, double y) {
                const glm::dvec4 q = m * glm::dvec4(x, y, 0.5, 1);
                return q.x + 10 * q.z;
              });
}

// object_matrix() * q is object(q), bit for bit (the same products in the same order), and
// the other transforms likewise: a primitive writes the differences into its depth.
TEST(Matrices, TheContextsTransformsAsMatrices) {
  GlContext c(8, 8);
  ASSERT_NE(pfglCompilePrimitivesEXT(
                "primitive check(varying float X, Y; inout varying float Z) {\n"
                "  point q = point(X * 0.1, Y * 0.2, -1.5, 1.0);\n"
                "  point a = object_matrix() * q - object(q);\n"
                "  point b = eye_from_object_matrix() * q - eye_from_object(q);\n"
                "  point e = eye_matrix() * q - eye(q);\n"
                "  point k = clip_matrix() * q - clip(q);\n"
                "  point s = screen_matrix() * q - screen(q);\n"
                "  Z = 0.5 + abs(a.x) + abs(a.y) + abs(a.z) + abs(a.w) + abs(b.x) + abs(b.w) + abs(e.x) + abs(e.w)\n"
                "        + abs(k.z) + abs(k.w) + abs(s.x) + abs(s.y) + abs(s.z);\n"
                "}\n"),
            0u);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.6, 0.5, -0.4, 0.7, 1.0, 9.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslated(0.3, -0.2, -2.0);
  pfglRotated(30, 0.2, 1, 0.4);
  pfglScaled(1.5, 0.8, 1.2);
  pfglEnable(GL_DEPTH_TEST);
  pfglDepthFunc(GL_ALWAYS);
  pfglClear(GL_DEPTH_BUFFER_BIT);
  pfglBegin(pfglGetPrimitiveEXT("check"));
  pfglSequencePointEXT();
  pfglEnd();
  pfglFinish();
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  for (int i = 0; i < 64; ++i) EXPECT_EQ(c.depth()[i], 0.5f) << "pixel " << i;
}

namespace {
void expectError(const std::string& body, const std::string& message) {
  Compiled c = compile("primitive p(varying float X, Y; inout varying float Z) {\n" + body + "\n}\n");
  EXPECT_FALSE(c.ok) << body;
  EXPECT_NE(c.diagnostics.find(message), std::string::npos) << c.diagnostics;
}
}  // namespace

TEST(Matrices, Errors) {
  expectError("  matrix m = matrix(1.0);\n  Z = m.x;", "a matrix's elements are m[row][column]");
  expectError("  matrix m = matrix(1.0);\n  matrix n = m / m;", "operator '/' cannot combine matrix and matrix");
  expectError("  matrix m = matrix(1.0);\n  point q = point(1.0, 2.0, 3.0) * m;",
              "operator '*' cannot combine point and matrix");
  expectError("  matrix m = matrix(1.0, 2.0, 3.0);", "matrix() takes 1 number (the diagonal) or 16 (row by row), not 3");
  expectError("  float d = determinant(point(1.0, 2.0, 3.0));", "determinant() takes a matrix, not point");
  expectError("  matrix m = matrix(1.0);\n  Z = m[4][0];", "out of range");
  expectError("  matrix m = point(1.0, 2.0, 3.0);", "expected matrix, found point");
  Compiled c = compile("interpolator bad(float k) { interpolator_return(matrix(k)); }\n");
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("an interpolator returns a float, point, vector, normal or color"), std::string::npos)
      << c.diagnostics;
}
