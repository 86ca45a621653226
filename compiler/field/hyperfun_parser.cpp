// The HyperFun parser (see hyperfun_parser.h): recursive descent over HyperFun's C grammar.
#include "compiler/field/hyperfun_parser.h"

#include <algorithm>
#include <cmath>

#include "compiler/field/hyperfun_library.h"
#include "compiler/stack_guard.h"

namespace pf::field::hyperfun {
namespace {

constexpr int kMaxArraySize = 1000000;

// HyperFun's HF_round (to the nearest integer, halves up) of an array size, clamped to
// [0, kMaxArraySize + 1] so that it fits an int.
int roundSize(double v) {
  const double c = std::ceil(v);
  const double r = c - v > 0.5 ? c - 1.0 : c;
  return r >= 1.0 ? static_cast<int>(std::min(r, kMaxArraySize + 1.0)) : 0;
}

constexpr int kMaxTreeDepth = 4000;  // levels of an expression tree
constexpr int kMaxNesting = 1000;    // parentheses, signs and blocks inside each other

bool isSetOp(Op op) { return op == Op::Union || op == Op::Intersection || op == Op::Subtraction || op == Op::Product; }

class Parser {
 public:
  Parser(const SourceFile& file, const std::vector<Token>& tokens, DiagnosticLog& log)
      : file_(file), toks_(tokens), log_(log) {}

  Program program() {
    Program p;
    while (cur().kind != Tok::End) {
      ObjectDef obj = object();
      for (const ObjectDef& earlier : p.objects)
        if (earlier.name == obj.name)
          fail(obj.line, obj.col,
               "object '" + obj.name + "' is already defined on line " + std::to_string(earlier.line));
      p.objects.push_back(std::move(obj));
    }
    if (p.objects.empty()) fail(cur(), "the file defines no object (expected 'name(x[3], a[1]) { ... }')");
    return p;
  }

 private:
  const Token& cur() const { return toks_[pos_]; }
  const Token& next() const { return toks_[pos_ + 1 < toks_.size() ? pos_ + 1 : pos_]; }
  const Token& take() {
    const Token& t = toks_[pos_];
    if (pos_ + 1 < toks_.size()) ++pos_;
    return t;
  }
  bool at(Tok k) const { return cur().kind == k; }
  bool atName(std::string_view name) const { return cur().kind == Tok::Ident && cur().text == name; }

  [[noreturn]] void fail(int line, int col, std::string message) {
    log_.error({&file_, line, col}, std::move(message));
    throw CompileAbort();
  }
  [[noreturn]] void fail(const Token& t, std::string message) { fail(t.line, t.col, std::move(message)); }

  // Counts the parser's own recursion (parentheses, signs, blocks) while in scope.
  struct Nested {
    Parser& p;
    Nested(Parser& parser, const Token& at) : p(parser) {
      if (++p.nesting_ > kMaxNesting)
        p.fail(at, "nested more than " + std::to_string(kMaxNesting) + " levels deep (split it with variables)");
      if (stackNearlyExhausted()) p.fail(at, "nested too deep for this thread's stack (split it with variables)");
    }
    ~Nested() { --p.nesting_; }
  };
  void checkDepth(Expr& e) {
    for (const Expr& a : e.args) e.depth = std::max(e.depth, a.depth + 1);
    if (e.depth > kMaxTreeDepth)
      fail(e.line, e.col, "expression nested more than " + std::to_string(kMaxTreeDepth) +
                              " levels deep (split it with variables)");
  }
  static std::string describe(const Token& t) {
    switch (t.kind) {
      case Tok::Ident: return "'" + t.text + "'";
      case Tok::Number: return "'" + t.text + "'";
      case Tok::String: return "\"" + t.text + "\"";
      default: return tokenSpelling(t.kind);
    }
  }
  const Token& expect(Tok k, std::string_view context) {
    if (!at(k)) fail(cur(), "expected " + tokenSpelling(k) + std::string(context) + ", found " + describe(cur()));
    return take();
  }

