// HyperFun's convolution surfaces over triangles, meshes, arcs and radius-sized segments, and its
// SARDF distance primitives: each tape against an independent reference in double -- numerical
// integration of the Cauchy kernel (Gauss-Legendre over subdivided triangles, along arcs and
// segments), never the closed forms the library uses -- at random points and at the hard ones (in
// a triangle's plane, on its edges and vertices, on an arc's axis and on the arc, far away);
// HyperFun's quirks (hfConvArc's write-backs, hfConvLineR's threshold and clamp); the errors.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "compiler/field/hyperfun_reader.h"
#include "field/field_reference.h"
#include "raster/field/float_evaluator.h"

namespace pf::field {
namespace {

using P = std::array<double, 3>;
using Fn = std::function<double(const P&)>;

FieldTape compileOk(const std::string& text) {
  DiagnosticLog log;
  auto tape = readHyperFunModel("m.hf", text, log, {}, "my_model");
  EXPECT_TRUE(tape) << log.format();
  return tape ? *tape : FieldTape{};
}

std::string compileError(const std::string& text) {
  DiagnosticLog log;
  auto tape = readHyperFunModel("m.hf", text, log, {});
  EXPECT_FALSE(tape) << text;
  return log.format();
}

// An object my_model(x[3], a[2]) with the given body lines (the body starts on line 2).
std::string model(const std::string& body) { return "my_model(x[3], a[2]) {\n" + body + "\n}\n"; }

void expectHas(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "expected to find: " << part << "\nin:\n" << text;
}

double sq(double v) { return v * v; }
P sub(const P& a, const P& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
P add(const P& a, const P& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
P mul(const P& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const P& a, const P& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
P cross(const P& a, const P& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double kernel(const P& x, const P& y, double s) { return 1.0 / sq(1.0 + s * s * dot(sub(x, y), sub(x, y))); }

// Gauss-Legendre nodes and weights on [0, 1] (Newton's iteration on P_n).
struct Gauss {
  std::vector<double> t, w;
  explicit Gauss(int n) {
    for (int i = 1; i <= n; ++i) {
      double x = std::cos(M_PI * (i - 0.25) / (n + 0.5)), dp = 1.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = x;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (x * p1 - p0) / (x * x - 1.0);
        const double dx = p1 / dp;
        x -= dx;
        if (std::fabs(dx) < 1e-16) break;
      }
      t.push_back((1.0 + x) / 2.0);
      w.push_back(1.0 / ((1.0 - x * x) * dp * dp));
    }
  }
};
const Gauss kGauss(12);

// The integral of f over [lo, hi] by 12-point Gauss-Legendre on `panels` equal panels.
double integrate(const std::function<double(double)>& f, double lo, double hi, int panels = 96) {
  double sum = 0.0;
  const double width = (hi - lo) / panels;
  for (int i = 0; i < panels; ++i)
    for (size_t k = 0; k < kGauss.t.size(); ++k) sum += kGauss.w[k] * f(lo + width * (i + kGauss.t[k]));
  return sum * width;
}

// The Cauchy kernel's integral over the triangle abc: the triangle cut into 4^levels similar
// ones, each integrated by a 12x12 Gauss rule through the collapsed square a + u(b - a) + uv(c - b)
// (area element 2 |abc| u du dv).
double triangleIntegral(const P& x, const P& a, const P& b, const P& c, double s, int levels = 3) {
  if (levels > 0) {
    const P ab = mul(add(a, b), 0.5), bc = mul(add(b, c), 0.5), ca = mul(add(c, a), 0.5);
    return triangleIntegral(x, a, ab, ca, s, levels - 1) + triangleIntegral(x, ab, b, bc, s, levels - 1) +
           triangleIntegral(x, ca, bc, c, s, levels - 1) + triangleIntegral(x, ab, bc, ca, s, levels - 1);
  }
  const P n = cross(sub(b, a), sub(c, a));
  const double twice_area = std::sqrt(dot(n, n));
  double sum = 0.0;
  for (size_t i = 0; i < kGauss.t.size(); ++i)
    for (size_t j = 0; j < kGauss.t.size(); ++j) {
      const double u = kGauss.t[i], v = kGauss.t[j];
      const P p = add(add(a, mul(sub(b, a), u)), mul(sub(c, b), u * v));
      sum += kGauss.w[i] * kGauss.w[j] * u * kernel(x, p, s);
    }
  return sum * twice_area;
}

// The Cauchy kernel's integral along the segment from b to e (arc length).
double segmentIntegral(const P& x, const P& b, const P& e, double s) {
  const double len = std::sqrt(dot(sub(e, b), sub(e, b)));
  return len * integrate([&](double t) { return kernel(x, add(b, mul(sub(e, b), t)), s); }, 0.0, 1.0);
}

// HyperFun's arc: centre c, radius r, spanning theta degrees from the +x axis of the frame turned by
// angle degrees about axis, integrated over the ANGLE (HyperFun's normalisation, measured against
// its closed form: the arc-length integral divided by r). HyperFun's quirks: 1e-6 added to angle
// and to each axis component, theta clamped to 360, its degree 3.141592/180 radians.
double arcIntegral(const P& x, const P& c, double r, double theta, P axis, double angle, double s) {
  const double rd = 3.141592 / 180.0;
  for (double& a : axis) a += 1e-6;
  const P u = mul(axis, 1.0 / std::sqrt(dot(axis, axis)));
  const double turn = (angle + 1e-6) * rd, ct = std::cos(turn), st = std::sin(turn);
  auto rotate = [&](const P& v) { return add(add(mul(v, ct), mul(cross(u, v), st)), mul(u, dot(u, v) * (1 - ct))); };
  return integrate(
      [&](double phi) { return kernel(x, add(c, rotate({r * std::cos(phi), r * std::sin(phi), 0.0})), s); }, 0.0,
      std::min(theta, 360.0) * rd, 192);
}

// The largest relative error seen, and where (printed with PF_REPORT_ACCURACY set).
struct Errors {
  double relative = 0.0, scaled = 0.0;  // |got - want| / |want|, and / scale
  double in_float = 0.0;                // the float evaluator's |got - want| / scale (reported only)
  P where{}, where_float{};
  ~Errors() {
    if (std::getenv("PF_REPORT_ACCURACY"))
      std::printf("[accuracy] max relative error %.3g at (%g, %g, %g); max error / scale %.3g; in float %.3g at "
                  "(%g, %g, %g)\n",
                  relative, where[0], where[1], where[2], scaled, in_float, where_float[0], where_float[1],
                  where_float[2]);
  }
};

// The tape (in double, with its float constants) against `want` at `points`, within tol times
// scale(p) -- by default max(|want|, 1e-4): the values are integrals (T = 0), positive, and are
// held to tol relative down to 1e-4 (HyperFun's thresholds T are larger) and to 1e-4 tol absolute
// below, where far from a triangle, in its plane, its edges' terms cancel -- and finite in the
// float evaluator.
void expectAt(const FieldTape& t, const Fn& want, const std::vector<P>& points, double tol, Errors& errors,
              const Fn& scale = nullptr) {
  FloatEvaluator f(t);
  for (const P& p : points) {
    const double w = want(p), got = testing::evaluateDouble(t, p[0], p[1], p[2]);
    const double size = scale ? scale(p) : std::max(std::fabs(w), 1e-4);
    const double err = std::fabs(got - w) / std::fabs(w);
    if (err > errors.relative) {
      errors.relative = err;
      errors.where = p;
    }
    errors.scaled = std::max(errors.scaled, std::fabs(got - w) / size);
    EXPECT_NEAR(got, w, tol * size) << "at " << p[0] << ", " << p[1] << ", " << p[2];
    const double single = f.evaluate(float(p[0]), float(p[1]), float(p[2]));
    EXPECT_TRUE(std::isfinite(single)) << "float evaluator at " << p[0] << ", " << p[1] << ", " << p[2];
    if (std::fabs(single - w) / size > errors.in_float) {
      errors.in_float = std::fabs(single - w) / size;
      errors.where_float = p;
    }
  }
}

std::vector<P> randomPoints(int n, double lo, double hi, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<P> points;
  for (int i = 0; i < n; ++i) points.push_back({u(rng), u(rng), u(rng)});
  return points;
}

// --- Triangles and meshes ----------------------------------------------------------------------

const P kTri[2][3] = {{{-1.0, -0.5, 0.2}, {1.2, -0.3, -0.1}, {0.1, 1.0, 0.4}},
                      {{0.3, 0.2, -1.0}, {0.5, -0.6, 0.8}, {-0.7, 0.4, 0.5}}};
const double kTriS[2] = {1.5, 0.8};
const char* kTriModel =
    "array v[18], w[2];\nv = [-1, -0.5, 0.2, 1.2, -0.3, -0.1, 0.1, 1, 0.4, 0.3, 0.2, -1, 0.5, -0.6, 0.8, "
    "-0.7, 0.4, 0.5];\nw = [1.5, 0.8];\n";

// HyperFun's value: S^3 times the integral (measured against its closed form).
double triangles(const P& x) {
  double sum = 0.0;
  for (int i = 0; i < 2; ++i)
    sum += std::pow(kTriS[i], 3) * triangleIntegral(x, kTri[i][0], kTri[i][1], kTri[i][2], kTriS[i]);
  return sum;
}

// Points on the first triangle: its vertices, edges (middles, thirds) and inside; in its plane
// outside it; just off it; and far away.
std::vector<P> hardTrianglePoints() {
  const P& a = kTri[0][0];
  const P& b = kTri[0][1];
  const P& c = kTri[0][2];
  const P n = cross(sub(b, a), sub(c, a));
  std::vector<P> points = {a, b, c, mul(add(a, b), 0.5), add(mul(b, 2.0 / 3), mul(c, 1.0 / 3)), mul(add(c, a), 0.5),
                           mul(add(add(a, b), c), 1.0 / 3), add(a, mul(sub(a, b), 0.7)),  // in the plane, outside
                           add(b, mul(sub(b, c), 2.0)), add(mul(add(a, b), 0.5), mul(n, 1e-4)),
                           add(c, mul(n, 1e-7)), {12.0, -9.0, 7.0}, {-30.0, 2.0, 1.0}};
  for (const P& uv : randomPoints(30, -1.0, 2.0, 23))  // in the plane, in and around the triangle
    points.push_back(add(a, add(mul(sub(b, a), uv[0]), mul(sub(c, a), uv[1]))));
  return points;
}

TEST(HyperFunConvolution, TrianglesAgainstQuadrature) {
  const FieldTape t = compileOk(model(std::string(kTriModel) + "my_model = hfConvTriangle(x, v, w, 0);"));
  Errors errors, hard;
  expectAt(t, triangles, randomPoints(150, -2.0, 2.0), 1e-5, errors);
  expectAt(t, triangles, hardTrianglePoints(), 1e-5, hard);
  // T is subtracted.
  const FieldTape minus_t = compileOk(model(std::string(kTriModel) + "my_model = hfConvTriangle(x, v, w, 0.1);"));
  EXPECT_NEAR(testing::evaluateDouble(minus_t, 0.2, 0.1, 0.3), testing::evaluateDouble(t, 0.2, 0.1, 0.3) - 0.1, 1e-7);
}

TEST(HyperFunConvolution, MeshesAreTrianglesByVertexNumber) {
  // The two triangles of kTri as a mesh: 6 vertices, in another order, numbered from 1.
  const std::string mesh =
      "array v[18], t[6], w[2];\nv = [0.1, 1, 0.4, -1, -0.5, 0.2, 1.2, -0.3, -0.1, 0.3, 0.2, -1, 0.5, -0.6, 0.8, "
      "-0.7, 0.4, 0.5];\nt = [2, 3, 1, 4, 5, 6];\nw = [1.5, 0.8];\n";
  const FieldTape t = compileOk(model(mesh + "my_model = hfConvMesh(x, v, t, w, 0);"));
  Errors errors;
  expectAt(t, triangles, randomPoints(100, -2.0, 2.0, 5), 1e-5, errors);
  expectAt(t, triangles, hardTrianglePoints(), 1e-5, errors);
  const FieldTape minus_t = compileOk(model(mesh + "my_model = hfConvMesh(x, v, t, w, 0.1);"));
  EXPECT_NEAR(testing::evaluateDouble(minus_t, 0.2, 0.1, 0.3), testing::evaluateDouble(t, 0.2, 0.1, 0.3) - 0.1, 1e-7);
  const std::string bad = "array v[9], t[3], w[1];\nv = [0, 0, 0, 1, 0, 0, 0, 1, 0];\nw = [1];\n";
  expectHas(compileError(model(bad + "t = [1, 2, 4];\nmy_model = hfConvMesh(x, v, t, w, 0.1);")),
            "m.hf:6:29: error: item 3 of 'tri' (argument 3 of 'hfConvMesh') is 4, which is not a vertex number: "
            "they are whole numbers from 1 to 3 (the vertices of 'v')");
  expectHas(compileError(model(bad + "t = [0, 2, 3];\nmy_model = hfConvMesh(x, v, t, w, 0.1);")),
            "m.hf:6:29: error: item 1 of 'tri' (argument 3 of 'hfConvMesh') is 0, which is not a vertex number");
  expectHas(compileError(model(bad + "t = [1, 2.5, 3];\nmy_model = hfConvMesh(x, v, t, w, 0.1);")),
            "m.hf:6:29: error: item 2 of 'tri' (argument 3 of 'hfConvMesh') is 2.5, which is not a vertex number");
  expectHas(compileError(model(bad + "t = [1, 2, 3];\nt[2] = x[1];\nmy_model = hfConvMesh(x, v, t, w, 0.1);")),
            "m.hf:7:29: error: item 2 of 'tri' (argument 3 of 'hfConvMesh') depends on the point x; it must be "
            "known when the model is compiled");
  expectHas(compileError(model("array v[8], t[3], w[1];\nv = [0, 0, 0, 1, 0, 0, 0, 1];\nt = [1, 2, 3];\nw = [1];\n"
                               "my_model = hfConvMesh(x, v, t, w, 0.1);")),
            "m.hf:6:26: error: 'vect' (argument 2 of 'hfConvMesh') must hold 3 items per vertex; 'v' has 8");
  expectHas(compileError(model(bad + "t = [1, 2, 3];\nmy_model = hfConvMesh(x, v, t, t, 0.1);")),
            "m.hf:6:29: error: 'tri' (argument 3 of 'hfConvMesh') must be an array of 9 items; 't' has 3");
}

TEST(HyperFunConvolution, DegenerateTrianglesAddNothing) {
  // Collinear corners, and two equal corners: zero area, so the integral is 0 everywhere.
  const FieldTape t = compileOk(
      model("array v[18], w[2];\nv = [0, 0, 0, 1, 1, 1, 2, 2, 2, 0.5, 0, 0, 0.5, 0, 0, 1, 1, 0];\nw = [2, 1];\n"
            "my_model = hfConvTriangle(x, v, w, 0.25);"));
  for (const P& p : std::vector<P>{{0.5, 0.5, 0.5}, {1, 1, 1}, {0.5, 0, 0}, {0.3, -0.2, 0.9}, {40, 1, -3}})
    EXPECT_EQ(testing::evaluateDouble(t, p[0], p[1], p[2]), -0.25) << p[0] << ", " << p[1] << ", " << p[2];
  expectHas(compileError(model("array v[8], w[1];\nv = [0, 0, 0, 1, 0, 0, 0, 1];\nw = [1];\n"
                               "my_model = hfConvTriangle(x, v, w, 0.1);")),
            "m.hf:5:30: error: 'vect' (argument 2 of 'hfConvTriangle') must be an array of 9 items; 'v' has 8");
}

// --- Arcs --------------------------------------------------------------------------------------

// Three arcs: 100 degrees about a tilted axis, 250 degrees (split in two by HyperFun), and 400
// degrees (clamped to 360).
const char* kArcModel =
    "array c[9], r[3], th[3], ax[9], ang[3], w[3];\nc = [0.1, -0.2, 0.3, -0.5, 0.4, 0, 0.6, 0.1, -0.4];\n"
    "r = [1.1, 0.7, 0.5];\nth = [100, 250, 400];\nax = [0.3, 0.5, 1, 1, 0, 0, -0.2, 1, 0.4];\n"
    "ang = [35, -60, 120];\nw = [1.3, 2.0, 0.9];\n";
const P kArcC[3] = {{0.1, -0.2, 0.3}, {-0.5, 0.4, 0.0}, {0.6, 0.1, -0.4}};
const P kArcAxis[3] = {{0.3, 0.5, 1.0}, {1.0, 0.0, 0.0}, {-0.2, 1.0, 0.4}};
const double kArcR[3] = {1.1, 0.7, 0.5}, kArcTheta[3] = {100, 250, 400}, kArcAngle[3] = {35, -60, 120},
             kArcS[3] = {1.3, 2.0, 0.9};

double arcs(const P& x) {
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) sum += arcIntegral(x, kArcC[i], kArcR[i], kArcTheta[i], kArcAxis[i], kArcAngle[i], kArcS[i]);
  return sum;
}

// The point on arc i at phi degrees, lifted along the arc's normal by `lift` (HyperFun's frame, as
// arcIntegral's).
P arcPoint(int i, double phi_degrees, double lift = 0.0) {
  const double rd = 3.141592 / 180.0;
  P axis = kArcAxis[i];
  for (double& a : axis) a += 1e-6;
  const P u = mul(axis, 1.0 / std::sqrt(dot(axis, axis)));
  const double turn = (kArcAngle[i] + 1e-6) * rd, ct = std::cos(turn), st = std::sin(turn);
  auto rotate = [&](const P& v) { return add(add(mul(v, ct), mul(cross(u, v), st)), mul(u, dot(u, v) * (1 - ct))); };
  const double phi = phi_degrees * rd;
  return add(kArcC[i], rotate({kArcR[i] * std::cos(phi), kArcR[i] * std::sin(phi), lift}));
}

TEST(HyperFunConvolution, ArcsAgainstQuadrature) {
  const FieldTape t = compileOk(model(std::string(kArcModel) + "my_model = hfConvArc(x, c, r, th, ax, ang, w, 0);"));
  Errors errors, on_axis_and_arc;
  expectAt(t, arcs, randomPoints(120, -2.0, 2.0, 9), 1e-5, errors);
  // On each arc (its ends, its middle, where HyperFun splits it), on its axis (the centre, above
  // and below it), just off the arc, and far away.
  std::vector<P> hard = {{15.0, -4.0, 9.0}, {-40.0, 3.0, 0.5}};
  for (int i = 0; i < 3; ++i) {
    const double span = std::min(kArcTheta[i], 360.0);
    for (double phi : {0.0, span / 2, span, 180.0, 300.0}) hard.push_back(arcPoint(i, phi));
    hard.push_back(arcPoint(i, 10.0, 1e-5));
    hard.push_back(kArcC[i]);
    const P normal = sub(arcPoint(i, 0.0, 1.0), arcPoint(i, 0.0, 0.0));
    hard.push_back(add(kArcC[i], mul(normal, 0.8)));  // on the axis
    hard.push_back(add(kArcC[i], mul(normal, -3.0)));
  }
  expectAt(t, arcs, hard, 1e-5, on_axis_and_arc);
  const FieldTape minus_t = compileOk(model(std::string(kArcModel) + "my_model = hfConvArc(x, c, r, th, ax, ang, w, 0.2);"));
  EXPECT_NEAR(testing::evaluateDouble(minus_t, 0.2, 0.1, 0.3), testing::evaluateDouble(t, 0.2, 0.1, 0.3) - 0.2, 1e-7);
}

TEST(HyperFunConvolution, ArcLimits) {
  // Radius 0: the kernel at the centre times the angle spanned (HyperFun's value too); theta 0:
  // nothing.
  const FieldTape t = compileOk(
      model("array c[6], r[2], th[2], ax[6], ang[2], w[2];\nc = [0.2, 0, 0, 0, 0, 0];\nr = [0, 1];\nth = [90, 0];\n"
            "ax = [0, 0, 1, 0, 0, 1];\nang = [0, 0];\nw = [1.5, 1];\nmy_model = hfConvArc(x, c, r, th, ax, ang, w, 0);"));
  Errors errors;
  expectAt(t, [](const P& x) { return 90 * 3.141592 / 180 * kernel(x, {0.2, 0, 0}, 1.5); },
           {{0.2, 0, 0}, {1, 2, 0.5}, {-0.3, 0.1, 0.2}, {0, 0, 0}}, 1e-6, errors);
}

TEST(HyperFunConvolution, ArcWritesAngleAndThetaBack) {
  const std::string arrays =
      "array c[3], r[1], th[1], ax[3], ang[1], w[1];\nc = [0, 0, 0];\nr = [1];\nax = [0, 0, 1];\nang = [30];\n"
      "w = [1];\n";
  auto after = [&](const std::string& theta, const std::string& value) {
    const FieldTape t = compileOk(model(arrays + "th = [" + theta + "];\nf = hfConvArc(x, c, r, th, ax, ang, w, 0);\n" +
                                        "g = hfConvArc(x, c, r, th, ax, ang, w, 0);\nmy_model = " + value + ";"));
    return testing::evaluateDouble(t, 0, 0, 0);
  };
  // Each call adds 1e-6 to ang[1] in the caller's array.
  EXPECT_NEAR(after("90", "(ang[1] - 30) * 1e6"), 2.0, 1e-6);
  // theta over 180 comes back as 180 (clamped to 360 first); 180 or less is left alone.
  EXPECT_EQ(after("270", "th[1]"), 180.0);
  EXPECT_EQ(after("400", "th[1]"), 180.0);
  EXPECT_EQ(after("120", "th[1]"), 120.0);
  // So a second call with the same arrays draws a 180-degree arc at angle 30 + 2e-6.
  const FieldTape t =
      compileOk(model(arrays + "th = [270];\nf = hfConvArc(x, c, r, th, ax, ang, w, 0);\n"
                               "my_model = hfConvArc(x, c, r, th, ax, ang, w, 0);"));
  Errors errors;
  expectAt(t, [](const P& x) { return arcIntegral(x, {0, 0, 0}, 1, 180, {0, 0, 1}, 30 + 1e-6, 1); },
           randomPoints(40, -1.5, 1.5, 4), 1e-5, errors);
}

TEST(HyperFunConvolution, ArcErrors) {
  const std::string arrays =
      "array c[3], r[1], th[1], ax[3], ang[1], w[1];\nc = [0, 0, 0];\nr = [1];\nax = [0, 0, 1];\nang = [30];\n"
      "w = [1];\n";
  expectHas(compileError(model(arrays + "th[1] = x[1];\nmy_model = hfConvArc(x, c, r, th, ax, ang, w, 0);")),
            "m.hf:9:31: error: item 1 of 'theta' (argument 4 of 'hfConvArc') depends on the point x; it must be known "
            "when the model is compiled (HyperFun clamps it to 360 and splits an arc over 180 degrees in two)");
  expectHas(compileError(model(arrays + "th = [-20];\nmy_model = hfConvArc(x, c, r, th, ax, ang, w, 0);")),
            "m.hf:9:31: error: item 1 of 'theta' (argument 4 of 'hfConvArc') is negative (-20)");
  expectHas(compileError(model(arrays + "th = [20];\nmy_model = hfConvArc(x, c, r, th, ang, ang, w, 0);")),
            "m.hf:9:35: error: 'axis' (argument 5 of 'hfConvArc') must be an array of 3 items; 'ang' has 1");
  expectHas(compileError(model(arrays + "th = [20];\nmy_model = hfConvArc(x, c, r, th, ax, ang, c, 0);")),
            "m.hf:9:25: error: 'center' (argument 2 of 'hfConvArc') must be an array of 9 items; 'c' has 3");
}

// --- hfConvLineR -------------------------------------------------------------------------------

// HyperFun's hfConvLineR: S = 1 for R >= 1, else 1/R; the segments' integrals summed and clamped
// to 1; minus one segment's integral at distance R from its begin point, perpendicular to it, for
// the last segment's length. With `scale`, the larger of the two terms instead (what the
// difference's error is relative to).
double lineR(const P& x, const std::vector<P>& begin, const std::vector<P>& end, double R, bool scale = false) {
  const double s = R >= 1 ? 1.0 : 1.0 / R;
  double sum = 0.0;
  for (size_t i = 0; i < begin.size(); ++i) sum += segmentIntegral(x, begin[i], end[i], s);
  const P& b = begin.back();
  const P dir = sub(end.back(), b);
  P side = cross(dir, {0.3, -0.7, 0.2});
  side = mul(side, R / std::sqrt(dot(side, side)));
  const double threshold = segmentIntegral(add(b, side), b, end.back(), s);
  return scale ? std::max(std::min(sum, 1.0), threshold) : std::min(sum, 1.0) - threshold;
}

TEST(HyperFunConvolution, LineRAgainstQuadrature) {
  const std::vector<P> b = {{-1, 0, 0}, {0, -1, 0.5}}, e = {{1, 0.5, 0}, {0, 0.2, -0.5}};
  const std::string arrays = "array b[6], e[6];\nb = [-1, 0, 0, 0, -1, 0.5];\ne = [1, 0.5, 0, 0, 0.2, -0.5];\n";
  Errors errors;
  for (double R : {0.4, 1.5}) {
    SCOPED_TRACE(R);
    const FieldTape t = compileOk(model(arrays + "my_model = hfConvLineR(x, b, e, " + std::to_string(R) + ");"));
    std::vector<P> points = randomPoints(100, -2.0, 2.0, 13);
    for (const P& p : {b[0], e[0], b[1], e[1], P{0, 0.2, 0}, P{20, -5, 3}}) points.push_back(p);
    expectAt(t, [&](const P& x) { return lineR(x, b, e, R); }, points, 1e-5, errors,
             [&](const P& x) { return lineR(x, b, e, R, true); });
  }
  // The threshold comes from the last segment: the same segments in the other order (lengths
  // 2.06 and 1.6) give another field.
  const FieldTape swapped = compileOk(model(
      "array b[6], e[6];\nb = [0, -1, 0.5, -1, 0, 0];\ne = [0, 0.2, -0.5, 1, 0.5, 0];\nmy_model = hfConvLineR(x, b, e, 1.5);"));
  const std::vector<P> b2 = {b[1], b[0]}, e2 = {e[1], e[0]};
  expectAt(swapped, [&](const P& x) { return lineR(x, b2, e2, 1.5); }, randomPoints(40, -2.0, 2.0, 17), 1e-5, errors,
           [&](const P& x) { return lineR(x, b2, e2, 1.5, true); });
  EXPECT_GT(std::fabs(lineR({0.3, 0.3, 0.3}, b, e, 1.5) - lineR({0.3, 0.3, 0.3}, b2, e2, 1.5)), 0.01);
}

TEST(HyperFunConvolution, LineRClampsTheSumAtOne) {
  // Three long segments through the origin: near them the integrals add up to more than 1.
  const FieldTape t = compileOk(
      model("array b[9], e[9];\nb = [-3, 0, 0, 0, -3, 0, 0, 0, -3];\ne = [3, 0, 0, 0, 3, 0, 0, 0, 3];\n"
            "my_model = hfConvLineR(x, b, e, 2);"));
  const std::vector<P> b = {{-3, 0, 0}, {0, -3, 0}, {0, 0, -3}}, e = {{3, 0, 0}, {0, 3, 0}, {0, 0, 3}};
  const double top = lineR({0, 0, 0}, b, e, 2);  // 1 - T
  EXPECT_GT(segmentIntegral({0, 0, 0}, b[0], e[0], 1) * 3, 1.5);
  Errors errors;
  expectAt(t, [&](const P& x) { return lineR(x, b, e, 2); },
           {{0, 0, 0}, {0.2, 0.1, 0}, {1, 0, 0}, {0.3, 0.3, 0.3}, {2, 2, 2}, {5, 0, 1}}, 1e-5, errors,
           [&](const P& x) { return lineR(x, b, e, 2, true); });
  EXPECT_NEAR(testing::evaluateDouble(t, 0.2, 0.1, 0), top, 1e-6);  // clamped: the same as at the origin
}

TEST(HyperFunConvolution, LineRErrors) {
  const std::string arrays = "array b[6], e[6], f[7];\nb = [-1, 0, 0, 0, -1, 0.5];\ne = [1, 0.5, 0, 0, 0.2, -0.5];\n"
                             "f = [0, 0, 0, 1, 1, 1, 2];\n";
  expectHas(compileError(model(arrays + "my_model = hfConvLineR(x, b, e, x[1]);")),
            "m.hf:6:33: error: 'R' (argument 4 of 'hfConvLineR') depends on the point x; it must be known when the "
            "model is compiled (HyperFun chooses the kernel's width S by comparing R with 1)");
  expectHas(compileError(model(arrays + "my_model = hfConvLineR(x, b, e, 0);")),
            "m.hf:6:33: error: 'R' (argument 4 of 'hfConvLineR') is 0");
  expectHas(compileError(model(arrays + "my_model = hfConvLineR(x, b, f, 1);")),
            "m.hf:6:30: error: 'end' (argument 3 of 'hfConvLineR') must hold 3 items per segment; 'f' has 7");
  expectHas(compileError(model(arrays + "my_model = hfConvLineR(x, x, e, 1);")),
            "m.hf:6:27: error: 'begin' (argument 2 of 'hfConvLineR') must be an array of 6 items; 'x' has 3");
}

// --- SARDF distance primitives -----------------------------------------------------------------

TEST(HyperFunConvolution, SardfDistancePrimitives) {
  const std::string centre = "array c[3], u[3];\nc = [0.3, -0.2, 0.1];\nu = [1, 2, -0.5];\n";
  const P c = {0.3, -0.2, 0.1};
  Errors errors;
  auto check = [&](const std::string& call, const Fn& want) {
    SCOPED_TRACE(call);
    std::vector<P> points = randomPoints(200, -2.5, 2.5, 21);
    expectAt(compileOk(model(centre + "my_model = " + call + ";")), want, points, 1e-5, errors,
             [&](const P& x) { return std::max(1.0, std::fabs(want(x))); });
  };
  auto torus = [](double along, double u, double v, double R, double r0) {
    return r0 - std::sqrt(sq(std::sqrt(u * u + v * v) - R) + along * along);
  };
  check("hfDTorusX(x, c, 1.2, 0.4)", [&](const P& x) { const P d = sub(x, c); return torus(d[0], d[1], d[2], 1.2, 0.4); });
  check("hfDTorusY(x, c, 1.2, 0.4)", [&](const P& x) { const P d = sub(x, c); return torus(d[1], d[0], d[2], 1.2, 0.4); });
  check("hfDTorusZ(x, c, 1.2, 0.4)", [&](const P& x) { const P d = sub(x, c); return torus(d[2], d[0], d[1], 1.2, 0.4); });
  check("hfDCylinder(x, c, u, 0.6)", [&](const P& x) {
    const P axis = {1, 2, -0.5}, d = sub(x, c);
    return 0.6 - std::sqrt(dot(d, d) - sq(dot(d, axis)) / dot(axis, axis));  // Pythagoras, not a cross product
  });
  auto cone = [](double along, double u, double v, double R) {
    const double t = std::atan(R);
    return std::fabs(along) * std::sin(t) - std::sqrt(u * u + v * v) * std::cos(t);
  };
  check("hfDConeX(x, c, 0.7)", [&](const P& x) { const P d = sub(x, c); return cone(d[0], d[1], d[2], 0.7); });
  check("hfDConeY(x, c, 0.7)", [&](const P& x) { const P d = sub(x, c); return cone(d[1], d[0], d[2], 0.7); });
  check("hfDConeZ(x, c, 0.7)", [&](const P& x) { const P d = sub(x, c); return cone(d[2], d[0], d[1], 0.7); });
  expectHas(compileError(model("array c[3], u[3];\nc = [0, 0, 0];\nu = [0, 0, 0];\nmy_model = hfDCylinder(x, c, u, 1);")),
            "m.hf:5:30: error: 'axis' (argument 3 of 'hfDCylinder') is the zero vector");
}

}  // namespace
}  // namespace pf::field
