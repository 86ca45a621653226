// The HyperFun scanner: source text to tokens, with HyperFun's own lexical rules.
//
// What HyperFun's C interpreter does (docs/hyperfun.md, shared/hyperfun.md a.2): identifiers are
// case-insensitive (lowercased here), `--` starts a comment to the end of the line (so `a--b` is
// `a` then a comment), numbers are `digits[.[digits]][e[+|-]digits]` or `.digits`, a multi-digit
// integer part may not start with 0 and an exponent may not start with 0. Tokens keep their
// 1-based line and column for diagnostics.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "compiler/diagnostics.h"

namespace pf::field::hyperfun {

enum class Tok {
  End, Number, Ident, String,
  // reserved words
  Array, If, Then, Else, EndIf, While, Loop, EndLoop, And, Or, Not, Xor,
  // punctuation
  Caret, Plus, Minus, Tilde, Slash, Star, Amp, Bar, Backslash, At, Comma, Semicolon, Assign,
  LParen, RParen, LBracket, RBracket, LBrace, RBrace, Less, LessEq, Greater, GreaterEq, NotEqual,
};

struct Token {
  Tok kind = Tok::End;
  std::string text;     // identifiers lowercased; the source spelling otherwise
  double number = 0.0;  // Number only
  int line = 0, col = 0;
};

// How a token kind is written, for messages ("'then'", "';'", "end of file").
std::string tokenSpelling(Tok kind);

// The tokens of `file`, ending with Tok::End. Lexical errors go to `log`; the caller checks
// log.errorCount() before parsing.
std::vector<Token> scanHyperFun(const SourceFile& file, DiagnosticLog& log);

}  // namespace pf::field::hyperfun