  void checkSize(const Token& n, int size) {
    if (size < 1) fail(n, "an array's size must be at least 1");
    if (size > kMaxArraySize) fail(n, "an array's size must be at most " + std::to_string(kMaxArraySize));
  }

  // `x [ N ]` in a header, returning N.
  int headerArray(std::string_view name, int& line, int& col) {
    if (!atName(name))
      fail(cur(), "expected '" + std::string(name) + "[...]' in the object's header, found " + describe(cur()));
    line = cur().line;
    col = cur().col;
    take();
    expect(Tok::LBracket, " after '" + std::string(name) + "'");
    const Token& n = expect(Tok::Number, " (the array's size)");
    const int size = roundSize(n.number);
    checkSize(n, size);
    expect(Tok::RBracket, " after the array's size");
    return size;
  }

  ObjectDef object() {
    ObjectDef obj;
    if (!at(Tok::Ident))
      fail(cur(), "expected an object name ('my_model(x[3], a[1]) { ... }'), found " + describe(cur()));
    if (isLibraryName(cur().text))
      fail(cur(), "'" + cur().text + "' is a library function's name and cannot name an object");
    obj.name = cur().text;
    obj.line = cur().line;
    obj.col = cur().col;
    take();
    int line = 0, col = 0;
    expect(Tok::LParen, " after the object's name");
    obj.x_size = headerArray("x", line, col);
    expect(Tok::Comma, " after 'x[...]'");
    obj.a_size = headerArray("a", obj.a_line, obj.a_col);
    if (at(Tok::Comma)) {
      take();
      obj.s_size = headerArray("s", line, col);
      obj.declares_s = true;
    }
    expect(Tok::RParen, " to close the object's header");
    expect(Tok::LBrace, " to open the object's body");
    while (at(Tok::Array)) arrayDecl(obj);
    obj.body = statements(obj, false);
    if (!atName(obj.name)) {
      if (at(Tok::Array)) fail(cur(), "array declarations must come before the statements");
      if (atName("x") || atName("a"))
        fail(cur(), "'" + cur().text +
                        "' cannot be assigned (copy it into a declared array first: 'array xt[3]; xt[1] = x[1]; ...')");
      fail(cur(), "expected a statement or the final '" + obj.name + " = expression;', found " + describe(cur()));
    }
    take();
    expect(Tok::Assign, " after '" + obj.name + "'");
    obj.result = expr();
    expect(Tok::Semicolon, " after the object's value");
    if (!at(Tok::RBrace))
      fail(cur(), "'" + obj.name + " = ...;' must be the last statement of '" + obj.name + "': expected '}', found " +
                      describe(cur()));
    take();
    return obj;
  }

  void arrayDecl(ObjectDef& obj) {
    take();  // 'array'
    for (;;) {
      if (!at(Tok::Ident) || isLibraryName(cur().text) || cur().text == "x" || cur().text == "a" || cur().text == "s" ||
          cur().text == obj.name)
        fail(cur(), "expected the name of a new array, found " + describe(cur()));
      ArrayDecl d{cur().text, 0, cur().line, cur().col};
      take();
      for (const ArrayDecl& e : obj.arrays)
        if (e.name == d.name)
          fail(d.line, d.col, "array '" + d.name + "' is already declared on line " + std::to_string(e.line));
      expect(Tok::LBracket, " after the array's name");
      const Token& n = expect(Tok::Number, " (the array's size; it must be a number)");
      d.size = roundSize(n.number);
      checkSize(n, d.size);
      expect(Tok::RBracket, " after the array's size");
      obj.arrays.push_back(d);
      if (!at(Tok::Comma)) break;
      take();
    }
    expect(Tok::Semicolon, " after the array declaration");
  }

