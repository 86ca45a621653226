// The extension's own conformance cases (no OSMesa counterpart): each renders with primflow and
// judges the result against a reference computed here in double precision (an image where
// there is one, for the report), or against the error codes and log text the API promises.
#include <primflow/gl.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "conformance.h"

namespace pfconf {

namespace {

constexpr int kSize = 64;

// A primflow context over an image of kSize x kSize, cleared to the suite's clear colour, with
// window coordinates = object x, y (glOrtho) unless the case sets its own projection.
struct Canvas {
  Image image;
  PFcontext ctx = nullptr;
  Canvas() {
    image.width = image.height = kSize;
    image.rgba.assign(static_cast<size_t>(kSize) * kSize * 4, 0);
    ctx = pfCreateContext(GL_RGBA, 24);
    image.ok = ctx && pfMakeCurrent(ctx, image.rgba.data(), GL_UNSIGNED_BYTE, kSize, kSize);
    pfglClearColor(kClear[0] / 255.0f, kClear[1] / 255.0f, kClear[2] / 255.0f, kClear[3] / 255.0f);
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    pfglMatrixMode(GL_PROJECTION);
    pfglOrtho(0, kSize, 0, kSize, -1, 1);
    pfglMatrixMode(GL_MODELVIEW);
  }
  ~Canvas() {
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx);
  }
  void finish() { pfglFinish(); }
};

// An image of the clear colour, to paint a reference into.
Image blankReference() {
  Image img;
  img.width = img.height = kSize;
  img.ok = true;
  img.rgba.resize(static_cast<size_t>(kSize) * kSize * 4);
  for (size_t i = 0; i < img.rgba.size(); i += 4) std::copy(kClear, kClear + 4, img.rgba.begin() + static_cast<long>(i));
  return img;
}

void put(Image& img, int x, int y, double r, double g, double b) {
  uint8_t* p = &img.rgba[(static_cast<size_t>(y) * kSize + x) * 4];
  p[0] = static_cast<uint8_t>(std::lround(std::clamp(r, 0.0, 1.0) * 255));
  p[1] = static_cast<uint8_t>(std::lround(std::clamp(g, 0.0, 1.0) * 255));
  p[2] = static_cast<uint8_t>(std::lround(std::clamp(b, 0.0, 1.0) * 255));
  p[3] = 255;
}

// Compares the canvas with the reference: every pixel within `tolerance` per channel except
// those `skip` excuses (pixels too close to an edge for a double-precision reference to decide).
void judgeImages(Result& r, const Image& reference, const Image& actual, int tolerance,
                 const std::function<bool(int, int)>& skip = nullptr) {
  r.reference = reference;
  r.actual = actual;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (skip && skip(x, y)) continue;
      const size_t i = (static_cast<size_t>(y) * kSize + x) * 4;
      int d = 0;
      for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(reference.rgba[i + c]) - int(actual.rgba[i + c])));
      r.max_colour_error = std::max(r.max_colour_error, d);
      if (d > tolerance && r.pixels_off++ < 5)
        r.detail += "(" + std::to_string(x) + ", " + std::to_string(y) + ") off by " + std::to_string(d) + "\n";
    }
  r.status = r.pixels_off == 0 ? Result::Status::Pass : Result::Status::Fail;
}

void expectError(Result& r, GLenum want, const char* after) {
  const GLenum got = pfglGetError();
  if (got != want) {
    r.status = Result::Status::Fail;
    char buf[128];
    std::snprintf(buf, sizeof buf, "after %s: error 0x%x, expected 0x%x\n", after, got, want);
    r.detail += buf;
  }
}

