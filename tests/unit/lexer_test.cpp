// Lexer: tokens, keywords, numbers, comments, locations, bad characters.
#include <gtest/gtest.h>

#include "compiler/lexer.h"

using namespace pf;

namespace {
std::vector<Token> lexString(const std::string& s, DiagnosticLog& log, SourceFile*& keep) {
  keep = new SourceFile("t.pfl", s);
  return lex(*keep, log);
}
}  // namespace

TEST(Lexer, KeywordsIdentifiersAndPunctuation) {
  DiagnosticLog log;
  SourceFile* f;
  auto t = lexString("primitive p(point v[3]; inout varying float Z) { Z = 1.5e2 + 3; }", log, f);
  ASSERT_FALSE(log.hasErrors());
  std::vector<Tok> kinds;
  for (auto& k : t) kinds.push_back(k.kind);
  std::vector<Tok> want = {Tok::KwPrimitive, Tok::Ident, Tok::LParen, Tok::KwPoint, Tok::Ident, Tok::LBracket,
                           Tok::IntLit, Tok::RBracket, Tok::Semi, Tok::KwInout, Tok::KwVarying, Tok::KwFloat,
                           Tok::Ident, Tok::RParen, Tok::LBrace, Tok::Ident, Tok::Assign, Tok::FloatLit,
                           Tok::Plus, Tok::IntLit, Tok::Semi, Tok::RBrace, Tok::End};
  EXPECT_EQ(kinds, want);
  EXPECT_EQ(t[17].text, "1.5e2");
  delete f;
}

TEST(Lexer, LocationsAreLineAndColumn) {
  DiagnosticLog log;
  SourceFile* f;
  auto t = lexString("// comment\n  /* block\n comment */ foo\n\tbar", log, f);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].loc.line, 3);
  EXPECT_EQ(t[0].loc.col, 13);
  EXPECT_EQ(t[1].loc.line, 4);
  EXPECT_EQ(t[1].loc.col, 2);
  delete f;
}

TEST(Lexer, OperatorsTwoCharacters) {
  DiagnosticLog log;
  SourceFile* f;
  auto t = lexString("<= >= == != && || += -= *= /= < > ! =", log, f);
  std::vector<Tok> want = {Tok::Le, Tok::Ge, Tok::Eq, Tok::Ne, Tok::AndAnd, Tok::OrOr, Tok::PlusAssign,
                           Tok::MinusAssign, Tok::StarAssign, Tok::SlashAssign, Tok::Lt, Tok::Gt, Tok::Bang,
                           Tok::Assign, Tok::End};
  std::vector<Tok> kinds;
  for (auto& k : t) kinds.push_back(k.kind);
  EXPECT_EQ(kinds, want);
  delete f;
}

TEST(Lexer, BadInputIsReportedNotFatal) {
  DiagnosticLog log;
  SourceFile* f;
  auto t = lexString("a @ b\n12abc $ /* never closed", log, f);
  EXPECT_EQ(log.errorCount(), 4);  // '@', malformed number, '$', unterminated comment
  EXPECT_EQ(log.all()[0].loc.col, 3);
  EXPECT_EQ(log.all()[1].loc.line, 2);
  EXPECT_EQ(t.back().kind, Tok::End);
  delete f;
}

TEST(Lexer, NonPrintableCharacterIsShownAsHex) {
  DiagnosticLog log;
  SourceFile* f;
  lexString(std::string("x \x01 y"), log, f);
  ASSERT_EQ(log.errorCount(), 1);
  EXPECT_NE(log.all()[0].message.find("\\x01"), std::string::npos);
  delete f;
}