  // Statements up to the first token that cannot start one. In a block (if/while) the object's
  // own name is an error: HyperFun allows its assignment only as the last statement.
  std::vector<Stmt> statements(ObjectDef& obj, bool in_block) {
    std::vector<Stmt> out;
    for (;;) {
      if (at(Tok::If) || at(Tok::While)) {
        out.push_back(control(obj));
      } else if (at(Tok::Ident) && cur().text != obj.name && cur().text != "x" && cur().text != "a") {
        out.push_back(assignment(obj));
      } else {
        if (in_block && atName(obj.name))
          fail(cur(), "'" + obj.name + "' can only be assigned by the object's last statement, not inside 'if' or "
                      "'while' (assign a variable here and end with '" + obj.name + " = variable;')");
        if (in_block && (atName("x") || atName("a")))
          fail(cur(), "'" + cur().text + "' cannot be assigned (copy it into a declared array first)");
        return out;
      }
    }
  }

  Stmt control(ObjectDef& obj) {
    const Nested nested(*this, cur());
    Stmt s;
    const bool is_if = at(Tok::If);
    s.kind = is_if ? Stmt::Kind::If : Stmt::Kind::While;
    s.line = cur().line;
    s.col = cur().col;
    take();
    s.value_line = cur().line;
    s.value_col = cur().col;
    s.value = condition();
    expect(is_if ? Tok::Then : Tok::Loop, " after the condition");
    s.body = statements(obj, true);
    if (is_if && at(Tok::Else)) {
      take();
      s.else_body = statements(obj, true);
      expect(Tok::EndIf, " to close 'if'");
    } else if (is_if && !at(Tok::EndIf)) {
      fail(cur(), "expected 'else' or 'endif', found " + describe(cur()));
    } else {
      expect(is_if ? Tok::EndIf : Tok::EndLoop, is_if ? " to close 'if'" : " to close 'while'");
    }
    expect(Tok::Semicolon, is_if ? " after 'endif'" : " after 'endloop'");
    return s;
  }

  Stmt assignment(ObjectDef& obj) {
    Stmt s;
    const Token& target = take();
    if (isLibraryName(target.text)) {
      if (at(Tok::LParen))
        fail(target, "a call is not a statement: assign its value ('dummy = " + target.text + "(...);')");
      fail(target, "'" + target.text + "' is a library function's name and cannot be assigned");
    }
    s.name = target.text;
    s.line = target.line;
    s.col = target.col;
    if (at(Tok::LBracket)) {
      take();
      s.kind = Stmt::Kind::AssignElement;
      s.index = expr();
      expect(Tok::RBracket, " after the index");
      expect(Tok::Assign, " after '" + s.name + "[...]'");
      s.value_line = cur().line;
      s.value_col = cur().col;
      s.value = expr();
    } else {
      expect(Tok::Assign, " after '" + s.name + "'");
      s.value_line = cur().line;
      s.value_col = cur().col;
      if (at(Tok::LBracket)) {
        s.kind = Stmt::Kind::AssignArray;
        take();
        for (;;) {
          double sign = 1.0;
          if (at(Tok::Minus) || at(Tok::Plus)) sign = take().kind == Tok::Minus ? -1.0 : 1.0;
          if (!at(Tok::Number))
            fail(cur(), "a whole-array assignment lists signed numbers only ('" + s.name + " = [0, -1.5, 2];'); assign "
                        "expressions item by item ('" + s.name + "[2] = r;')");
          s.items.push_back(sign * take().number);
          if (!at(Tok::Comma)) break;
          take();
        }
        expect(Tok::RBracket, " to close the list");
      } else {
        s.kind = Stmt::Kind::Assign;
        s.value = expr();
        obj.assigned.insert(s.name);
      }
    }
    expect(Tok::Semicolon, " after the assignment");
    return s;
  }

