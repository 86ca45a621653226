// HyperFun's attribute patterns, tables and colour spaces (hfA_CheckerBoard, Circles, Crackles,
// NoiseG, LookUpTable, SmoothLookUpTable, Spline, RGBToHSV, HSVToRGB, and hfA_Floor / hfA_Modulo
// on the point): each attribute tape, evaluated in double, against HyperFun's C code written out
// here in double at random points (away from the steps where float and double may differ); misuse
// at file:line:col.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "field/hyperfun_attribute_helpers.h"

namespace pf::field {
namespace {

using namespace attribute_testing;

// Within `e` of an integer.
bool nearInteger(double v, double e) { return std::fabs(v - std::round(v)) < e; }

TEST(HyperFunAttributePatterns, FloorAndModuloOfThePointTruncateAsHyperFunsIntCast) {
  // hfA_Floor is C's (int) cast (towards 0); hfA_Modulo(a, b) = a - b (int)(a/b), + b if negative.
  auto modulo = [](double a, double b) {
    const double r = a - b * std::trunc(a / b);
    return r < 0 ? r + b : r;
  };
  expectAttributes(model("s[1] = hfA_Floor(2*x[1]);\ns[2] = hfA_Modulo(3*x[2], 0.75);\ns[3] = hfA_Modulo(x[3], -0.625);"),
                   [&](double x, double y, double z) {
                     return std::vector<double>{std::trunc(2 * x), modulo(3 * y, 0.75), modulo(z, -0.625)};
                   },
                   [](double x, double y, double z) {
                     return nearInteger(2 * x, 1e-5) || nearInteger(3 * y / 0.75, 1e-5) || nearInteger(z / 0.625, 1e-5);
                   });
}

TEST(HyperFunAttributePatterns, CheckerBoardColoursTheBlocksOfEachCell) {
  const double block[3] = {0.5, 0.4, 0.3}, gap[3] = {0.25, 0.2, 0.35};
  const std::string body =
      "array bs[3], gp[3], cb[3], cg[3];\nbs = [0.5, 0.4, 0.3];\ngp = [0.25, 0.2, 0.35];\ncb = [1, 0, 0];\n"
      "cg = [0, 0.5, 1];\nd = hfA_CheckerBoard(x, bs, gp, s, cb, cg);";
  expectAttributes(model(body),
                   [&](double x, double y, double z) {
                     const double p[3] = {x, y, z};
                     bool inside = true;
                     for (int i = 0; i < 3; ++i) {
                       const double period = block[i] + gap[i], corner = period * std::floor(p[i] / period);
                       inside = inside && p[i] > corner && p[i] < corner + block[i];
                     }
                     return inside ? std::vector<double>{1, 0, 0} : std::vector<double>{0, 0.5, 1};
                   },
                   [&](double x, double y, double z) {
                     const double p[3] = {x, y, z};
                     for (int i = 0; i < 3; ++i) {
                       const double period = block[i] + gap[i], r = p[i] - period * std::floor(p[i] / period);
                       if (r < 1e-5 || std::fabs(r - block[i]) < 1e-5 || period - r < 1e-5) return true;
                     }
                     return false;
                   });
}

// Circles' and Crackles' table: map [0, 0.3, 0.7, 1], colour sets of 3 with a 10th item that
// HyperFun overwrites with 1.1 (item n_prob + 1 = 5: set 2's green).
const char* kTable = "array mp[4], at[10];\nmp = [0, 0.3, 0.7, 1];\nat = [1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5];\n";
std::vector<double> tableSet(double v, bool first_wins, std::vector<double> s) {
  double at[10] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5};
  const double mp[4] = {0, 0.3, 0.7, 1};
  at[4] = 1.1;
  for (int i = 0; i < 3; ++i)
    if (v >= mp[i] && v < mp[i + 1]) {
      s = {at[3 * i], at[3 * i + 1], at[3 * i + 2]};
      if (first_wins) break;
    }
  return s;
}
bool nearTableEdge(double v) {
  for (double e : {0.0, 0.3, 0.7, 1.0})
    if (std::fabs(v - e) < 1e-5) return true;
  return false;
}

TEST(HyperFunAttributePatterns, CirclesChooseByTheFractionOfTheRadius) {
  auto v = [](double x, double y, double z) { return std::fmod(std::sqrt(x * x + y * y + z * z), 1.0); };
  expectAttributes(model(std::string(kTable) + "d = hfA_Circles(x, s, at, mp);"),
                   [&](double x, double y, double z) { return tableSet(v(x, y, z), true, {0, 0, 0}); },
                   [&](double x, double y, double z) { return nearTableEdge(v(x, y, z)); });
}

// pattern.h's Noise: Gardner's series, amplitude 1, onto [0, 1].
double gardner(double x, double y, double z, double phase, double freq) {
  const double sx = std::sin(freq * x), sy = std::sin(freq * y), sz = std::sin(freq * z);
  const double serx = sx + std::sin(freq * x / 1.35 + phase * sz) / 1.17;
  const double sery = sy + std::sin(freq * y / 1.35 + phase * sx) / 1.17;
  const double serz = sz + std::sin(freq * z / 1.35 + phase * sy) / 1.17;
  const double c = 2.17 / 1.17, c_min = std::pow(-c, 3), c_max = -c_min;
  return (serx * sery * serz - c_min) / (c_max - c_min);
}

TEST(HyperFunAttributePatterns, CracklesCycleGardnersNoiseThroughTheTable) {
  const double freq = 2.0;
  auto w = [&](double x, double y, double z) {
    const double phase = (std::fabs(x) + std::fabs(y) + std::fabs(z)) / 3.0;
    return (-1 + 2 * gardner(x, x, z, phase, freq)) + (-1 + 2 * gardner(y, y, x, phase, freq)) +
           (-1 + 2 * gardner(z, z, y, phase, freq));
  };
  auto v = [&](double x, double y, double z) {
    const double ww = w(x, y, z);
    const int i = static_cast<int>((ww - std::floor(ww)) * 1000.0);
    return (1.0 + std::sin(i * 2.0 * std::numbers::pi / 1000.0)) / 2.0;
  };
  expectAttributes(model(std::string(kTable) + "s = [0.2, 0.2, 0.2];\nd = hfA_Crackles(x, s, 2, at, mp);"),
                   [&](double x, double y, double z) { return tableSet(v(x, y, z), false, {0.2, 0.2, 0.2}); },
                   [&](double x, double y, double z) {
                     const double ww = w(x, y, z);
                     return nearInteger(ww, 1e-4) || nearInteger((ww - std::floor(ww)) * 1000.0, 1e-2) ||
                            nearTableEdge(v(x, y, z));
                   });
}

TEST(HyperFunAttributePatterns, NoiseGIsGardnersSeriesOnZeroToOne) {
  expectAttributes(model("s[1] = hfA_NoiseG(x, 0.7, 1.4);\ns[2] = hfA_NoiseG(x, 3, 0.5);"),
                   [](double x, double y, double z) {
                     return std::vector<double>{gardner(x, y, z, 1.4, 0.7), gardner(x, y, z, 0.5, 3), 0};
                   });
}

TEST(HyperFunAttributePatterns, LookUpTablesTakeTheFirstMatchingSetAndTheLastOutsideTheTable) {
  const double mp[3] = {-1, 0, 1.5}, at[9] = {1, 0, 0, 0, 1, 0, 0.2, 0.4, 1};
  const std::string arrays = "array mp[3], at[9];\nmp = [-1, 0, 1.5];\nat = [1, 0, 0, 0, 1, 0, 0.2, 0.4, 1];\n";
  for (bool smooth : {false, true}) {
    SCOPED_TRACE(smooth);
    const std::string call = smooth ? "hfA_SmoothLookUpTable" : "hfA_LookUpTable";
    expectAttributes(model(arrays + "d = " + call + "(x[1], s, at, mp);"),
                     [&](double t, double, double) {
                       std::vector<double> s = {at[6], at[7], at[8]};  // below the table too (HyperFun's flag)
                       for (int i = 0; i < 2; ++i)
                         if (t >= mp[i] && t < mp[i + 1]) {
                           const double l = smooth ? (t - mp[i]) / (mp[i + 1] - mp[i]) : 0.0;
                           for (int j = 0; j < 3; ++j) s[j] = (1 - l) * at[3 * i + j] + l * at[3 * (i + 1) + j];
                           break;
                         }
                       return s;
                     },
                     [&](double t, double, double) { return nearTableEdge(t) || std::fabs(t + 1) < 1e-5 || std::fabs(t - 1.5) < 1e-5; });
  }
}

TEST(HyperFunAttributePatterns, SplineIsHyperFunsCatmullRomThroughTheColours) {
  const double cr[4][4] = {{-0.5, 1.5, -1.5, 0.5}, {1.0, -2.5, 2.0, -0.5}, {-0.5, 0.0, 0.5, 0.0}, {0.0, 1.0, 0.0, 0.0}};
  for (int size : {4, 6}) {
    SCOPED_TRACE(size);
    std::vector<double> knot;
    std::string list;
    for (int k = 0; k < 3 * size; ++k) {
      knot.push_back(0.1 * ((k * 7) % 11));
      list += (k ? ", " : "") + std::to_string(knot.back());
    }
    const std::string n = std::to_string(3 * size);
    expectAttributes(model("array kn[" + n + "];\nkn = [" + list + "];\nd = hfA_Spline(s, kn, x[1], -2, 2);"),
                     [&](double t, double, double) {
                       double u = (t + 2) / 4;
                       std::vector<double> s(3);
                       if (u < 0) return std::vector<double>{knot[0], knot[1], knot[2]};
                       if (u > 1) return std::vector<double>(knot.end() - 3, knot.end());
                       const int spans = size - 3;
                       u *= spans;
                       const int span = static_cast<int>(u);
                       u -= span;
                       for (int i = 0; i < 3; ++i) {
                         double c[4] = {0, 0, 0, 0};
                         for (int row = 0; row < 4; ++row)
                           for (int k = 0; k < 4; ++k) c[row] += cr[row][k] * knot[(span + k) * 3 + i];
                         s[i] = ((c[0] * u + c[1]) * u + c[2]) * u + c[3];
                       }
                       return s;
                     },
                     [&](double t, double, double) { return nearInteger((t + 2) / 4 * (size - 3), 1e-5); });
  }
}

TEST(HyperFunAttributePatterns, RGBAndHSVConvertAsHyperFunsCode) {
  expectAttributes(model("array c[3];\nc[1] = 0.5 + 0.2*x[1];\nc[2] = 0.5 + 0.2*x[2];\nc[3] = 0.5 + 0.2*x[3];\n"
                         "d = hfA_RGBToHSV(c, s);"),
                   [](double x, double y, double z) {
                     const double r = 0.5 + 0.2 * x, g = 0.5 + 0.2 * y, b = 0.5 + 0.2 * z;
                     const double lo = std::min(r, std::min(g, b)), hi = std::max(r, std::max(g, b)), delta = hi - lo;
                     double h = 0;
                     if (delta > 0) {
                       if (hi == r && hi != g) h += (g - b) / delta;
                       if (hi == g && hi != b) h += 2 + (b - r) / delta;
                       if (hi == b && hi != r) h += 4 + (r - g) / delta;
                       h *= 60;
                     }
                     return std::vector<double>{h, hi > 0 ? delta / hi : 0, hi};
                   });
  expectAttributes(model("array c[3];\nc[1] = 200*x[1];\nc[2] = 0.5 + 0.2*x[2];\nc[3] = 0.8 + 0.1*x[3];\n"
                         "d = hfA_HSVToRGB(c, s);"),
                   [](double x, double y, double z) {
                     double h = 200 * x, r, g, b;
                     const double s = 0.5 + 0.2 * y, v = 0.8 + 0.1 * z;
                     while (h < 0.0) h += 360.0;
                     while (h > 360.0) h -= 360.0;
                     if (h < 120.0) r = (120.0 - h) / 60.0, g = h / 60.0, b = 0;
                     else if (h < 240.0) r = 0, g = (240.0 - h) / 60.0, b = (h - 120.0) / 60.0;
                     else r = (h - 240.0) / 60.0, g = 0, b = (360.0 - h) / 60.0;
                     auto cap = [](double c) { return c < 1 ? c : 1; };
                     return std::vector<double>{(1 - s + s * cap(r)) * v, (1 - s + s * cap(g)) * v, (1 - s + s * cap(b)) * v};
                   });
}

TEST(HyperFunAttributePatterns, MisuseIsReportedAtTheArgument) {
  expectHas(compileError(model("array c2[2];\nc2 = [0, 1];\nd = hfA_CheckerBoard(x, s, s, s, s, c2);")),
            "m.hf:4:37: error: 'input_gap' (argument 6 of 'hfA_CheckerBoard') must be an array of 3 items; 'c2' has 2");
  expectHas(compileError(model("array kn[9];\nkn = [0, 0, 0, 0, 0, 0, 0, 0, 0];\nd = hfA_Spline(s, kn, x[1], 0, 1);")),
            "m.hf:4:19: error: 'knots' (argument 2 of 'hfA_Spline') must be an array of at least 12 items; 'kn' has 9");
  expectHas(compileError(model("array mp[3];\nmp = [0, 1, 2];\nd = hfA_LookUpTable(x[1], s, s, mp);")),
            "m.hf:4:30: error: 'input_attr' (argument 3 of 'hfA_LookUpTable') must be an array of at least 9 items; "
            "'s' has 3");
  expectHas(compileError(model("d = hfA_NoiseG(x, 1);")), "m.hf:2:5: error: 'hfA_NoiseG' takes 3 arguments (x, freq, phase), found 2");
}

}  // namespace
}  // namespace pf::field
