// Recursive-descent parser for the primitive language (grammar: docs/language.md).
// Precedence, loosest first: ?:  ||  &&  == !=  < <= > >=  + -  * / %  unary  postfix.
#include "compiler/parser.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "compiler/stack_guard.h"

namespace pf {
namespace {

// The nesting limit: deep input is an error, not a stack overflow. It bounds every path from a
// unit's root to a leaf -- statements, parentheses, calls and each operator applied to another's
// result -- so that sema and lowering, which recurse over the tree, stay within a thread's stack
// (docs/reliability.md).
constexpr int kMaxDepth = 256;

class Parser {
 public:
  Parser(std::vector<Token> toks, DiagnosticLog& log) : t_(std::move(toks)), log_(log) {}

  Program program() {
    Program p;
    while (!at(Tok::End)) {
      try {
        if (at(Tok::KwPrimitive) || at(Tok::KwInterpolator)) {
          p.units.push_back(unit());
        } else if (atFieldUnit()) {
          p.units.push_back(field());
        } else if (isTypeToken(cur().kind)) {
          p.units.push_back(function());
        } else {
          error(cur().loc, "expected 'primitive', 'interpolator', 'field' or a function at top level, found " + describe(cur()));
          skipToUnit();
        }
      } catch (const Sync&) {
        skipToUnit();
      }
    }
    return p;
  }

 private:
  struct Sync {};  // thrown after an error to resynchronise

  std::vector<Token> t_;
  size_t pos_ = 0;
  DiagnosticLog& log_;
  int depth_ = 0;

  const Token& cur() const { return t_[pos_]; }
  const Token& next() const { return t_[std::min(pos_ + 1, t_.size() - 1)]; }
  const Token& ahead(size_t n) const { return t_[std::min(pos_ + n, t_.size() - 1)]; }
  // The token after the type that starts here: `fixed<bits,frac>` is six tokens, the other
  // types one (a malformed fixed<...> gives the token where it goes wrong; baseType() reports it).
  const Token& afterType() const {
    if (!at(Tok::KwFixed)) return next();
    static constexpr Tok shape[] = {Tok::Lt, Tok::IntLit, Tok::Comma, Tok::IntLit, Tok::Gt};
    for (size_t i = 0; i < 5; ++i)
      if (ahead(i + 1).kind != shape[i]) return ahead(i + 1);
    return ahead(6);
  }
  // A conversion such as float(i) or fixed<16,8>(x): a type followed by '('.
  bool atConversion() const { return isTypeToken(cur().kind) && afterType().kind == Tok::LParen; }
  bool at(Tok k) const { return cur().kind == k; }
  // A label of the interpolation construct: a kind's keyword, or `name:` (no statement begins
  // with a name and a colon, so the name is a shared interpolator's).
  bool atInterpolationLabel() const {
    return at(Tok::KwPerspectiveLinear) || at(Tok::KwLinear) || at(Tok::KwDefault) ||
           (at(Tok::Ident) && next().kind == Tok::Colon);
  }
  Token take() {
    Token tk = cur();
    if (pos_ + 1 < t_.size()) ++pos_;
    return tk;
  }
  bool accept(Tok k) {
    if (!at(k)) return false;
    take();
    return true;
  }
  static std::string describe(const Token& tk) {
    if (tk.kind == Tok::End) return "end of file";
    if (tk.kind == Tok::Ident || tk.kind == Tok::IntLit || tk.kind == Tok::FloatLit)
      return "'" + tk.text + "'";
    return tokenName(tk.kind);
  }
  [[noreturn]] void fail(SourceLoc loc, const std::string& msg) {
    error(loc, msg);
    throw Sync{};
  }
  void error(SourceLoc loc, const std::string& msg) {
    log_.error(loc, msg);
    if (log_.errorCount() >= DiagnosticLog::kMaxErrors) throw CompileAbort{};
  }
  Token expect(Tok k, const char* context) {
    if (!at(k)) {
      // A missing ';' is reported where it is missing, as GCC and Clang do: just after the
      // token before it, not at the next statement (often on a later line).
      if (k == Tok::Semi)
        fail(afterPrevious(), std::string("expected ';' ") + context + ", before " + describe(cur()));
      fail(cur().loc, std::string("expected ") + tokenName(k) + " " + context + ", found " + describe(cur()));
    }
    return take();
  }
  // Just past the end of the token before the current one (tokens never span lines).
  SourceLoc afterPrevious() const {
    if (pos_ == 0) return cur().loc;
    const Token& p = t_[pos_ - 1];
    SourceLoc loc = p.loc;
    loc.col += static_cast<int>(p.text.size());
    return loc;
  }
  // Whether the current token can begin an expression.
  bool atExpressionStart() const {
    switch (cur().kind) {
      case Tok::IntLit: case Tok::FloatLit: case Tok::KwTrue: case Tok::KwFalse: case Tok::LParen:
      case Tok::Ident: case Tok::Minus: case Tok::Bang: case Tok::Plus:
        return true;
      default:
        return atConversion();
    }
  }
  bool atUnitStart() const {
    return at(Tok::KwPrimitive) || at(Tok::KwInterpolator) || atFieldUnit() ||
           (isTypeToken(cur().kind) && afterType().kind == Tok::Ident);
  }
  void skipToUnit() {
    if (!atUnitStart()) take();
    while (!at(Tok::End) && !atUnitStart()) take();
  }
  // After an error inside a block: skip past the next ';' or to a '}' at this level.
  void skipStatement() {
    int nest = 0;
    while (!at(Tok::End)) {
      if (at(Tok::LBrace)) ++nest;
      if (at(Tok::RBrace)) {
        if (nest == 0) return;
        --nest;
      }
      if (at(Tok::Semi) && nest == 0) {
        take();
        return;
      }
      take();
    }
  }