  // --- Real expressions ----------------------------------------------------------------------
  static Expr node(Expr::Kind kind, const Token& at) {
    Expr e;
    e.kind = kind;
    e.line = at.line;
    e.col = at.col;
    return e;
  }
  Expr binary(Op op, const Token& at, Expr lhs, Expr rhs) {
    Expr e = node(Expr::Kind::Binary, at);
    e.op = op;
    e.args.push_back(std::move(lhs));
    e.args.push_back(std::move(rhs));
    checkDepth(e);
    return e;
  }

  // fexpr := term { (+ - | & \ @) term }: one level, left to right (HyperFun's C interpreter).
  Expr expr() {
    const Nested nested(*this, cur());
    Expr lhs = term();
    bool set_seen = false, arith_seen = false, noted = false;
    for (;;) {
      Op op;
      switch (cur().kind) {
        case Tok::Plus: op = Op::Add; break;
        case Tok::Minus: op = Op::Sub; break;
        case Tok::Bar: op = Op::Union; break;
        case Tok::Amp: op = Op::Intersection; break;
        case Tok::Backslash: op = Op::Subtraction; break;
        case Tok::At: op = Op::Product; break;
        default: return lhs;
      }
      (isSetOp(op) ? set_seen : arith_seen) = true;
      const Token& t = take();
      if (set_seen && arith_seen && !noted) {
        log_.note({&file_, t.line, t.col},
                  "HyperFun gives the set operators | & \\ @ the precedence of + and -, applied left to right "
                  "(the documentation says they bind looser); parenthesize to make the order explicit");
        noted = true;
      }
      lhs = binary(op, t, std::move(lhs), term());
    }
  }

  Expr term() {
    Expr lhs = factor();
    while (at(Tok::Star) || at(Tok::Slash)) {
      const Token& t = take();
      lhs = binary(t.kind == Tok::Star ? Op::Mul : Op::Div, t, std::move(lhs), factor());
    }
    return lhs;
  }

  // factor := unary { ^ unary }: left-associative, so 2^3^2 = (2^3)^2.
  Expr factor() {
    Expr lhs = unary();
    while (at(Tok::Caret)) {
      const Token& t = take();
      lhs = binary(Op::Pow, t, std::move(lhs), unary());
    }
    return lhs;
  }

  // A sign binds tighter than ^: -2^2 = (-2)^2.
  Expr unary() {
    if (at(Tok::Minus) || at(Tok::Plus) || at(Tok::Tilde)) {
      const Nested nested(*this, cur());
      const Token& t = take();
      Expr e = node(Expr::Kind::Unary, t);
      e.op = t.kind == Tok::Minus ? Op::Negate : t.kind == Tok::Plus ? Op::Plus : Op::Complement;
      e.args.push_back(unary());
      checkDepth(e);
      return e;
    }
    return primary();
  }

  Expr primary() {
    const Token& t = cur();
    switch (t.kind) {
      case Tok::Number: {
        Expr e = node(Expr::Kind::Number, t);
        e.number = t.number;
        take();
        return e;
      }
      case Tok::LParen: {
        take();
        Expr e = expr();
        expect(Tok::RParen, " to close '('");
        return e;
      }
      case Tok::Ident: {
        take();
        if (at(Tok::LParen)) {
          Expr e = node(Expr::Kind::Call, t);
          e.name = t.text;
          take();
          if (!at(Tok::RParen)) {
            e.args.push_back(expr());
            while (at(Tok::Comma)) {
              take();
              e.args.push_back(expr());
            }
          }
          expect(Tok::RParen, " to close the arguments of '" + t.text + "'");
          checkDepth(e);
          return e;
        }
        if (at(Tok::LBracket)) {
          Expr e = node(Expr::Kind::Element, t);
          e.name = t.text;
          take();
          e.args.push_back(expr());
          expect(Tok::RBracket, " after the index");
          checkDepth(e);
          return e;
        }
        if (isLibraryName(t.text)) fail(t, "expected '(' after the function name '" + t.text + "'");
        Expr e = node(Expr::Kind::Name, t);
        e.name = t.text;
        return e;
      }
      case Tok::String:
        fail(t, "a string is allowed only as the argument of a library function that reads a file, and primflow "
                "supports none of them");
      default:
        fail(t, "expected an expression, found " + describe(t));
    }
  }

