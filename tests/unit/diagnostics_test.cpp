// What an author sees of bad input (docs/reliability.md): line numbers with any line ending,
// a long line shown around its column, at most 20 errors, control bytes escaped, literals out
// of range refused.
#include <gtest/gtest.h>

#include <string>

#include "compile_helpers.h"
#include "compiler/field/fidget_reader.h"

namespace pf::test {
namespace {

TEST(Diagnostics, OldMacLineEndingsCountLines) {
  const Compiled c = compile("primitive p(varying float X, Y; inout varying float Z) {\r  Z = 1;\r  Z = ;\r}\r");
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("test.pfl:3:7: error: expected an expression"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("\n      Z = ;\n"), std::string::npos) << c.diagnostics;
}

TEST(Diagnostics, ALongLineIsShownAroundTheColumn) {
  // 10 MB on one line, the error near its end: the line shown is a window of it, caret included.
  std::string body = "  float a = 1.0" + std::string(10 << 20, ' ') + " + ;";
  const Compiled c = compile("primitive p(varying float X, Y; inout varying float Z) {\n" + body + "\n}\n");
  EXPECT_FALSE(c.ok);
  EXPECT_LT(c.diagnostics.size(), 1000u) << c.diagnostics.substr(0, 1000);
  const size_t shown = c.diagnostics.find("\n    ...");
  ASSERT_NE(shown, std::string::npos) << c.diagnostics.substr(0, 1000);
  // The caret sits under the ';' of the window.
  const size_t line_end = c.diagnostics.find('\n', shown + 1);
  const std::string line = c.diagnostics.substr(shown + 1, line_end - shown - 1);
  const std::string caret = c.diagnostics.substr(line_end + 1, c.diagnostics.find('\n', line_end + 1) - line_end - 1);
  ASSERT_EQ(caret.back(), '^');
  EXPECT_EQ(line[caret.size() - 1], ';') << line << "\n" << caret;
}

TEST(Diagnostics, AtMostTwentyErrorsAreShownOfAnyKind) {
  // Thirty semantic errors (names never declared): twenty shown, the rest counted.
  std::string body;
  for (int i = 0; i < 30; ++i) body += "  Z = missing" + std::to_string(i) + ";\n";
  const Compiled c = compile("primitive p(varying float X, Y; inout varying float Z) {\n" + body + "}\n");
  EXPECT_FALSE(c.ok);
  size_t shown = 0;
  for (size_t at = c.diagnostics.find(": error: "); at != std::string::npos; at = c.diagnostics.find(": error: ", at + 1))
    ++shown;
  EXPECT_EQ(shown, 20u) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("error: 10 more error(s) not shown"), std::string::npos) << c.diagnostics;
}

TEST(Diagnostics, FloatLiteralsPastTheLargestFloatAreErrors) {
  for (const char* literal : {"1e999999", "1e39", "340282356779733661637539395458142568448.0"}) {
    const Compiled c = compile(std::string("primitive p(varying float X, Y; inout varying float Z) { Z = ") + literal + "; }\n");
    EXPECT_FALSE(c.ok) << literal;
    EXPECT_NE(c.diagnostics.find("is out of range (the largest float is 3.4e38)"), std::string::npos) << c.diagnostics;
  }
  EXPECT_TRUE(compile("primitive p(varying float X, Y; inout varying float Z) { Z = 3.4e38 * 1e-38 + 1e-999; }\n").ok);
}

TEST(Diagnostics, ControlBytesInMessagesAreEscaped) {
  // A Fidget operation name holding a NUL byte: named in the message as \x00.
  DiagnosticLog log;
  const std::string model = std::string("_0 var-x\n_1 at") + '\0' + "an _0\n";
  EXPECT_FALSE(field::readFidgetModel("m.vm", model, log).has_value());
  const std::string text = log.format();
  EXPECT_EQ(text.find('\0'), std::string::npos);
  EXPECT_NE(text.find("at\\x00an"), std::string::npos) << text;
}

}  // namespace
}  // namespace pf::test