  struct DepthGuard {
    Parser& p;
    DepthGuard(Parser& parser, SourceLoc loc) : p(parser) {
      const bool too_deep = ++p.depth_ > kMaxDepth;
      if (too_deep || stackNearlyExhausted()) {
        p.depth_ = 0;
        p.error(loc, too_deep ? "nesting too deep (more than " + std::to_string(kMaxDepth) + " levels)"
                              : std::string("nesting too deep for this thread's stack"));
        throw CompileAbort{};
      }
    }
    ~DepthGuard() { if (p.depth_ > 0) --p.depth_; }
  };

  static bool isTypeToken(Tok k) {
    switch (k) {
      case Tok::KwFloat: case Tok::KwInt: case Tok::KwBool: case Tok::KwPoint:
      case Tok::KwVector: case Tok::KwNormal: case Tok::KwColor: case Tok::KwMatrix: case Tok::KwInterpolatorData:
      case Tok::KwFixed:
        return true;
      default: return false;
    }
  }
  static bool isQualifierToken(Tok k) {
    return k == Tok::KwUniform || k == Tok::KwVarying || k == Tok::KwInout;
  }
  static BaseType baseOf(Tok k) {
    switch (k) {
      case Tok::KwFloat: return BaseType::Float;
      case Tok::KwInt: return BaseType::Int;
      case Tok::KwBool: return BaseType::Bool;
      case Tok::KwPoint: return BaseType::Point;
      case Tok::KwVector: return BaseType::Vector;
      case Tok::KwNormal: return BaseType::Normal;
      case Tok::KwColor: return BaseType::Color;
      case Tok::KwMatrix: return BaseType::Matrix;
      case Tok::KwInterpolatorData: return BaseType::InterpData;
      case Tok::KwFixed: return BaseType::Fixed;
      default: return BaseType::Void;
    }
  }

  Qualifier qualifiers() {
    bool uni = false, var = false, inout = false;
    SourceLoc first = cur().loc;
    while (isQualifierToken(cur().kind)) {
      Token q = take();
      if (q.kind == Tok::KwUniform) uni = true;
      if (q.kind == Tok::KwVarying) var = true;
      if (q.kind == Tok::KwInout) inout = true;
    }
    if (uni && var) error(first, "a declaration cannot be both 'uniform' and 'varying'");
    if (inout) return var ? Qualifier::InoutVarying : Qualifier::Inout;
    if (var) return Qualifier::Varying;
    if (uni) return Qualifier::Uniform;
    return Qualifier::None;
  }

  Type baseType() {
    if (!isTypeToken(cur().kind)) fail(cur().loc, "expected a type, found " + describe(cur()));
    if (at(Tok::KwFixed)) return fixedType();
    return Type::of(baseOf(take().kind));
  }