  // --- Conditions (if / while) ---------------------------------------------------------------
  // bexpr := cmp { (and | or) cmp }: one level, left to right.
  Expr condition() {
    Expr lhs = comparison();
    while (at(Tok::And) || at(Tok::Or)) {
      const Token& t = take();
      lhs = binary(t.kind == Tok::And ? Op::And : Op::Or, t, std::move(lhs), comparison());
    }
    return lhs;
  }

  Expr comparison() {
    Expr lhs = conditionOperand();
    for (;;) {
      Op op;
      switch (cur().kind) {
        case Tok::Less: op = Op::Less; break;
        case Tok::LessEq: op = Op::LessEq; break;
        case Tok::Greater: op = Op::Greater; break;
        case Tok::GreaterEq: op = Op::GreaterEq; break;
        case Tok::Assign: op = Op::Equal; break;
        case Tok::NotEqual: op = Op::NotEqual; break;
        default: return lhs;
      }
      const Token& t = take();
      lhs = binary(op, t, std::move(lhs), conditionOperand());
    }
  }

  // bprim := not bprim | ( bexpr ) | fexpr. A leading '(' is always a boolean group (HyperFun).
  Expr conditionOperand() {
    const Nested nested(*this, cur());
    if (at(Tok::Not)) {
      const Token& t = take();
      Expr e = node(Expr::Kind::Unary, t);
      e.op = Op::Not;
      e.args.push_back(conditionOperand());
      checkDepth(e);
      return e;
    }
    if (at(Tok::LParen)) {
      take();
      Expr e = condition();
      expect(Tok::RParen, " to close '('");
      switch (cur().kind) {
        case Tok::Plus: case Tok::Minus: case Tok::Star: case Tok::Slash: case Tok::Caret:
        case Tok::Bar: case Tok::Amp: case Tok::Backslash: case Tok::At:
          fail(cur(), "in a condition, HyperFun reads a '(' that starts an operand as a boolean group, so " +
                          describe(cur()) + " cannot follow its ')': write '2*(a+b) > 1', not '(a+b)*2 > 1'");
        default: break;
      }
      return e;
    }
    return expr();
  }

  const SourceFile& file_;
  const std::vector<Token>& toks_;
  DiagnosticLog& log_;
  size_t pos_ = 0;
  int nesting_ = 0;
};

}  // namespace

std::string opSpelling(Op op) {
  switch (op) {
    case Op::Negate: return "'-'";
    case Op::Plus: return "'+'";
    case Op::Complement: return "'~'";
    case Op::Not: return "'not'";
    case Op::Add: return "'+'";
    case Op::Sub: return "'-'";
    case Op::Mul: return "'*'";
    case Op::Div: return "'/'";
    case Op::Pow: return "'^'";
    case Op::Union: return "'|'";
    case Op::Intersection: return "'&'";
    case Op::Subtraction: return "'\\'";
    case Op::Product: return "'@'";
    case Op::Less: return "'<'";
    case Op::LessEq: return "'<='";
    case Op::Greater: return "'>'";
    case Op::GreaterEq: return "'>='";
    case Op::Equal: return "'='";
    case Op::NotEqual: return "'/='";
    case Op::And: return "'and'";
    case Op::Or: return "'or'";
  }
  return "?";
}

std::optional<Program> parseHyperFun(const SourceFile& file, const std::vector<Token>& tokens, DiagnosticLog& log) {
  try {
    return Parser(file, tokens, log).program();
  } catch (const CompileAbort&) {
    return std::nullopt;
  }
}

}  // namespace pf::field::hyperfun