const char* kDisk =
    "primitive disk(point center[1]; float radius[1]; interpolator_data d[1]; inout varying float Z) {\n"
    "  point c = screen(center[0]);\n"
    "  float cx = c.x / c.w;\n"
    "  float cy = c.y / c.w;\n"
    "  bound(cx - radius[0], cy - radius[0], cx + radius[0], cy + radius[0]);\n"
    "  if ((X - cx) * (X - cx) + (Y - cy) * (Y - cy) >= radius[0] * radius[0]) return;\n"
    "  Z = 0.5;\n"
    "  interpolation { perspective_linear: linear: interpolator_return(d[0]); default: interpolator_return; }\n"
    "}\n";

// Figure 3: many disks in one glBegin, centre and radius bound per sequence point.
void sequencePoints(Result& r) {
  r.status = Result::Status::Pass;
  Canvas c;
  if (!pfglCompilePrimitivesEXT(kDisk)) return void(r.detail = "the disk primitive did not compile");
  const GLuint center = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
  struct Disk { double x, y, r, g; } disks[] = {{20.25, 18.5, 13.5, 0.2}, {44.0, 40.75, 9.0, 0.6}, {30.5, 50.0, 6.25, 1.0}};
  pfglBegin(pfglGetPrimitiveEXT("disk"));
  for (const Disk& d : disks) {
    pfglColor3f(1.0f, static_cast<float>(d.g), 0.25f);
    pfglRastParamfEXT(radius, static_cast<float>(d.r));
    pfglRastParam3fEXT(center, static_cast<float>(d.x), static_cast<float>(d.y), 0.0f);
    pfglSequencePointEXT();
  }
  pfglEnd();
  c.finish();
  expectError(r, GL_NO_ERROR, "drawing");
  Image ref = blankReference();
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (const Disk& d : disks)  // later disks are drawn over earlier ones (depth test off)
        if ((x + 0.5 - d.x) * (x + 0.5 - d.x) + (y + 0.5 - d.y) * (y + 0.5 - d.y) < d.r * d.r) put(ref, x, y, 1.0, d.g, 0.25);
  const Result::Status errors = r.status;
  judgeImages(r, ref, c.image, 1);
  if (errors == Result::Status::Fail) r.status = errors;
}

// The colour of a receding triangle interpolated each way pfglMaterialInterpEXT offers.
void interpolatorKinds(Result& r) {
  static const double tri[3][3] = {{-0.9, -0.9, -1.2}, {2.5, -2.0, -8.0}, {-0.5, 0.9, -1.5}};
  Image ref = blankReference(), actual;
  bool first = true;
  for (GLenum kind : {GL_PERSPECTIVE_LINEAR_INTERPOLATOR_EXT, GL_LINEAR_INTERPOLATOR_EXT}) {
    Canvas c;
    pfglMatrixMode(GL_PROJECTION);
    pfglLoadIdentity();
    pfglFrustum(-1, 1, -1, 1, 1, 10);
    pfglMatrixMode(GL_MODELVIEW);
    pfglMaterialInterpEXT(pfglGetParamNameEXT("color"), GL_TRIANGLES, kind);
    pfglBegin(GL_TRIANGLES);
    for (int i = 0; i < 3; ++i) {
      pfglColor3f(i == 1 ? 1.0f : 0.0f, 0.0f, 1.0f);
      pfglVertex3d(tri[i][0], tri[i][1], tri[i][2]);
    }
    pfglEnd();
    c.finish();
    // Reference: window-space barycentrics, weighted by 1/w for perspective-correct.
    Image expect = blankReference();
    double wx[3], wy[3], w[3];
    for (int i = 0; i < 3; ++i) {
      w[i] = -tri[i][2];
      wx[i] = (tri[i][0] / w[i] * 0.5 + 0.5) * kSize;
      wy[i] = (tri[i][1] / w[i] * 0.5 + 0.5) * kSize;
    }
    auto lambdas = [&](int x, int y, double l[3]) {
      const double px = x + 0.5, py = y + 0.5;
      const double area = (wx[1] - wx[0]) * (wy[2] - wy[0]) - (wx[2] - wx[0]) * (wy[1] - wy[0]);
      l[0] = ((wx[1] - px) * (wy[2] - py) - (wx[2] - px) * (wy[1] - py)) / area;
      l[1] = ((wx[2] - px) * (wy[0] - py) - (wx[0] - px) * (wy[2] - py)) / area;
      l[2] = 1 - l[0] - l[1];
    };
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        double l[3];
        lambdas(x, y, l);
        if (l[0] <= 0 || l[1] <= 0 || l[2] <= 0) continue;
        const double red = kind == GL_LINEAR_INTERPOLATOR_EXT ? l[1] : (l[1] / w[1]) / (l[0] / w[0] + l[1] / w[1] + l[2] / w[2]);
        put(expect, x, y, red, 0.0, 1.0);
      }
    // Pixels within 0.02 of an edge are the rasterizer's to decide; the rest are judged.
    Result one;
    judgeImages(one, expect, c.image, 1, [&](int x, int y) {
      double l[3];
      lambdas(x, y, l);
      return std::min({l[0], l[1], l[2]}) < 0.02;
    });
    r.max_colour_error = std::max(r.max_colour_error, one.max_colour_error);
    r.pixels_off += one.pixels_off;
    r.detail += one.detail;
    if (first) {
      ref = expect;
      actual = c.image;
      first = false;
    }
  }
  r.reference = ref;
  r.actual = actual;
  r.status = r.pixels_off == 0 ? Result::Status::Pass : Result::Status::Fail;
}