  // fixed<bits,frac>: 1 <= bits <= 64, 0 <= frac <= bits.
  Type fixedType() {
    take();
    expect(Tok::Lt, "after 'fixed' (a fixed-point type is fixed<bits,frac>, e.g. fixed<16,8>)");
    auto number = [&](const char* what, long lo, long hi) {
      if (!at(Tok::IntLit))
        fail(cur().loc, std::string("expected ") + what + " of fixed<bits,frac> (an integer), found " + describe(cur()));
      Token n = take();
      errno = 0;
      long v = std::strtol(n.text.c_str(), nullptr, 10);
      if (errno != 0 || v < lo || v > hi)
        fail(n.loc, std::string(what) + " of fixed<bits,frac> must be between " + std::to_string(lo) + " and " +
                        std::to_string(hi) + ", not " + n.text);
      return static_cast<int>(v);
    };
    int bits = number("the bits", 1, 64);
    expect(Tok::Comma, "between the bits and the fraction bits of fixed<bits,frac>");
    int frac = number("the fraction bits", 0, bits);
    expect(Tok::Gt, "to close fixed<bits,frac>");
    return Type::fixed(bits, frac);
  }

  // `[n]...`; `allow_parameter_sized`: the first may be `[]` (a primitive's parameter).
  void arrayDims(Type& t, bool allow_parameter_sized = false) {
    while (at(Tok::LBracket)) {
      SourceLoc loc = take().loc;
      if (allow_parameter_sized && t.dims.empty() && accept(Tok::RBracket)) {
        t.dims.push_back(0);
        continue;
      }
      if (!at(Tok::IntLit)) fail(cur().loc, "expected an array size (a positive integer), found " + describe(cur()));
      Token n = take();
      long v = std::strtol(n.text.c_str(), nullptr, 10);
      if (v <= 0 || v > 65536) fail(n.loc, "array size must be between 1 and 65536");
      t.dims.push_back(static_cast<int>(v));
      expect(Tok::RBracket, "after the array size");
      (void)loc;
    }
  }

  Unit unit() {
    Unit u;
    Token kw = take();
    u.kind = kw.kind == Tok::KwPrimitive ? UnitKind::Primitive : UnitKind::Interpolator;
    u.loc = kw.loc;
    u.name = expect(Tok::Ident, "after 'primitive'/'interpolator' (the unit's name)").text;
    expect(Tok::LParen, "to open the parameter list");
    while (!at(Tok::RParen)) {
      Qualifier q = qualifiers();
      Type base = baseType();
      do {
        Param p;
        p.loc = cur().loc;
        p.qualifier = q;
        p.type = base;
        p.name = expect(Tok::Ident, "(a parameter name)").text;
        arrayDims(p.type, u.kind == UnitKind::Primitive);
        u.params.push_back(std::move(p));
      } while (accept(Tok::Comma));
      if (!accept(Tok::Semi)) break;
    }
    expect(Tok::RParen, "to close the parameter list");
    u.body = block();
    return u;
  }

  // type name(type a, type b[3], ...) { ... }: a function, inlined where it is called.
  Unit function() {
    Unit u;
    u.kind = UnitKind::Function;
    u.loc = cur().loc;
    u.return_type = baseType();
    u.name = expect(Tok::Ident, "(the function's name)").text;
    expect(Tok::LParen, "to open the parameter list");
    if (!at(Tok::RParen)) {
      do {
        Param p;
        p.loc = cur().loc;
        p.qualifier = qualifiers();
        p.type = baseType();
        p.loc = cur().loc;
        p.name = expect(Tok::Ident, "(a parameter name)").text;
        arrayDims(p.type);
        u.params.push_back(std::move(p));
      } while (accept(Tok::Comma));
    }
    expect(Tok::RParen, "to close the parameter list");
    u.body = block();
    return u;
  }

  // `field` is a keyword only where a unit starts (`field` then a type): elsewhere it stays an
  // identifier, as the implicit primitive's parameter `field` is.
  bool atFieldUnit() const { return at(Tok::Ident) && cur().text == "field" && isTypeToken(next().kind); }

  // field float name(point p, float a, ...) { ... }: a function with the unit's kind.
  Unit field() {
    const SourceLoc loc = take().loc;
    Unit u = function();
    u.kind = UnitKind::Field;
    u.loc = loc;
    return u;
  }

  std::vector<StmtPtr> block() {
    expect(Tok::LBrace, "to open a block");
    std::vector<StmtPtr> out;
    while (!at(Tok::RBrace) && !at(Tok::End)) {
      try {
        out.push_back(statement());
      } catch (const Sync&) {
        skipStatement();
      }
    }
    expect(Tok::RBrace, "to close the block");
    return out;
  }

