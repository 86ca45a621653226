// The pixel programs' decoding (raster/decoded_program.h): a product read once by an add or a
// subtract is fused into it -- and only when the fused product is the one the program made.
// Every block here also runs through the reference interpreter (runBlock), which must agree with
// the executor to the bit.
#include <gtest/gtest.h>

#include <string>

#include "compile_helpers.h"
#include "raster/decoded_program.h"
#include "setup_batch_helpers.h"

using namespace pf;
using namespace pf::test;

namespace {

// The primitive `p`'s pixel program decoded with the kernels in use; how many products fused.
int fusedIn(const Compiled& c) {
  DecodedProgram d;
  decodeProgram(c.find("p")->pixel, laneIsaTables(), d);
  return d.fused;
}

Compiled compileBody(const std::string& body) {
  Compiled c = compile("primitive p(float k[1]; varying float X, Y; inout varying float Z) {\n" + body + "}\n");
  EXPECT_TRUE(c.ok) << c.diagnostics;
  return c;
}

}  // namespace

TEST(DecodedProgram, FusesEachProductReadOnceByAnAddOrSubtract) {
  // Four forms: t + c, c + t, t - c, c - t, each product read once.
  const Compiled c = compileBody(
      "  float a = X * k[0] + Y;\n  float b = Y - X * 0.25;\n  float e = X * Y - 3.0;\n"
      "  float f = 0.5 + Y * Y;\n  Z = (a + b + e + f) * 0.001;\n");
  EXPECT_EQ(fusedIn(c), 4);
  const BlockRun r = runBlock(*c.find("p"), {1.5f}, {}, 0, false);
  EXPECT_EQ(r.counters.lanes_committed, 64u);
}

TEST(DecodedProgram, LeavesProductsReadTwiceOrOfChangingValues) {
  // Read twice: the product is kept.
  EXPECT_EQ(fusedIn(compileBody("  float t = X * k[0];\n  Z = (t + Y) * (t - 1.0) * 0.001;\n")), 0);
  // A factor written more than once (a loop's variable, one register across iterations): its
  // value at the add need not be the product's, so nothing of it fuses.
  const Compiled c = compileBody(
      "  float v = X;\n  float s = 0.0;\n  for (int i = 0; i < 3; i += 1) {\n    float t = v * 3.0;\n"
      "    v = v + Y;\n    s = s + (t + v);\n  }\n  Z = s * 0.001;\n");
  EXPECT_EQ(fusedIn(c), 0);
  runBlock(*c.find("p"), {1.0f}, {}, 0, false);  // agrees with the reference
  // A product of values written once, read once after a varying if: fused.
  const Compiled d = compileBody(
      "  float v = X;\n  float t = v * 3.0;\n  if (Y > 4.0) v = v + 100.0;\n  Z = (t + v) * 0.001;\n");
  EXPECT_EQ(fusedIn(d), 1);
  runBlock(*d.find("p"), {1.0f}, {}, 0, false);
}

// The shipped primitives' programs (with interpolator-data ops, whose registers are another
// file) fuse as their listings say: pfc --emit=pixel shows 31 such products in
// sphere_impostors and 28 in triangles.
TEST(DecodedProgram, ShippedPrimitivesFuse) {
  for (const char* name : {"sphere_impostors", "triangles"}) {
    DecodedProgram d;
    decodeProgram(builtin(name).pixel, laneIsaTables(), d);
    EXPECT_GE(d.fused, 25) << name;
  }
}