// A shared interpolator of P gives the same colour at the same surface point on a triangle and
// on a point primitive.
void sharedInterpolatorSamePoint(Result& r) {
  r.status = Result::Status::Pass;
  // The triangle (2, 3), (62, 8), (20, 61); a probe is a pixel whose centre is well inside it.
  auto inside = [](double x, double y) {
    auto edge = [&](double ax, double ay, double bx, double by) { return (bx - ax) * (y - ay) - (by - ay) * (x - ax); };
    return edge(2, 3, 62, 8) > 30 && edge(62, 8, 20, 61) > 30 && edge(20, 61, 2, 3) > 30;
  };
  const char* src = "interpolator eye_rgb(float s) { interpolator_return(color(0.5 + P.x * s, 0.5 + P.y * s, 0.3, 1.0)); }";
  Image tri_image, point_image;
  std::vector<std::pair<int, int>> probes;
  for (int pass = 0; pass < 2; ++pass) {
    Canvas c;
    if (!pfglCompilePrimitivesEXT(src)) return void(r.detail = "the interpolator did not compile");
    const GLenum interp = pfglGetInterpolatorEXT("eye_rgb");
    pfglMaterialInterpEXT(pfglGetParamNameEXT("color"), pass == 0 ? GL_TRIANGLES : GL_POINTS, interp);
    pfglRastParamfEXT(pfglGetParamNameEXT("s"), 1.0f / 64.0f);
    pfglBegin(pass == 0 ? GL_TRIANGLES : GL_POINTS);
    if (pass == 0) {
      pfglVertex2f(2, 3);
      pfglVertex2f(62, 8);
      pfglVertex2f(20, 61);
    } else {
      for (int y = 4; y < 60; y += 5)
        for (int x = 3; x < 60; x += 5) {
          if (!inside(x + 0.5, y + 0.5)) continue;
          pfglVertex2f(x + 0.5f, y + 0.5f);  // the surface point under pixel (x, y)'s centre
          probes.push_back({x, y});
        }
    }
    pfglEnd();
    c.finish();
    expectError(r, GL_NO_ERROR, "drawing");
    (pass == 0 ? tri_image : point_image) = c.image;
  }
  // Only the probed pixels (all inside the triangle) are compared.
  Image ref = blankReference();
  for (auto [x, y] : probes)
    std::copy_n(&tri_image.rgba[(static_cast<size_t>(y) * kSize + x) * 4], 4, &ref.rgba[(static_cast<size_t>(y) * kSize + x) * 4]);
  const Result::Status errors = r.status;
  judgeImages(r, ref, point_image, 1);
  if (errors == Result::Status::Fail) r.status = errors;
}

