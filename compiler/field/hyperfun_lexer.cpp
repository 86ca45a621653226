// The HyperFun scanner (see hyperfun_lexer.h for the rules it follows).
#include "compiler/field/hyperfun_lexer.h"

#include <cctype>
#include <charconv>
#include <cstdio>

namespace pf::field::hyperfun {
namespace {

constexpr size_t kMaxIdentifier = 256;  // HyperFun's MAX_LENGTH_OF_STRING

struct Reserved {
  std::string_view word;
  Tok kind;
};
constexpr Reserved kReserved[] = {
    {"array", Tok::Array}, {"if", Tok::If},       {"then", Tok::Then},       {"else", Tok::Else},
    {"endif", Tok::EndIf}, {"while", Tok::While}, {"loop", Tok::Loop},       {"endloop", Tok::EndLoop},
    {"and", Tok::And},     {"or", Tok::Or},       {"not", Tok::Not},         {"xor", Tok::Xor},
};

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool isWordChar(char c) { return isDigit(c) || isLetter(c) || c == '_'; }

class Scanner {
 public:
  Scanner(const SourceFile& file, DiagnosticLog& log) : file_(file), text_(file.text), log_(log) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    for (;;) {
      skipBlanksAndComments();
      Token t;
      t.line = line_;
      t.col = col_;
      if (pos_ >= text_.size()) {
        t.kind = Tok::End;
        tokens.push_back(t);
        return tokens;
      }
      if (scanOne(t)) tokens.push_back(std::move(t));
    }
  }

 private:
  char peek(size_t ahead = 0) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }
  void advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      col_ = 1;
    } else {
      ++col_;
    }
    ++pos_;
  }
  void error(int line, int col, std::string message) {
    if (errors_++ < DiagnosticLog::kMaxErrors) log_.error({&file_, line, col}, std::move(message));
  }

  void skipBlanksAndComments() {
    for (;;) {
      const char c = peek();
      // HyperFun itself knows only ' ', '\t' and '\n'; '\r' (Windows line ends) and the other
      // blanks are accepted too.
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
        advance();
      } else if (c == '-' && peek(1) == '-') {  // a comment, even in `a--b`
        while (pos_ < text_.size() && peek() != '\n') advance();
      } else {
        return;
      }
    }
  }

  // Scans one token into t (kind, text, number); false after a lexical error.
  bool scanOne(Token& t) {
    const char c = peek();
    if (isLetter(c)) return scanWord(t);
    if (isDigit(c) || c == '.') return scanNumber(t);
    if (c == '"') return scanString(t);
    advance();
    t.text = std::string(1, c);
    switch (c) {
      case '^': t.kind = Tok::Caret; return true;
      case '+': t.kind = Tok::Plus; return true;
      case '-': t.kind = Tok::Minus; return true;
      case '~': t.kind = Tok::Tilde; return true;
      case '*': t.kind = Tok::Star; return true;
      case '&': t.kind = Tok::Amp; return true;
      case '|': t.kind = Tok::Bar; return true;
      case '\\': t.kind = Tok::Backslash; return true;
      case '@': t.kind = Tok::At; return true;
      case ',': t.kind = Tok::Comma; return true;
      case ';': t.kind = Tok::Semicolon; return true;
      case '=': t.kind = Tok::Assign; return true;
      case '(': t.kind = Tok::LParen; return true;
      case ')': t.kind = Tok::RParen; return true;
      case '[': t.kind = Tok::LBracket; return true;
      case ']': t.kind = Tok::RBracket; return true;
      case '{': t.kind = Tok::LBrace; return true;
      case '}': t.kind = Tok::RBrace; return true;
      case '/': return pair(t, '=', Tok::NotEqual, Tok::Slash);
      case '<': return pair(t, '=', Tok::LessEq, Tok::Less);
      case '>': return pair(t, '=', Tok::GreaterEq, Tok::Greater);
      default: break;
    }
    std::string shown = std::string(1, c);
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) >= 127) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", static_cast<unsigned>(static_cast<unsigned char>(c)));
      shown = hex;
    }
    error(t.line, t.col, "unexpected character '" + shown + "'");
    return false;
  }

  bool pair(Token& t, char second, Tok both, Tok single) {
    if (peek() == second) {
      advance();
      t.text += second;
      t.kind = both;
    } else {
      t.kind = single;
    }
    return true;
  }

  bool scanWord(Token& t) {
    const size_t start = pos_;
    while (isWordChar(peek())) advance();
    std::string word(text_.substr(start, pos_ - start));
    for (char& ch : word) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (word.size() > kMaxIdentifier) {
      error(t.line, t.col, "identifier longer than 256 characters");
      return false;
    }
    t.kind = Tok::Ident;
    for (const Reserved& r : kReserved)
      if (r.word == word) t.kind = r.kind;
    t.text = std::move(word);
    return true;
  }

  bool scanNumber(Token& t) {
    const size_t start = pos_;
    std::string problem;
    if (peek() == '.') {
      advance();
      if (!isDigit(peek())) problem = "'.' must be followed by digits";
    } else {
      if (peek() == '0' && isDigit(peek(1)))
        problem = "a number with more than one digit before the point may not start with 0";
      while (isDigit(peek())) advance();
      if (peek() == '.') advance();
    }
    while (isDigit(peek())) advance();
    if (problem.empty() && (peek() == 'e' || peek() == 'E')) {
      advance();
      if (peek() == '+' || peek() == '-') advance();
      if (peek() == '0') problem = "an exponent may not start with 0";
      else if (!isDigit(peek())) problem = "'e' must be followed by the exponent's digits";
      while (isDigit(peek())) advance();
    }
    if (!problem.empty()) {
      while (isWordChar(peek()) || peek() == '.') advance();  // skip the rest of the bad number
      const std::string bad(text_.substr(start, pos_ - start));
      error(t.line, t.col, "'" + bad + "' is not a HyperFun number: " + problem);
      return false;
    }
    t.kind = Tok::Number;
    t.text = std::string(text_.substr(start, pos_ - start));
    const std::string digits = t.text[0] == '.' ? "0" + t.text : t.text;  // from_chars wants a digit first
    const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), t.number);
    if (ec != std::errc() || ptr != digits.data() + digits.size()) {
      error(t.line, t.col, "'" + t.text + "' is out of the range of double-precision numbers");
      return false;
    }
    return true;
  }

  bool scanString(Token& t) {
    advance();
    const size_t start = pos_;
    while (pos_ < text_.size() && peek() != '"' && peek() != '\n') advance();
    if (peek() != '"') {
      error(t.line, t.col, "string without its closing '\"'");
      return false;
    }
    t.kind = Tok::String;
    t.text = std::string(text_.substr(start, pos_ - start));
    advance();
    return true;
  }

  const SourceFile& file_;
  std::string_view text_;
  DiagnosticLog& log_;
  size_t pos_ = 0;
  int line_ = 1, col_ = 1;
  int errors_ = 0;
};

}  // namespace