  StmtPtr make(StmtKind k, SourceLoc loc) {
    auto s = std::make_unique<Stmt>();
    s->kind = k;
    s->loc = loc;
    return s;
  }

  StmtPtr statement() {
    DepthGuard guard(*this, cur().loc);
    SourceLoc loc = cur().loc;
    if (at(Tok::LBrace)) {
      auto s = make(StmtKind::Block, loc);
      s->body = block();
      return s;
    }
    if (isQualifierToken(cur().kind) || isTypeToken(cur().kind)) {
      // `float(x)` is a conversion expression, not a declaration.
      if (!atConversion()) return declaration();
    }
    if (accept(Tok::KwIf)) {
      auto s = make(StmtKind::If, loc);
      expect(Tok::LParen, "after 'if'");
      s->value = expression();
      expect(Tok::RParen, "after the condition");
      s->body.push_back(statement());
      if (accept(Tok::KwElse)) {
        s->has_else = true;
        s->else_body.push_back(statement());
      }
      return s;
    }
    if (accept(Tok::KwWhile)) {
      auto s = make(StmtKind::Loop, loc);
      expect(Tok::LParen, "after 'while'");
      s->value = expression();
      expect(Tok::RParen, "after the loop condition");
      s->body.push_back(statement());
      return s;
    }
    if (accept(Tok::KwFor)) {
      auto s = make(StmtKind::Loop, loc);
      s->op = "for";
      expect(Tok::LParen, "after 'for'");
      if (!accept(Tok::Semi)) s->init = simpleStatement(true);  // consumes its ';'
      if (!at(Tok::Semi)) s->value = expression();
      expect(Tok::Semi, "after the loop condition");
      if (!at(Tok::RParen)) s->step = simpleStatement(false);
      expect(Tok::RParen, "to close 'for (...)'");
      s->body.push_back(statement());
      return s;
    }
    if (at(Tok::KwBreak) || at(Tok::KwContinue)) {
      bool brk = take().kind == Tok::KwBreak;
      auto s = make(brk ? StmtKind::Break : StmtKind::Continue, loc);
      expect(Tok::Semi, brk ? "after 'break'" : "after 'continue'");
      return s;
    }
    if (accept(Tok::KwReturn)) {
      auto s = make(StmtKind::Return, loc);
      // Functions return a value (sema checks). After a bare `return` missing its ';', the next
      // statement (`float z = ...`, `if`, `}`) cannot be a value: the ';' is what is missing.
      if (!at(Tok::Semi) && atExpressionStart()) s->value = expression();
      expect(Tok::Semi, "after 'return'");
      return s;
    }
    if (accept(Tok::KwBound)) {
      auto s = make(StmtKind::Bound, loc);
      expect(Tok::LParen, "after 'bound'");
      for (int i = 0; i < 4; ++i) {
        if (i) expect(Tok::Comma, "between bound(xmin, ymin, xmax, ymax) arguments");
        s->bound_args.push_back(expression());
      }
      expect(Tok::RParen, "after bound(xmin, ymin, xmax, ymax)");
      expect(Tok::Semi, "after the bound statement");
      return s;
    }
    if (accept(Tok::KwInterpolatorReturn)) {
      auto s = make(StmtKind::InterpReturn, loc);
      if (accept(Tok::LParen)) {
        s->value = expression();
        expect(Tok::RParen, "after the interpolator_return value");
      }
      expect(Tok::Semi, "after interpolator_return");
      return s;
    }
    if (accept(Tok::KwInterpolation)) return interpolation(loc);
    return simpleStatement(true);
  }

  // A declaration, assignment or expression: the statements allowed in for (init; ; step).
  // With `semicolon`, the terminating ';' is consumed.
  StmtPtr simpleStatement(bool semicolon) {
    SourceLoc loc = cur().loc;
    if (isQualifierToken(cur().kind) || (isTypeToken(cur().kind) && !atConversion())) {
      if (!semicolon) fail(loc, "a declaration cannot be the step of a 'for' loop");
      return declaration();
    }
    ExprPtr e = expression();
    if (at(Tok::Assign) || at(Tok::PlusAssign) || at(Tok::MinusAssign) || at(Tok::StarAssign) ||
        at(Tok::SlashAssign)) {
      auto s = make(StmtKind::Assign, loc);
      s->op = take().text;
      s->target = std::move(e);
      s->value = expression();
      if (semicolon) expect(Tok::Semi, "after the assignment");
      return s;
    }
    auto s = make(StmtKind::ExprStmt, loc);
    s->value = std::move(e);
    if (semicolon) expect(Tok::Semi, "after the expression");
    return s;
  }

