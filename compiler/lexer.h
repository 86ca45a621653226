// Lexer for the primitive language (C-like tokens, RenderMan-style keywords).
#pragma once

#include <string>
#include <vector>

#include "compiler/diagnostics.h"

namespace pf {

enum class Tok {
  End, Ident, IntLit, FloatLit,
  // keywords
  KwPrimitive, KwInterpolator, KwUniform, KwVarying, KwInout, KwIf, KwElse, KwReturn,
  KwInterpolation, KwInterpolatorReturn, KwBound, KwTrue, KwFalse, KwFor, KwWhile, KwBreak, KwContinue,
  KwFloat, KwInt, KwBool, KwPoint, KwVector, KwNormal, KwColor, KwMatrix, KwFixed, KwInterpolatorData,
  KwPerspectiveLinear, KwLinear, KwDefault,
  // punctuation and operators
  LParen, RParen, LBrace, RBrace, LBracket, RBracket, Comma, Semi, Colon, Dot, Question,
  Plus, Minus, Star, Slash, Percent, Bang, Assign, PlusAssign, MinusAssign, StarAssign,
  SlashAssign, Eq, Ne, Lt, Le, Gt, Ge, AndAnd, OrOr,
};

const char* tokenName(Tok t);

struct Token {
  Tok kind;
  std::string text;
  SourceLoc loc;
};

// Splits the whole file into tokens (ending with Tok::End). Bad characters and malformed
// numbers are reported to the log and skipped.
std::vector<Token> lex(const SourceFile& file, DiagnosticLog& log);

}  // namespace pf
