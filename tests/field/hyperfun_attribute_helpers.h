// Shared by the HyperFun attribute tests (hyperfun_attributes_test.cpp,
// hyperfun_attribute_patterns_test.cpp): compiling a model with its attribute tapes, and checking
// each attribute tape, evaluated in double, against a formula at random points.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "compiler/field/field_source.h"
#include "compiler/field/hyperfun_reader.h"
#include "field/field_reference.h"
#include "raster/field/float_evaluator.h"

namespace pf::field::attribute_testing {

using Colour = std::function<std::vector<double>(double, double, double)>;

struct Compiled {
  FieldTape shape;
  std::vector<FieldTape> attributes;
};

inline Compiled compileOk(const std::string& text) {
  DiagnosticLog log;
  Compiled c;
  auto tape = readHyperFunModel("m.hf", text, log, {}, "my_model", 0.0, &c.attributes);
  EXPECT_TRUE(tape) << log.format();
  if (tape) c.shape = *tape;
  return c;
}

inline std::string compileError(const std::string& text) {
  DiagnosticLog log;
  std::vector<FieldTape> attributes;
  auto tape = readHyperFunModel("m.hf", text, log, {}, "my_model", 0.0, &attributes);
  EXPECT_FALSE(tape) << text;
  return log.format();
}

inline void expectHas(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "expected to find: " << part << "\nin:\n" << text;
}

// A model my_model(x[3], a[1], s[3]) with these body lines (the body starts on line 2) and
// a ball of radius 2 as its shape.
inline std::string model(const std::string& body) {
  return "my_model(x[3], a[1], s[3]) {\n" + body + "\nmy_model = 4 - x[1]*x[1] - x[2]*x[2] - x[3]*x[3];\n}\n";
}

// Every attribute tape against `want` at random points of [-2.5, 2.5]^3, skipping points within
// `edge` of a discontinuity the test names (`near_edge`), where float and double may choose
// differently.
inline void expectAttributes(const std::string& text, const Colour& want,
                      const std::function<bool(double, double, double)>& near_edge = nullptr) {
  SCOPED_TRACE(text);
  const Compiled c = compileOk(text);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  int checked = 0;
  for (int k = 0; k < 400; ++k) {
    const double x = u(rng), y = u(rng), z = u(rng);
    if (near_edge && near_edge(x, y, z)) continue;
    const std::vector<double> w = want(x, y, z);
    ASSERT_EQ(c.attributes.size(), w.size());
    for (size_t i = 0; i < w.size(); ++i) {
      EXPECT_NEAR(testing::evaluateDouble(c.attributes[i], x, y, z), w[i], 2e-6 * std::max(1.0, std::fabs(w[i])))
          << "s[" << i + 1 << "] at " << x << ", " << y << ", " << z;
      // The float form the renderer runs, at the float point (its own rounding: a looser bound).
      FloatEvaluator f(c.attributes[i]);
      EXPECT_NEAR(f.evaluate(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)), w[i],
                  1e-4 * std::max(1.0, std::fabs(w[i])))
          << "float s[" << i + 1 << "] at " << x << ", " << y << ", " << z;
    }
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

}  // namespace pf::field::attribute_testing
