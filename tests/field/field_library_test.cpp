// The field library written in the language (compiler/hyperfun.pfl, hyperfun_convolution.pfl)
// against the HyperFun reader (compiler/field/hyperfun_library.cpp, hyperfun_convolution.cpp): two
// implementations of HyperFun's library, one in the
// language and one building tapes in C++, must give the same field for the same model. Each case
// is a `field` unit and the HyperFun model it stands for; their tapes are evaluated in double at
// random points. (The reader's own tests check its formulas against hyperfun.md's in double.)
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "compiler/field/field_unit.h"
#include "compiler/field/hyperfun_reader.h"
#include "field/field_reference.h"

namespace pf::field {
namespace {

struct LibraryCase {
  const char* language;  // the body of `field float f(point p)`, returning the value
  const char* hyperfun;  // the body of `my_model(x[3], a[1])`, setting my_model
};

const LibraryCase kCases[] = {
    {"return hfSphere(p, point(0.2, -0.1, 0.3), 1.1);",
     "array c[3]; c = [0.2, -0.1, 0.3]; my_model = hfSphere(x, c, 1.1);"},
    {"return hfEllipsoid(p, point(0.1, 0.0, 0.0), 1.2, 0.7, 0.9);",
     "array c[3]; c = [0.1, 0, 0]; my_model = hfEllipsoid(x, c, 1.2, 0.7, 0.9);"},
    {"return hfCylinderX(p, point(0.0, 0.2, 0.0), 0.6) + hfCylinderY(p, point(0.1, 0.0, 0.0), 0.5) + hfCylinderZ(p, point(0.0, 0.0, 0.3), 0.4);",
     "array c[3], d[3], e[3]; c = [0, 0.2, 0]; d = [0.1, 0, 0]; e = [0, 0, 0.3];"
     "my_model = hfCylinderX(x, c, 0.6) + hfCylinderY(x, d, 0.5) + hfCylinderZ(x, e, 0.4);"},
    {"return hfEllCylX(p, point(0.0, 0.0, 0.0), 0.6, 0.8) - hfEllCylY(p, point(0.3, 0.0, 0.0), 0.5, 0.7) + hfEllCylZ(p, point(0.0, 0.1, 0.0), 0.9, 0.4);",
     "array c[3], d[3], e[3]; c = [0, 0, 0]; d = [0.3, 0, 0]; e = [0, 0.1, 0];"
     "my_model = hfEllCylX(x, c, 0.6, 0.8) - hfEllCylY(x, d, 0.5, 0.7) + hfEllCylZ(x, e, 0.9, 0.4);"},
    {"return hfTorusX(p, point(0.0, 0.0, 0.0), 1.0, 0.3) + hfTorusY(p, point(0.2, 0.0, 0.0), 0.8, 0.2) + hfTorusZ(p, point(0.0, 0.0, 0.1), 1.2, 0.4);",
     "array c[3], d[3], e[3]; c = [0, 0, 0]; d = [0.2, 0, 0]; e = [0, 0, 0.1];"
     "my_model = hfTorusX(x, c, 1.0, 0.3) + hfTorusY(x, d, 0.8, 0.2) + hfTorusZ(x, e, 1.2, 0.4);"},
    {"return hfBlock(p, point(-0.5, -0.4, -0.3), 1.0, 0.8, 0.6);",
     "array v[3]; v = [-0.5, -0.4, -0.3]; my_model = hfBlock(x, v, 1.0, 0.8, 0.6);"},
    {"return hfConeX(p, point(0.0, 0.0, 0.0), 0.5) + hfConeY(p, point(0.1, 0.0, 0.0), 0.7) + hfConeZ(p, point(0.0, 0.2, 0.0), 0.9);",
     "array c[3], d[3], e[3]; c = [0, 0, 0]; d = [0.1, 0, 0]; e = [0, 0.2, 0];"
     "my_model = hfConeX(x, c, 0.5) + hfConeY(x, d, 0.7) + hfConeZ(x, e, 0.9);"},
    {"return hfEllConeX(p, point(0.0, 0.0, 0.0), 0.5, 0.6) + hfEllConeY(p, point(0.0, 0.0, 0.0), 0.7, 0.4) + hfEllConeZ(p, point(0.0, 0.0, 0.0), 0.9, 1.1);",
     "array c[3]; c = [0, 0, 0];"
     "my_model = hfEllConeX(x, c, 0.5, 0.6) + hfEllConeY(x, c, 0.7, 0.4) + hfEllConeZ(x, c, 0.9, 1.1);"},
    {"return hfSuperEll(p, point(0.0, 0.1, 0.0), 1.0, 0.8, 0.9, 0.5, 1.5);",
     "array c[3]; c = [0, 0.1, 0]; my_model = hfSuperEll(x, c, 1.0, 0.8, 0.9, 0.5, 1.5);"},
    {"return hfSphere(p, point(0.0, 0.0, 0.0), 1.0) + hfNoiseG(p, 0.3, 2.0, 1.4);",
     "array c[3]; c = [0, 0, 0]; my_model = hfSphere(x, c, 1.0) + hfNoiseG(x, 0.3, 2.0, 1.4);"},
    {"float s = hfSphere(p, point(0.3, 0.0, 0.0), 0.8); float t = hfSphere(p, point(-0.3, 0.0, 0.0), 0.7);"
     "return hfUnion(s, t) + hfIntersect(s, t) - hfSubtract(s, t) + hfProduct(t, s) + hfNegate(s);",
     "array c[3], d[3]; c = [0.3, 0, 0]; d = [-0.3, 0, 0]; f1 = hfSphere(x, c, 0.8); f2 = hfSphere(x, d, 0.7);"
     "my_model = (f1 | f2) + (f1 & f2) - (f1 \\ f2) + (f2 @ f1) + ~f1;"},
    {"float s = hfSphere(p, point(0.3, 0.0, 0.0), 0.8); float t = hfSphere(p, point(-0.3, 0.0, 0.0), 0.7);"
     "return hfBlendUni(s, t, 0.5, 1.0, 1.0) + hfBlendInt(s, t, -0.3, 0.8, 1.2);",
     "array c[3], d[3]; c = [0.3, 0, 0]; d = [-0.3, 0, 0]; f1 = hfSphere(x, c, 0.8); f2 = hfSphere(x, d, 0.7);"
     "my_model = hfBlendUni(f1, f2, 0.5, 1.0, 1.0) + hfBlendInt(f1, f2, -0.3, 0.8, 1.2);"},
    {"float s = 0.0;"
     "s += hfBlobbyTerm(p, point(-0.5, 0.0, 0.0), 2.0, 1.0);"
     "s += hfBlobbyTerm(p, point(0.5, 0.2, 0.0), 3.0, 0.5);"
     "return s - 0.3;",
     "array x0[2], y0[2], z0[2], a1[2], b[2]; x0 = [-0.5, 0.5]; y0 = [0, 0.2]; z0 = [0, 0]; a1 = [2, 3]; b = [1, 0.5];"
     "my_model = hfBlobby(x, x0, y0, z0, a1, b, 0.3);"},
    {"return hfMetaballTerm(p, point(-0.5, 0.0, 0.0), 1.2, 2.0) + hfMetaballTerm(p, point(0.5, 0.2, 0.0), 0.8, 1.5) - 0.25;",
     "array x0[2], y0[2], z0[2], b[2], d[2]; x0 = [-0.5, 0.5]; y0 = [0, 0.2]; z0 = [0, 0]; b = [1.2, 0.8]; d = [2, 1.5];"
     "my_model = hfMetaball(x, x0, y0, z0, b, d, 0.25);"},
    {"return hfSoftTerm(p, point(-0.5, 0.0, 0.0), 2.0) + hfSoftTerm(p, point(0.5, 0.2, 0.0), 1.5) - 0.2;",
     "array x0[2], y0[2], z0[2], d[2]; x0 = [-0.5, 0.5]; y0 = [0, 0.2]; z0 = [0, 0]; d = [2, 1.5];"
     "my_model = hfSoft(x, x0, y0, z0, d, 0.2);"},
    {"return hfConvLineTerm(p, point(-1.0, 0.0, 0.0), point(1.0, 0.5, 0.0), 1.5)"
     " + hfConvLineTerm(p, point(0.0, -1.0, 0.5), point(0.0, 1.0, -0.5), 0.8) - 0.3;",
     "array b[6], e[6], w[2]; b = [-1, 0, 0, 0, -1, 0.5]; e = [1, 0.5, 0, 0, 1, -0.5]; w = [1.5, 0.8];"
     "my_model = hfConvLine(x, b, e, w, 0.3);"},
    {"return hfConvPointTerm(p, point(-0.5, 0.0, 0.0), 1.5) + hfConvPointTerm(p, point(0.5, 0.2, 0.1), 2.0) - 0.4;",
     "array v[6], w[2]; v = [-0.5, 0, 0, 0.5, 0.2, 0.1]; w = [1.5, 2.0];"
     "my_model = hfConvPoint(x, v, w, 0.4);"},
    {"return hfConvTriangleTerm(p, point(-1.0, -0.5, 0.2), point(1.2, -0.3, -0.1), point(0.1, 1.0, 0.4), 1.5)"
     " + hfConvTriangleTerm(p, point(0.3, 0.2, -1.0), point(0.5, -0.6, 0.8), point(-0.7, 0.4, 0.5), 0.8) - 0.1;",
     "array v[18], w[2]; v = [-1, -0.5, 0.2, 1.2, -0.3, -0.1, 0.1, 1, 0.4, 0.3, 0.2, -1, 0.5, -0.6, 0.8, -0.7, 0.4, 0.5];"
     "w = [1.5, 0.8]; my_model = hfConvTriangle(x, v, w, 0.1);"},
    {"return hfConvTriangleTerm(p, point(0.0, 0.0, 0.0), point(1.0, 0.0, 0.0), point(0.0, 1.0, 0.0), 2.0)"
     " + hfConvTriangleTerm(p, point(1.0, 0.0, 0.0), point(0.0, 0.0, 1.0), point(0.0, 1.0, 0.0), 1.2)"
     " + hfConvTriangleTerm(p, point(0.0, 0.0, 0.0), point(1.0, 0.0, 0.0), point(2.0, 0.0, 0.0), 1.2) - 0.3;",
     "array v[12], t[9], w[3]; v = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]; t = [1, 2, 3, 2, 4, 3, 1, 2, 2];"
     "w = [2, 1.2, 1.2]; my_model = hfConvMesh(x, v, t, w, 0.3);"},
    {"return hfConvArcTerm(p, point(0.1, -0.2, 0.3), 1.1, 100.0, vector(0.3, 0.5, 1.0), 35.0, 1.3)"
     " + hfConvArcTerm(p, point(-0.5, 0.4, 0.0), 0.7, 250.0, vector(1.0, 0.0, 0.0), -60.0, 2.0)"
     " + hfConvArcTerm(p, point(0.6, 0.1, -0.4), 0.5, 400.0, vector(-0.2, 1.0, 0.4), 120.0, 0.9) - 0.2;",
     "array c[9], r[3], th[3], ax[9], ang[3], w[3]; c = [0.1, -0.2, 0.3, -0.5, 0.4, 0, 0.6, 0.1, -0.4];"
     "r = [1.1, 0.7, 0.5]; th = [100, 250, 400]; ax = [0.3, 0.5, 1, 1, 0, 0, -0.2, 1, 0.4]; ang = [35, -60, 120];"
     "w = [1.3, 2.0, 0.9]; my_model = hfConvArc(x, c, r, th, ax, ang, w, 0.2);"},
    {"float S = hfConvLineRWidth(0.4);"
     "return min(hfConvLineTerm(p, point(-1.0, 0.0, 0.0), point(1.0, 0.5, 0.0), S)"
     " + hfConvLineTerm(p, point(0.0, -1.0, 0.5), point(0.0, 0.2, -0.5), S), 1.0) - hfConvLineRThreshold(0.4, length(vector(0.0, 1.2, -1.0)));",
     "array b[6], e[6]; b = [-1, 0, 0, 0, -1, 0.5]; e = [1, 0.5, 0, 0, 0.2, -0.5]; my_model = hfConvLineR(x, b, e, 0.4);"},
    {"float S = hfConvLineRWidth(2.0);"  // the sum passes 1 near the origin only
     "return min(hfConvLineTerm(p, point(-1.0, 0.0, 0.0), point(1.0, 0.0, 0.0), S) + hfConvLineTerm(p, point(0.0, -1.0, 0.0), point(0.0, 1.0, 0.0), S)"
     " + hfConvLineTerm(p, point(0.0, 0.0, -0.7), point(0.0, 0.0, 0.7), S), 1.0) - hfConvLineRThreshold(2.0, 1.4);",
     "array b[9], e[9]; b = [-1, 0, 0, 0, -1, 0, 0, 0, -0.7]; e = [1, 0, 0, 0, 1, 0, 0, 0, 0.7]; my_model = hfConvLineR(x, b, e, 2);"},
    {"return hfDTorusX(p, point(0.0, 0.1, 0.0), 1.0, 0.3) + hfDTorusY(p, point(0.2, 0.0, 0.0), 0.8, 0.2) + hfDTorusZ(p, point(0.0, 0.0, 0.1), 1.2, 0.4)"
     " + hfDCylinder(p, point(0.1, -0.2, 0.3), vector(1.0, 2.0, -0.5), 0.6)"
     " + hfDConeX(p, point(0.0, 0.0, 0.0), 0.5) + hfDConeY(p, point(0.2, 0.0, 0.0), 0.7) + hfDConeZ(p, point(0.0, 0.2, 0.0), 1.9);",
     "array c[3], d[3], e[3], f[3], u[3], g[3], h[3]; c = [0, 0.1, 0]; d = [0.2, 0, 0]; e = [0, 0, 0.1]; f = [0.1, -0.2, 0.3];"
     "u = [1, 2, -0.5]; g = [0, 0, 0]; h = [0, 0.2, 0];"
     "my_model = hfDTorusX(x, c, 1.0, 0.3) + hfDTorusY(x, d, 0.8, 0.2) + hfDTorusZ(x, e, 1.2, 0.4) + hfDCylinder(x, f, u, 0.6)"
     " + hfDConeX(x, g, 0.5) + hfDConeY(x, d, 0.7) + hfDConeZ(x, h, 1.9);"},
    {"point q = hfShift3D(p, 0.2, -0.1, 0.3); q = hfScale3D(q, 1.5, 0.8, 1.2); q = hfStretch3D(q, point(0.1, 0.0, 0.0), 1.1, 0.9, 1.3);"
     "return hfEllipsoid(q, point(0.0, 0.0, 0.0), 1.0, 0.6, 0.8);",
     "array xt[3], c[3], o[3]; xt[1] = x[1]; xt[2] = x[2]; xt[3] = x[3]; c = [0, 0, 0]; o = [0.1, 0, 0];"
     "dummy = hfShift3D(xt, 0.2, -0.1, 0.3); dummy = hfScale3D(xt, 1.5, 0.8, 1.2); dummy = hfStretch3D(xt, o, 1.1, 0.9, 1.3);"
     "my_model = hfEllipsoid(xt, c, 1.0, 0.6, 0.8);"},
    {"point q = hfRotate3DX(p, 0.4); q = hfRotate3DY(q, -0.7); q = hfRotate3DZ(q, 1.1);"
     "return hfBlock(q, point(-0.5, -0.4, -0.3), 1.0, 0.8, 0.6);",
     "array xt[3], v[3]; xt[1] = x[1]; xt[2] = x[2]; xt[3] = x[3]; v = [-0.5, -0.4, -0.3];"
     "dummy = hfRotate3DX(xt, 0.4); dummy = hfRotate3DY(xt, -0.7); dummy = hfRotate3DZ(xt, 1.1);"
     "my_model = hfBlock(xt, v, 1.0, 0.8, 0.6);"},
    {"point q = hfTwistX(p, -1.0, 1.0, 0.0, 1.0); q = hfTwistY(q, -1.0, 1.0, 0.3, -0.5); q = hfTwistZ(q, -1.0, 1.5, -0.2, 0.9);"
     "return hfBlock(q, point(-0.5, -0.4, -0.3), 1.0, 0.8, 0.6);",
     "array xt[3], v[3]; xt[1] = x[1]; xt[2] = x[2]; xt[3] = x[3]; v = [-0.5, -0.4, -0.3];"
     "dummy = hfTwistX(xt, -1.0, 1.0, 0.0, 1.0); dummy = hfTwistY(xt, -1.0, 1.0, 0.3, -0.5); dummy = hfTwistZ(xt, -1.0, 1.5, -0.2, 0.9);"
     "my_model = hfBlock(xt, v, 1.0, 0.8, 0.6);"},
    {"point q = hfTaperX(p, -1.0, 1.0, 0.5, 1.5); q = hfTaperY(q, -0.5, 1.0, 1.2, 0.7); q = hfTaperZ(q, -1.0, 0.5, 0.8, 1.1);"
     "return hfSphere(q, point(0.0, 0.0, 0.0), 0.9);",
     "array xt[3], c[3]; xt[1] = x[1]; xt[2] = x[2]; xt[3] = x[3]; c = [0, 0, 0];"
     "dummy = hfTaperX(xt, -1.0, 1.0, 0.5, 1.5); dummy = hfTaperY(xt, -0.5, 1.0, 1.2, 0.7); dummy = hfTaperZ(xt, -1.0, 0.5, 0.8, 1.1);"
     "my_model = hfSphere(xt, c, 0.9);"},
    {"point q = hfSpaceMapExpStep(p, point(0.0, 0.0, 0.0), point(0.3, 0.2, 0.0), vector(0.5, 0.6, 0.7));"
     "q = hfSpaceMapExpStep(q, point(0.5, 0.0, 0.0), point(0.4, -0.3, 0.1), vector(0.8, 0.5, 0.4));"
     "return hfSphere(q, point(0.0, 0.0, 0.0), 0.9);",
     "array xt[3], c[3], src[6], tgt[6], b[6]; xt[1] = x[1]; xt[2] = x[2]; xt[3] = x[3]; c = [0, 0, 0]; src = [0, 0, 0, 0.5, 0, 0]; tgt = [0.3, 0.2, 0, 0.4, -0.3, 0.1];"
     "b = [0.5, 0.6, 0.7, 0.8, 0.5, 0.4]; dummy = hfSpaceMapExp(xt, src, tgt, b); my_model = hfSphere(xt, c, 0.9);"},
    {"point q = hfSpaceMapCubicStep(p, point(0.0, 0.0, 0.0), point(0.3, 0.2, 0.0), vector(1.5, 1.6, 1.7));"
     "return hfSphere(q, point(0.0, 0.0, 0.0), 0.9);",
     "array xt[3], c[3], src[3], tgt[3], b[3]; xt[1] = x[1]; xt[2] = x[2]; xt[3] = x[3]; c = [0, 0, 0]; src = [0, 0, 0]; tgt = [0.3, 0.2, 0];"
     "b = [1.5, 1.6, 1.7]; dummy = hfSpaceMapCubic(xt, src, tgt, b); my_model = hfSphere(xt, c, 0.9);"},
    // SARDF operations: operands that take every quadrant and both the bounded and the stripe
    // pieces over [-1.6, 1.6]^3; hfSign of the point (a Select in both).
    {"return hfDUni(p.x, p.y, 0.4, 0.3) + hfDInt(p.y - 0.2, p.z, 0.5, 0.25) + hfDSub(p.x + p.z, p.y, 0.3, 0.35)"
     " + hfDBlendUni(p.x, p.z, 0.5) + hfDBlendInt(p.y, p.x, 0.6) + hfSign(p.z - 0.1);",
     "my_model = hfDUni(x[1], x[2], 0.4, 0.3) + hfDInt(x[2] - 0.2, x[3], 0.5, 0.25) + hfDSub(x[1] + x[3], x[2], 0.3, 0.35)"
     " + hfDBlendUni(x[1], x[3], 0.5) + hfDBlendInt(x[2], x[1], 0.6) + sign(x[3] - 0.1);"},
    {"return hfDEllipsoid(p, point(0.1, -0.2, 0.0), 1.2, 0.5, 0.8);",
     "array c[3]; c = [0.1, -0.2, 0]; my_model = hfDEllipsoid(x, c, 1.2, 0.5, 0.8);"},
    {"return hfPow(p.x, 3.0) - hfPow(abs(p.y) + 0.5, 0.7) + hfLogd(p.z * p.z + 1.0) + hfTan(p.x * 0.4) + hfSinh(p.y) - hfCosh(p.z * 0.5) + hfTanh(p.x);",
     "my_model = x[1]^3 - (abs(x[2]) + 0.5)^0.7 + logd(x[3]*x[3] + 1) + tan(x[1]*0.4) + sinh(x[2]) - cosh(x[3]*0.5) + tanh(x[1]);"},
};

TEST(FieldLibrary, EveryFunctionMatchesTheHyperFunReader) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  for (const LibraryCase& c : kCases) {
    SCOPED_TRACE(c.language);
    DiagnosticLog log;
    const std::string language = std::string("field float f(point p) {\n") + c.language + "\n}\n";
    const auto mine = compileFieldUnit("lib.pfl", language, "", {}, log);
    const std::string hyperfun = std::string("my_model(x[3], a[1]) {\n") + c.hyperfun + "\n}\n";
    const auto theirs = readHyperFunModel("lib.hf", hyperfun, log, {}, "my_model");
    ASSERT_TRUE(mine && theirs) << log.format();
    int compared = 0;
    for (int i = 0; i < 400; ++i) {
      const double x = static_cast<float>(u(rng)), y = static_cast<float>(u(rng)), z = static_cast<float>(u(rng));
      const double want = testing::evaluateDouble(*theirs, x, y, z);
      const double got = testing::evaluateDouble(*mine, x, y, z);
      if (!std::isfinite(want)) {
        EXPECT_FALSE(std::isfinite(got) && std::fabs(got) < 1e30) << "at " << x << ", " << y << ", " << z;
        continue;
      }
      ASSERT_NEAR(got, want, 2e-5 * std::max(1.0, std::fabs(want))) << "at " << x << ", " << y << ", " << z;
      ++compared;
    }
    EXPECT_GT(compared, 300);
  }
}

}  // namespace
}  // namespace pf::field
