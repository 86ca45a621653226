// Lexer: characters -> tokens with line:column locations. Handles // and /* */ comments.
#include "compiler/lexer.h"

#include <cctype>
#include <unordered_map>

namespace pf {

const char* tokenName(Tok t) {
  switch (t) {
    case Tok::End: return "end of file";
    case Tok::Ident: return "identifier";
    case Tok::IntLit: return "integer literal";
    case Tok::FloatLit: return "float literal";
    case Tok::KwPrimitive: return "'primitive'";
    case Tok::KwInterpolator: return "'interpolator'";
    case Tok::KwUniform: return "'uniform'";
    case Tok::KwVarying: return "'varying'";
    case Tok::KwInout: return "'inout'";
    case Tok::KwIf: return "'if'";
    case Tok::KwElse: return "'else'";
    case Tok::KwReturn: return "'return'";
    case Tok::KwInterpolation: return "'interpolation'";
    case Tok::KwInterpolatorReturn: return "'interpolator_return'";
    case Tok::KwBound: return "'bound'";
    case Tok::KwTrue: return "'true'";
    case Tok::KwFalse: return "'false'";
    case Tok::KwFor: return "'for'";
    case Tok::KwWhile: return "'while'";
    case Tok::KwBreak: return "'break'";
    case Tok::KwContinue: return "'continue'";
    case Tok::KwFloat: return "'float'";
    case Tok::KwInt: return "'int'";
    case Tok::KwBool: return "'bool'";
    case Tok::KwPoint: return "'point'";
    case Tok::KwVector: return "'vector'";
    case Tok::KwNormal: return "'normal'";
    case Tok::KwColor: return "'color'";
    case Tok::KwMatrix: return "'matrix'";
    case Tok::KwFixed: return "'fixed'";
    case Tok::KwInterpolatorData: return "'interpolator_data'";
    case Tok::KwPerspectiveLinear: return "'perspective_linear'";
    case Tok::KwLinear: return "'linear'";
    case Tok::KwDefault: return "'default'";
    case Tok::LParen: return "'('";
    case Tok::RParen: return "')'";
    case Tok::LBrace: return "'{'";
    case Tok::RBrace: return "'}'";
    case Tok::LBracket: return "'['";
    case Tok::RBracket: return "']'";
    case Tok::Comma: return "','";
    case Tok::Semi: return "';'";
    case Tok::Colon: return "':'";
    case Tok::Dot: return "'.'";
    case Tok::Question: return "'?'";
    case Tok::Plus: return "'+'";
    case Tok::Minus: return "'-'";
    case Tok::Star: return "'*'";
    case Tok::Slash: return "'/'";
    case Tok::Percent: return "'%'";
    case Tok::Bang: return "'!'";
    case Tok::Assign: return "'='";
    case Tok::PlusAssign: return "'+='";
    case Tok::MinusAssign: return "'-='";
    case Tok::StarAssign: return "'*='";
    case Tok::SlashAssign: return "'/='";
    case Tok::Eq: return "'=='";
    case Tok::Ne: return "'!='";
    case Tok::Lt: return "'<'";
    case Tok::Le: return "'<='";
    case Tok::Gt: return "'>'";
    case Tok::Ge: return "'>='";
    case Tok::AndAnd: return "'&&'";
    case Tok::OrOr: return "'||'";
  }
  return "token";
}

namespace {

const std::unordered_map<std::string, Tok>& keywords() {
  static const std::unordered_map<std::string, Tok> k = {
      {"primitive", Tok::KwPrimitive},
      {"interpolator", Tok::KwInterpolator},
      {"uniform", Tok::KwUniform},
      {"varying", Tok::KwVarying},
      {"inout", Tok::KwInout},
      {"if", Tok::KwIf},
      {"else", Tok::KwElse},
      {"return", Tok::KwReturn},
      {"interpolation", Tok::KwInterpolation},
      {"interpolator_return", Tok::KwInterpolatorReturn},
      {"bound", Tok::KwBound},
      {"true", Tok::KwTrue},
      {"false", Tok::KwFalse},
      {"for", Tok::KwFor},
      {"while", Tok::KwWhile},
      {"break", Tok::KwBreak},
      {"continue", Tok::KwContinue},
      {"float", Tok::KwFloat},
      {"int", Tok::KwInt},
      {"bool", Tok::KwBool},
      {"point", Tok::KwPoint},
      {"vector", Tok::KwVector},
      {"normal", Tok::KwNormal},
      {"color", Tok::KwColor},
      {"matrix", Tok::KwMatrix},
      {"fixed", Tok::KwFixed},
      {"interpolator_data", Tok::KwInterpolatorData},
      {"perspective_linear", Tok::KwPerspectiveLinear},
      {"linear", Tok::KwLinear},
      {"default", Tok::KwDefault},
  };
  return k;
}

}  // namespace

std::vector<Token> lex(const SourceFile& file, DiagnosticLog& log) {
  std::vector<Token> out;
  const std::string& s = file.text;
  size_t i = 0;
  int line = 1, col = 1;
  auto advance = [&](size_t n) {
    for (size_t k = 0; k < n && i < s.size(); ++k, ++i) {
      if (s[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
  };
  auto here = [&] { return SourceLoc{&file, line, col}; };
  auto peek = [&](size_t k) { return i + k < s.size() ? s[i + k] : '\0'; };

  while (i < s.size()) {
    char c = s[i];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      advance(1);
      continue;
    }
    if (c == '/' && peek(1) == '/') {
      while (i < s.size() && s[i] != '\n') advance(1);
      continue;
    }
    if (c == '/' && peek(1) == '*') {
      SourceLoc start = here();
      advance(2);
      while (i < s.size() && !(s[i] == '*' && peek(1) == '/')) advance(1);
      if (i >= s.size()) {
        log.error(start, "unterminated comment");
        break;
      }
      advance(2);
      continue;
    }
    SourceLoc loc = here();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      size_t b = i;
      while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_'))
        advance(1);
      std::string word = s.substr(b, i - b);
      auto it = keywords().find(word);
      out.push_back({it == keywords().end() ? Tok::Ident : it->second, word, loc});
      continue;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && std::isdigit(static_cast<unsigned char>(peek(1))))) {
      size_t b = i;
      bool is_float = false;
      while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) advance(1);
      if (i < s.size() && s[i] == '.') {
        is_float = true;
        advance(1);
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) advance(1);
      }
      if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        size_t save_i = i;
        int save_line = line, save_col = col;
        advance(1);
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) advance(1);
        if (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) {
          is_float = true;
          while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) advance(1);
        } else {
          i = save_i;
          line = save_line;
          col = save_col;
        }
      }
      if (i < s.size() && (s[i] == 'f' || s[i] == 'F')) {
        is_float = true;
        advance(1);
      }
      if (i < s.size() && (std::isalpha(static_cast<unsigned char>(s[i])) || s[i] == '_')) {
        log.error(here(), "malformed number: unexpected character '" + std::string(1, s[i]) + "'");
        while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_'))
          advance(1);
        continue;
      }
      out.push_back({is_float ? Tok::FloatLit : Tok::IntLit, s.substr(b, i - b), loc});
      continue;
    }
    auto two = [&](char second, Tok yes, Tok no) {
      if (peek(1) == second) {
        out.push_back({yes, s.substr(i, 2), loc});
        advance(2);
      } else {
        out.push_back({no, s.substr(i, 1), loc});
        advance(1);
      }
    };
    switch (c) {
      case '(': out.push_back({Tok::LParen, "(", loc}); advance(1); break;
      case ')': out.push_back({Tok::RParen, ")", loc}); advance(1); break;
      case '{': out.push_back({Tok::LBrace, "{", loc}); advance(1); break;
      case '}': out.push_back({Tok::RBrace, "}", loc}); advance(1); break;
      case '[': out.push_back({Tok::LBracket, "[", loc}); advance(1); break;
      case ']': out.push_back({Tok::RBracket, "]", loc}); advance(1); break;
      case ',': out.push_back({Tok::Comma, ",", loc}); advance(1); break;
      case ';': out.push_back({Tok::Semi, ";", loc}); advance(1); break;
      case ':': out.push_back({Tok::Colon, ":", loc}); advance(1); break;
      case '.': out.push_back({Tok::Dot, ".", loc}); advance(1); break;
      case '?': out.push_back({Tok::Question, "?", loc}); advance(1); break;
      case '%': out.push_back({Tok::Percent, "%", loc}); advance(1); break;
      case '+': two('=', Tok::PlusAssign, Tok::Plus); break;
      case '-': two('=', Tok::MinusAssign, Tok::Minus); break;
      case '*': two('=', Tok::StarAssign, Tok::Star); break;
      case '/': two('=', Tok::SlashAssign, Tok::Slash); break;
      case '!': two('=', Tok::Ne, Tok::Bang); break;
      case '=': two('=', Tok::Eq, Tok::Assign); break;
      case '<': two('=', Tok::Le, Tok::Lt); break;
      case '>': two('=', Tok::Ge, Tok::Gt); break;
      case '&':
        if (peek(1) == '&') {
          out.push_back({Tok::AndAnd, "&&", loc});
          advance(2);
        } else {
          log.error(loc, "unexpected character '&' (did you mean '&&'?)");
          advance(1);
        }
        break;
      case '|':
        if (peek(1) == '|') {
          out.push_back({Tok::OrOr, "||", loc});
          advance(2);
        } else {
          log.error(loc, "unexpected character '|' (did you mean '||'?)");
          advance(1);
        }
        break;
      default: {
        unsigned char uc = static_cast<unsigned char>(c);
        std::string shown = (uc >= 32 && uc < 127) ? std::string(1, c) : "\\x" + [&] {
          const char* hex = "0123456789abcdef";
          return std::string{hex[uc >> 4], hex[uc & 15]};
        }();
        log.error(loc, "unexpected character '" + shown + "'");
        advance(1);
      }
    }
  }
  out.push_back({Tok::End, "", here()});
  return out;
}

}  // namespace pf