  StmtPtr declaration() {
    SourceLoc loc = cur().loc;
    Qualifier q = qualifiers();
    Type base = baseType();
    auto block = make(StmtKind::Block, loc);  // several declarators become a block of Decls
    do {
      auto s = make(StmtKind::Decl, cur().loc);
      s->qualifier = q;
      s->decl_type = base;
      s->name = expect(Tok::Ident, "(a variable name)").text;
      arrayDims(s->decl_type);
      if (accept(Tok::Assign)) s->value = expression();
      block->body.push_back(std::move(s));
    } while (accept(Tok::Comma));
    expect(Tok::Semi, "after the declaration");
    if (block->body.size() == 1) return std::move(block->body[0]);
    block->op = "decls";  // marks a declaration group: no new scope
    return block;
  }

  StmtPtr interpolation(SourceLoc loc) {
    auto s = make(StmtKind::Interpolation, loc);
    expect(Tok::LBrace, "after 'interpolation'");
    while (!at(Tok::RBrace) && !at(Tok::End)) {
      InterpolationCase c;
      // one or more labels
      bool any = false;
      while (atInterpolationLabel()) {
        Token lab = take();
        c.label_locs.push_back(lab.loc);
        if (lab.kind == Tok::Ident) {  // a shared interpolator's name
          c.interpolators.push_back(lab.text);
          c.name_locs.push_back(lab.loc);
        } else {
          c.kinds.push_back(lab.kind == Tok::KwPerspectiveLinear ? InterpKind::PerspectiveLinear
                            : lab.kind == Tok::KwLinear          ? InterpKind::Linear
                                                                 : InterpKind::Shared);
          c.kind_locs.push_back(lab.loc);
        }
        expect(Tok::Colon, "after the interpolation label");
        any = true;
      }
      if (!any)
        fail(cur().loc, "expected an interpolation label ('perspective_linear:', 'linear:', 'default:' or an interpolator's name), found " + describe(cur()));
      while (!at(Tok::RBrace) && !at(Tok::End) && !atInterpolationLabel()) {
        try {
          c.body.push_back(statement());
        } catch (const Sync&) {
          skipStatement();
        }
      }
      s->cases.push_back(std::move(c));
    }
    expect(Tok::RBrace, "to close the interpolation construct");
    return s;
  }

  // ---- expressions ----
  ExprPtr makeExpr(ExprKind k, SourceLoc loc) {
    auto e = std::make_unique<Expr>();
    e->kind = k;
    e->loc = loc;
    return e;
  }

  // Makes `child` an operand of `parent`. A tree taller than the nesting limit (with the
  // nesting above it) is refused here, where it grows: a long flat chain such as `a + b + c ...`
  // or `v[0][0]...` never nests the parser's own calls, but every later pass recurses down it.
  void adopt(Expr& parent, ExprPtr child) {
    parent.height = std::max(parent.height, child->height + 1);
    parent.args.push_back(std::move(child));
    if (depth_ + parent.height > kMaxDepth) {
      depth_ = 0;
      error(parent.loc, "expression nested too deep (more than " + std::to_string(kMaxDepth) +
                            " levels; each operator of a chain such as a + b + c is one): split it with local variables");
      throw CompileAbort{};
    }
  }

  ExprPtr expression() {
    DepthGuard guard(*this, cur().loc);
    return ternary();
  }

  ExprPtr ternary() {
    ExprPtr c = binary(0);
    if (at(Tok::Question)) {
      SourceLoc loc = take().loc;
      auto e = makeExpr(ExprKind::Ternary, loc);
      adopt(*e, std::move(c));
      adopt(*e, expression());
      expect(Tok::Colon, "in the conditional expression");
      adopt(*e, expression());
      return e;
    }
    return c;
  }

  static int precedence(Tok k) {
    switch (k) {
      case Tok::OrOr: return 1;
      case Tok::AndAnd: return 2;
      case Tok::Eq: case Tok::Ne: return 3;
      case Tok::Lt: case Tok::Le: case Tok::Gt: case Tok::Ge: return 4;
      case Tok::Plus: case Tok::Minus: return 5;
      case Tok::Star: case Tok::Slash: case Tok::Percent: return 6;
      default: return -1;
    }
  }