std::string tokenSpelling(Tok kind) {
  switch (kind) {
    case Tok::End: return "end of file";
    case Tok::Number: return "number";
    case Tok::Ident: return "name";
    case Tok::String: return "string";
    case Tok::Array: return "'array'";
    case Tok::If: return "'if'";
    case Tok::Then: return "'then'";
    case Tok::Else: return "'else'";
    case Tok::EndIf: return "'endif'";
    case Tok::While: return "'while'";
    case Tok::Loop: return "'loop'";
    case Tok::EndLoop: return "'endloop'";
    case Tok::And: return "'and'";
    case Tok::Or: return "'or'";
    case Tok::Not: return "'not'";
    case Tok::Xor: return "'xor'";
    case Tok::Caret: return "'^'";
    case Tok::Plus: return "'+'";
    case Tok::Minus: return "'-'";
    case Tok::Tilde: return "'~'";
    case Tok::Slash: return "'/'";
    case Tok::Star: return "'*'";
    case Tok::Amp: return "'&'";
    case Tok::Bar: return "'|'";
    case Tok::Backslash: return "'\\'";
    case Tok::At: return "'@'";
    case Tok::Comma: return "','";
    case Tok::Semicolon: return "';'";
    case Tok::Assign: return "'='";
    case Tok::LParen: return "'('";
    case Tok::RParen: return "')'";
    case Tok::LBracket: return "'['";
    case Tok::RBracket: return "']'";
    case Tok::LBrace: return "'{'";
    case Tok::RBrace: return "'}'";
    case Tok::Less: return "'<'";
    case Tok::LessEq: return "'<='";
    case Tok::Greater: return "'>'";
    case Tok::GreaterEq: return "'>='";
    case Tok::NotEqual: return "'/='";
  }
  return "?";
}

std::vector<Token> scanHyperFun(const SourceFile& file, DiagnosticLog& log) { return Scanner(file, log).run(); }

}  // namespace pf::field::hyperfun
