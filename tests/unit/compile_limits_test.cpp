// The compiler's limits (docs/reliability.md): input that nests past them -- long flat chains,
// deep parentheses, long call chains, inlining that fans out -- is a clear error, never a stack
// overflow or a compile that runs for minutes; input within them compiles. Every compile here
// runs on a thread with a 1 MB stack, an application's worker thread's, not the main thread's 8 MB
// (8 MB under the sanitizers, whose frames are several times larger).
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "compile_helpers.h"
#include "compiler/sanitizers.h"
#include "unit/on_stack.h"

namespace pf::test {
namespace {

// An application thread's stack: 1 MB. Under the sanitizers every frame is several times larger
// (the analyzer's recursive expr() is 6.8 KB under ASan, 0.3 KB without), so those builds test
// on 8 MB -- and the smaller-stack test below shows they still stop with an error on less.
#if defined(PF_SANITIZED)
constexpr size_t kThreadStack = size_t{8} << 20;
#else
constexpr size_t kThreadStack = size_t{1} << 20;
#endif

Compiled compileOnSmallStack(const std::string& source) {
  Compiled c;
  onStack(kThreadStack, [&] { c = compile(source); });
  return c;
}

std::string primitiveWith(const std::string& body) {
  return "primitive p(varying float X, Y; inout varying float Z) {\n" + body + "\n}\n";
}

std::string repeated(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

std::string sumOf(int terms) {
  std::string e = "Z";
  for (int i = 1; i < terms; ++i) e += " + 1.0";
  return e;
}

TEST(CompileLimits, ALongSumIsAnErrorAtItsLineNotAStackOverflow) {
  const Compiled c = compileOnSmallStack(primitiveWith("  Z = " + sumOf(10000) + ";"));
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("test.pfl:2:"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("expression nested too deep (more than 256 levels"), std::string::npos)
      << c.diagnostics;
}

TEST(CompileLimits, SumsAndParenthesesWithinTheLimitCompile) {
  for (const std::string& e : {sumOf(250), repeated("(", 250) + "Z" + repeated(")", 250),
                               repeated("-", 250) + "Z", repeated("abs(", 120) + "Z" + repeated(")", 120)}) {
    const Compiled c = compileOnSmallStack(primitiveWith("  Z = " + e + ";"));
    EXPECT_TRUE(c.ok) << e.substr(0, 40) << ": " << c.diagnostics;
  }
}

TEST(CompileLimits, DeepParenthesesAndPostfixChainsAreErrors) {
  for (const std::string& e : {repeated("(", 5000) + "Z" + repeated(")", 5000), repeated("-", 5000) + "Z",
                               "a" + repeated("[0]", 100000), "v" + repeated(".x", 100000)}) {
    const Compiled c = compileOnSmallStack(primitiveWith("  float a[2]; a[0] = Z; a[1] = Z; vector v = vector(Z);\n  Z = " + e + ";"));
    EXPECT_FALSE(c.ok) << e.substr(0, 40);
    EXPECT_NE(c.diagnostics.find("too deep (more than 256 levels"), std::string::npos) << c.diagnostics.substr(0, 400);
  }
}

// X + 8 Y: the lane's index in the 8x8 block, 0 .. 63.
const char* kLaneIndex = "  int k = int(X) + 8 * int(Y);\n";

TEST(CompileLimits, AVaryingElseIfChainOf200BranchesRunsAsWritten) {
  // The first condition that holds wins: lane k takes `k < k + 1`, so a = k + 1. Nested as
  // written the chain would open 200 masks, past the 64 a program nests; it lowers flat.
  std::string body = std::string(kLaneIndex) + "  float a = 0;\n  if (k < 0) a = 1000;\n";
  for (int i = 1; i < 200; ++i) body += "  else if (k < " + std::to_string(i) + ") a = " + std::to_string(i) + ";\n";
  const Compiled c = compileOnSmallStack(primitiveWith(body + "  else a = 2000;\n  Z = a / 256.0;"));
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const BlockRun r = runBlock(*c.find("p"), {}, {}, 0);
  for (int k = 0; k < 64; ++k) EXPECT_EQ(r.depth[k], static_cast<float>(k + 1) / 256.0f) << "lane " << k;
  // On a uniform value the same chain is no nesting at run time either: it compiles.
  std::string uniform = "primitive p(float k[1]; varying float X, Y; inout varying float Z) {\n  float a = 0;\n  if (k[0] < 0) a = 1;\n";
  for (int i = 1; i < 200; ++i) uniform += "  else if (k[0] < " + std::to_string(i) + ") a = " + std::to_string(i) + ";\n";
  const Compiled u = compileOnSmallStack(uniform + "  Z = a;\n}\n");
  EXPECT_TRUE(u.ok) << u.diagnostics;
}

TEST(CompileLimits, AFlatElseIfChainTestsEachConditionOnlyWhereNoEarlierBranchWasTaken) {
  // `stuck` loops forever where k < 32: were its link's condition run in the lanes the first
  // branch took, those lanes would stop at the iteration cap and draw nothing.
  const std::string source =
      "float stuck(int k) { float n = 0; while (k < 32) n += 1.0; return n; }\n" +
      primitiveWith(std::string(kLaneIndex) +
                    "  float a = 0;\n"
                    "  if (k < 32) { a = 1; k = 100; }\n"  // a branch's writes are not seen by later conditions
                    "  else if (stuck(k) > 0.0) a = 2;\n"
                    "  else if (k < 40) a = 3;\n"
                    "  else if (k < 48) a = 4;\n"
                    "  else if (k < 56) a = 5;\n"
                    "  Z = (a + float(k) / 128.0) / 8.0;");
  const Compiled c = compileOnSmallStack(source);
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const BlockRun r = runBlock(*c.find("p"), {}, {}, 0, true, 1.0f, InterpKind::PerspectiveLinear, 1024);
  EXPECT_EQ(r.counters.iteration_cap_lanes, 0u);
  for (int k = 0; k < 64; ++k) {
    const float a = k < 32 ? 1 : k < 40 ? 3 : k < 48 ? 4 : k < 56 ? 5 : 0;
    const float kk = k < 32 ? 100 : static_cast<float>(k);
    EXPECT_EQ(r.depth[k], (a + kk / 128.0f) / 8.0f) << "lane " << k;
  }
}

TEST(CompileLimits, AFlatElseIfChainOfReturnsInAFunction) {
  // Every branch returns (the chain's end is the function's), and a chain without an else falls
  // through to the statement after it.
  const std::string source =
      "float every(int k) { if (k < 8) return 1.0; else if (k < 16) return 2.0; else if (k < 24) return 3.0;\n"
      "  else if (k < 32) return 4.0; else return 5.0; }\n"
      "float some(int k) { if (k < 8) return 1.0; else if (k < 16) return 2.0; else if (k < 24) return 3.0;\n"
      "  else if (k < 32) return 4.0; return 6.0; }\n" +
      primitiveWith(std::string(kLaneIndex) + "  Z = (every(k) + some(k) * 8.0) / 64.0;");
  const Compiled c = compileOnSmallStack(source);
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const BlockRun r = runBlock(*c.find("p"), {}, {}, 0);
  for (int k = 0; k < 64; ++k) {
    const float band = static_cast<float>(k / 8 + 1);
    const float every = k < 32 ? band : 5.0f, some = k < 32 ? band : 6.0f;
    EXPECT_EQ(r.depth[k], (every + some * 8.0f) / 64.0f) << "lane " << k;
  }
}

// f0 ... f(n-1), each calling the one before: `early` gives each an early return (an inlined
// call with a return before its end is a one-iteration loop), `twice` makes each call it twice.
std::string callChain(int n, bool early, bool twice) {
  std::string s = "float f0(float x) { return x * 0.5; }\n";
  for (int i = 1; i < n; ++i) {
    const std::string prev = "f" + std::to_string(i - 1);
    const std::string call = twice ? prev + "(x) + " + prev + "(x + 1.0)" : prev + "(x + 1.0)";
    s += "float f" + std::to_string(i) + "(float x) { ";
    if (early) s += "if (x > " + std::to_string(i) + ") return x; ";
    s += "return " + call + "; }\n";
  }
  return s + primitiveWith("  Z = f" + std::to_string(n - 1) + "(Z);");
}

TEST(CompileLimits, ALongCallChainIsAnErrorNamingTheChain) {
  const Compiled c = compileOnSmallStack(callChain(5000, false, false));
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("calls nest more than 64 deep once functions are inlined: p -> f4999 -> f4998"),
            std::string::npos)
      << c.diagnostics;
  const Compiled within = compileOnSmallStack(callChain(64, true, false));
  EXPECT_TRUE(within.ok) << within.diagnostics;
}

// A thread with less stack than the limits assume (a quarter of it): deep input is still an
// error -- the compiler watches the stack it has left -- never an overflow.
TEST(CompileLimits, ASmallerStackStillGivesAnErrorNotAnOverflow) {
  for (const std::string& source : {callChain(64, true, false), primitiveWith("  Z = " + sumOf(250) + ";"),
                                    primitiveWith("  Z = " + repeated("(", 250) + "Z" + repeated(")", 250) + ";")}) {
    Compiled c;
    onStack(kThreadStack / 4, [&] { c = compile(source); });
    if (!c.ok) {
      EXPECT_NE(c.diagnostics.find("too deep for this thread's stack"), std::string::npos) << c.diagnostics;
    }
  }
}

// Which functions return varying values is found by a worklist over the calls: rounds over all
// functions in the order of their names were quadratic in a chain that runs against that order
// (g0 calls g1 ... calls g19999, whose value is varying: 30 s for 5,000, minutes for 20,000;
// ctest's timeout catches a return of it). The chain is then refused as too deep to inline.
TEST(CompileLimits, AChainOfCallsAgainstTheNameOrderIsAnalyzedInLinearTime) {
  const int n = 20000;
  std::string s = "float g" + std::to_string(n - 1) + "(float x) { return X; }\n";
  for (int i = n - 2; i >= 0; --i)
    s += "float g" + std::to_string(i) + "(float x) { return g" + std::to_string(i + 1) + "(x); }\n";
  const Compiled c = compileOnSmallStack(s + primitiveWith("  Z = g0(Z);"));
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("calls nest more than 64 deep once functions are inlined: p -> g0 -> g1"), std::string::npos)
      << c.diagnostics;
}

// Lowering an early-returning function is a loop, lowered again when it turns out varying; the
// loops of the functions it calls start from what they found before, or each level of the chain
// doubles the work (24 levels: 2^24 lowerings, far past the program size limit below).
TEST(CompileLimits, EarlyReturnsDoNotDoubleTheWorkPerCallLevel) {
  const Compiled c = compileOnSmallStack(callChain(24, true, false));
  EXPECT_TRUE(c.ok) << c.diagnostics;
}

TEST(CompileLimits, InliningThatFansOutStopsAtTheSizeLimitNamingTheChain) {
  for (bool early : {false, true}) {
    const Compiled c = compileOnSmallStack(callChain(24, early, true));
    EXPECT_FALSE(c.ok);
    EXPECT_NE(c.diagnostics.find("the program grows past 262144 operations once its functions are inlined: p -> f23 -> f22"),
              std::string::npos)
        << c.diagnostics;
  }
  EXPECT_TRUE(compileOnSmallStack(callChain(10, true, true)).ok);
}

}  // namespace
}  // namespace pf::test
