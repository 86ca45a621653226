// Parser: the figure-7 shape of a primitive, precedence, syntax errors at the right place.
#include <gtest/gtest.h>

#include "compiler/ast_print.h"
#include "compiler/parser.h"

using namespace pf;

namespace {
struct Parsed {
  Program program;
  DiagnosticLog log;
  std::string errors;
};
std::unique_ptr<Parsed> parseString(const std::string& s) {
  auto p = std::make_unique<Parsed>();
  const SourceFile& f = p->log.addSource("t.pfl", s);
  p->program = parse(f, p->log);
  p->errors = p->log.format();
  return p;
}
}  // namespace

TEST(Parser, PrimitiveWithSequencePointParameters) {
  auto p = parseString(
      "primitive screen_triangle(float screen_vertex[3][3]; interpolator_data interp_data[3];\n"
      "                          varying float X, Y; inout varying float Z)\n"
      "{ if (X < screen_vertex[0][0]) return; Z = 0.5;\n"
      "  interpolation { perspective_linear: linear: interpolator_return(interp_data[0]); default: interpolator_return; } }\n");
  ASSERT_FALSE(p->log.hasErrors()) << p->errors;
  ASSERT_EQ(p->program.units.size(), 1u);
  const Unit& u = p->program.units[0];
  EXPECT_EQ(u.name, "screen_triangle");
  ASSERT_EQ(u.params.size(), 5u);
  EXPECT_EQ(u.params[0].type.dims, (std::vector<int>{3, 3}));
  EXPECT_EQ(u.params[3].name, "Y");
  EXPECT_EQ(u.params[4].qualifier, Qualifier::InoutVarying);
  ASSERT_EQ(u.body.size(), 3u);
  EXPECT_EQ(u.body[2]->kind, StmtKind::Interpolation);
  ASSERT_EQ(u.body[2]->cases.size(), 2u);
  EXPECT_EQ(u.body[2]->cases[0].kinds.size(), 2u);  // perspective_linear: linear: share a body
}

TEST(Parser, PrecedenceAndAssociativity) {
  auto p = parseString("primitive p() { float a = 1 + 2 * 3 - 4 / 2; bool b = a < 2 || a > 3 && !(a == 1); }");
  ASSERT_FALSE(p->log.hasErrors()) << p->errors;
  std::string ast = printAst(p->program);
  EXPECT_NE(ast.find("((1 + (2 * 3)) - (4 / 2))"), std::string::npos) << ast;
  EXPECT_NE(ast.find("((a < 2) || ((a > 3) && (!(a == 1))))"), std::string::npos) << ast;
}

TEST(Parser, MissingOperandPointsAtTheToken) {
  auto p = parseString("primitive p()\n{\n    float a = 1.0 +;\n}\n");
  ASSERT_TRUE(p->log.hasErrors());
  const Diagnostic& d = p->log.all()[0];
  EXPECT_EQ(d.loc.line, 3);
  EXPECT_EQ(d.loc.col, 20);
  EXPECT_NE(d.message.find("expected an expression"), std::string::npos);
  EXPECT_NE(p->errors.find("t.pfl:3:20: error: "), std::string::npos);
  EXPECT_NE(p->errors.find("        float a = 1.0 +;\n                       ^"), std::string::npos) << p->errors;
}

// A missing ';' is reported where it is missing -- just after the token before it, as GCC and
// Clang do -- not at the next statement: after a bare `return` (sphere.pfl's `if (disc < 0)
// return` once read the next line's `float` as its value), after a declaration, an
// assignment, and at the end of the file.
TEST(Parser, MissingSemicolonIsReportedWhereItIsMissing) {
  struct Case {
    const char* source;
    int line, col;
    const char* message;
  };
  const Case cases[] = {
      {"primitive p(inout varying float Z)\n{\n    if (X < 0) return\n    float z = 0.5;\n    Z = z;\n}\n", 3, 22,
       "expected ';' after 'return', before 'float'"},
      {"primitive p(inout varying float Z)\n{\n    if (X < 0) return\n}\n", 3, 22, "expected ';' after 'return', before '}'"},
      {"primitive p(inout varying float Z)\n{\n    float z = 0.5\n    Z = z;\n}\n", 3, 18,
       "expected ';' after the declaration, before 'Z'"},
      {"primitive p(inout varying float Z)\n{\n    Z = 0.5\n}\n", 3, 12, "expected ';' after the assignment, before '}'"},
      {"float f() { return 1.0", 1, 23, "expected ';' after 'return', before end of file"},
  };
  for (const Case& c : cases) {
    auto p = parseString(c.source);
    ASSERT_TRUE(p->log.hasErrors()) << c.source;
    const Diagnostic& d = p->log.all()[0];
    EXPECT_EQ(d.loc.line, c.line) << p->errors;
    EXPECT_EQ(d.loc.col, c.col) << p->errors;
    EXPECT_NE(d.message.find(c.message), std::string::npos) << p->errors;
  }
  // `return` followed by a value on the next line is still a return of that value.
  auto ok = parseString("float f()\n{\n    return\n        1.0;\n}\n");
  EXPECT_FALSE(ok->log.hasErrors()) << ok->errors;
}

TEST(Parser, RecoversAndReportsSeveralErrors) {
  auto p = parseString("primitive p() { float a = ; float b = 2; c = = 3; }");
  EXPECT_EQ(p->log.errorCount(), 2) << p->errors;
}

TEST(Parser, DeepNestingIsAnErrorNotACrash) {
  std::string s = "primitive p() { float a = " + std::string(5000, '(') + "1" + std::string(5000, ')') + "; }";
  auto p = parseString(s);
  EXPECT_TRUE(p->log.hasErrors());
  EXPECT_NE(p->errors.find("nesting too deep"), std::string::npos);
}

TEST(Parser, FunctionsAndReturnValues) {
  // `return value;` parses anywhere (sema decides: functions need one, primitives refuse it).
  auto p = parseString("float f(float a, vector b[2]) { return a; }\nprimitive p() { return 1; }");
  ASSERT_FALSE(p->log.hasErrors()) << p->errors;
  ASSERT_EQ(p->program.units.size(), 2u);
  EXPECT_EQ(p->program.units[0].kind, UnitKind::Function);
  EXPECT_EQ(p->program.units[0].return_type, Type::of(BaseType::Float));
  EXPECT_EQ(p->program.units[0].params[1].type.dims, std::vector<int>{2});
}

TEST(Parser, GarbageAtTopLevel) {
  auto p = parseString("float x; }}}} primitive ok() { }");
  EXPECT_TRUE(p->log.hasErrors());
  EXPECT_EQ(p->program.units.size(), 1u);  // recovered to the next unit
}