// Compile errors come back through pfglGetCompileLogEXT with file:line:col.
void compileErrors(Result& r) {
  Canvas c;
  const GLuint id = pfglCompilePrimitivesEXT("primitive p(point vertex[1]) {\n  float a = 1.0;\n  a = b + 2.0;\n}\n");
  char log[1024] = {0};
  GLsizei len = 0;
  pfglGetCompileLogEXT(0, sizeof log, &len, log);
  const std::string text(log, static_cast<size_t>(len));
  r.status = id == 0 && text.find(":3:7: error: 'b' is not declared") != std::string::npos ? Result::Status::Pass
                                                                                             : Result::Status::Fail;
  r.detail = "log: " + text;
}

// An instance whose parameters do not fit draws nothing and sets GL_INVALID_OPERATION.
void rejectedInstance(Result& r) {
  Canvas c;
  if (!pfglCompilePrimitivesEXT(kDisk)) return void(r.detail = "the disk primitive did not compile");
  r.status = Result::Status::Pass;
  pfglBegin(pfglGetPrimitiveEXT("disk"));
  pfglRastParam3fEXT(pfglGetParamNameEXT("center"), 32, 32, 0);
  pfglRastParam3fEXT(pfglGetParamNameEXT("radius"), 10, 10, 10);  // a float given three values
  pfglSequencePointEXT();
  pfglEnd();
  c.finish();
  expectError(r, GL_INVALID_OPERATION, "a mistyped radius");
  judgeImages(r, blankReference(), c.image, 0);
  if (r.pixels_off) r.detail += "the rejected instance drew\n";
}

// A runaway loop is stopped by the iteration cap and reported.
void iterationCap(Result& r) {
  Canvas c;
  if (!pfglCompilePrimitivesEXT("primitive spin(point vertex[1]; inout varying float Z) {\n"
                                "  float v = 0.0;\n  while (X > 32.0) v = v + 1.0;\n  Z = 0.5;\n}\n"))
    return void(r.detail = "spin did not compile");
  r.status = Result::Status::Pass;
  pfglEnable(GL_DEPTH_TEST);
  pfglBegin(pfglGetPrimitiveEXT("spin"));
  pfglVertex2f(0, 0);
  pfglEnd();
  c.finish();
  expectError(r, GL_TOO_MANY_ITERATIONS_EXT, "a runaway loop");
  GLint w, h, b;
  void* d = nullptr;
  if (!pfGetDepthBuffer(c.ctx, &w, &h, &b, &d)) return void(r.status = Result::Status::Fail);
  const float* z = static_cast<const float*>(d);
  for (int x = 0; x < kSize; ++x)
    if (z[x] != (x < 32 ? 0.5f : 1.0f)) {
      r.status = Result::Status::Fail;
      r.detail += "depth at x = " + std::to_string(x) + " is " + std::to_string(z[x]) + "\n";
      break;
    }
}

}  // namespace

const std::vector<ExtensionCase>& extensionCases() {
  static const std::vector<ExtensionCase> cases = {
      {"ext_sequence_points", "figure 3: disks with centre and radius bound per sequence point", sequencePoints},
      {"ext_interpolator_kinds", "pfglMaterialInterpEXT: perspective-linear and linear colour on a receding triangle", interpolatorKinds},
      {"ext_shared_interpolator", "a shared interpolator gives one value at one surface point on two primitives", sharedInterpolatorSamePoint},
      {"ext_compile_errors", "compile errors with line and column through pfglGetCompileLogEXT", compileErrors},
      {"ext_rejected_instance", "mismatched parameters: GL_INVALID_OPERATION, nothing drawn", rejectedInstance},
      {"ext_iteration_cap", "a runaway primitive stopped by the iteration cap and reported", iterationCap},
  };
  return cases;
}

}  // namespace pfconf