  ExprPtr binary(int min_prec) {
    ExprPtr lhs = unary();
    for (;;) {
      int p = precedence(cur().kind);
      if (p < 0 || p < min_prec) break;
      Token op = take();
      ExprPtr rhs = binary(p + 1);
      auto e = makeExpr(ExprKind::Binary, op.loc);
      e->name = op.text;
      adopt(*e, std::move(lhs));
      adopt(*e, std::move(rhs));
      lhs = std::move(e);
    }
    return lhs;
  }

  ExprPtr unary() {
    if (at(Tok::Minus) || at(Tok::Bang) || at(Tok::Plus)) {
      DepthGuard guard(*this, cur().loc);
      Token op = take();
      ExprPtr operand = unary();
      if (op.kind == Tok::Plus) return operand;
      auto e = makeExpr(ExprKind::Unary, op.loc);
      e->name = op.text;
      adopt(*e, std::move(operand));
      return e;
    }
    return postfix(primary());
  }

  ExprPtr postfix(ExprPtr e) {
    for (;;) {
      if (at(Tok::LBracket)) {
        take();
        auto ix = makeExpr(ExprKind::Index, e->loc);  // located where the indexed value starts
        adopt(*ix, std::move(e));
        adopt(*ix, expression());
        expect(Tok::RBracket, "after the index");
        e = std::move(ix);
      } else if (at(Tok::Dot)) {
        take();
        Token f = expect(Tok::Ident, "after '.' (a component such as x, y, z, w or r, g, b, a)");
        auto m = makeExpr(ExprKind::Member, f.loc);
        m->name = f.text;
        adopt(*m, std::move(e));
        e = std::move(m);
      } else {
        return e;
      }
    }
  }

  ExprPtr primary() {
    const Token& tk = cur();
    switch (tk.kind) {
      case Tok::IntLit: {
        auto e = makeExpr(ExprKind::IntLit, tk.loc);
        errno = 0;
        long long v = std::strtoll(tk.text.c_str(), nullptr, 10);
        if (errno == ERANGE || v > 2147483647LL) error(tk.loc, "integer literal out of range");
        e->number = static_cast<double>(v);
        take();
        return e;
      }
      case Tok::FloatLit: {
        auto e = makeExpr(ExprKind::FloatLit, tk.loc);
        e->number = std::strtod(tk.text.c_str(), nullptr);
        // Floats are 32-bit: a literal past the largest is a mistake, not infinity.
        if (!(std::fabs(e->number) <= static_cast<double>(std::numeric_limits<float>::max())))
          error(tk.loc, "floating-point literal '" + tk.text + "' is out of range (the largest float is 3.4e38)");
        take();
        return e;
      }
      case Tok::KwTrue: case Tok::KwFalse: {
        auto e = makeExpr(ExprKind::BoolLit, tk.loc);
        e->boolean = tk.kind == Tok::KwTrue;
        take();
        return e;
      }
      case Tok::LParen: {
        take();
        ExprPtr e = expression();
        expect(Tok::RParen, "to close the parenthesis");
        return e;
      }
      case Tok::Ident: {
        Token name = take();
        if (at(Tok::LParen)) return call(name.text, name.loc);
        auto e = makeExpr(ExprKind::Name, name.loc);
        e->name = name.text;
        return e;
      }
      default:
        if (atConversion()) {
          // constructor / conversion: float(i), point(x, y, z, w), fixed<16,8>(x)
          const SourceLoc loc = tk.loc;
          const Type type = baseType();
          ExprPtr e = call(baseTypeName(type.base), loc);
          e->conversion = type;
          return e;
        }
        fail(tk.loc, "expected an expression, found " + describe(tk));
    }
  }

  ExprPtr call(const std::string& callee, SourceLoc loc) {
    auto e = makeExpr(ExprKind::Call, loc);
    e->name = callee;
    expect(Tok::LParen, "to open the argument list");
    if (!at(Tok::RParen)) {
      do {
        adopt(*e, expression());
      } while (accept(Tok::Comma));
    }
    expect(Tok::RParen, "to close the argument list");
    return e;
  }
};

}  // namespace

Program parse(const SourceFile& file, DiagnosticLog& log) {
  std::vector<Token> toks = lex(file, log);
  Parser p(std::move(toks), log);
  try {
    return p.program();
  } catch (const CompileAbort&) {
    return Program{};
  }
}

}  // namespace pf
