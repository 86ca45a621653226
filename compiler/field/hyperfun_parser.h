// The HyperFun parser: tokens to a syntax tree of objects, statements and expressions.
//
// The grammar and precedence are those of HyperFun's C interpreter ([HFC] in shared/hyperfun.md,
// a.1-a.4), not of its documentation: the set operators | & \ @ share the level of binary + and -
// (left-associative), ^ is left-associative, and a unary sign binds tighter than ^, so `-2^2` is
// 4 and `2^3^2` is 64. In a condition, a '(' that starts an operand opens a boolean group. The
// tree is untyped: which names are arrays, variables, library functions or objects is decided
// when the tree is compiled (hyperfun_reader.cpp).
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "compiler/diagnostics.h"
#include "compiler/field/hyperfun_lexer.h"

namespace pf::field::hyperfun {

enum class Op : uint8_t {
  // unary
  Negate, Plus, Complement, Not,
  // arithmetic and set operations
  Add, Sub, Mul, Div, Pow, Union, Intersection, Subtraction, Product,
  // conditions
  Less, LessEq, Greater, GreaterEq, Equal, NotEqual, And, Or,
};

std::string opSpelling(Op op);  // "'+'", "'and'", ...

struct Expr {
  enum class Kind : uint8_t { Number, Name, Element, Unary, Binary, Call };
  Kind kind = Kind::Number;
  Op op = Op::Add;           // Unary, Binary
  double number = 0.0;       // Number
  std::string name;          // Name, Element (the array), Call (function or object), lowercased
  std::vector<Expr> args;    // Element: the index; Unary: 1 operand; Binary: 2; Call: the arguments
  int line = 0, col = 0;     // the token to point at: the name, the number or the operator
  int depth = 1;             // of the tree below (the parser limits it: compiling recurses)
};

struct Stmt {
  enum class Kind : uint8_t { Assign, AssignElement, AssignArray, If, While };
  Kind kind = Kind::Assign;
  std::string name;              // the assigned variable or array
  int line = 0, col = 0;         // the assigned name, or the 'if' / 'while' keyword
  Expr index;                    // AssignElement
  Expr value;                    // Assign, AssignElement: the value; If, While: the condition
  int value_line = 0, value_col = 0;  // where the value or condition starts ('[' of a list)
  std::vector<double> items;     // AssignArray: the signed numbers of the list
  std::vector<Stmt> body;        // If: the 'then' part; While: the loop body
  std::vector<Stmt> else_body;   // If
};

struct ArrayDecl {
  std::string name;
  int size = 0;
  int line = 0, col = 0;
};

struct ObjectDef {
  std::string name;  // lowercased
  int line = 0, col = 0;
  int x_size = 0, a_size = 0, s_size = 1;  // without an s array in the header, s[1] (as HyperFun)
  bool declares_s = false;
  int a_line = 0, a_col = 0;  // the header's `a`, for parameter-count errors
  std::vector<ArrayDecl> arrays;
  std::vector<Stmt> body;
  Expr result;                     // the final `name = expression;`
  std::set<std::string> assigned;  // every variable some statement assigns (for messages)
};

struct Program {
  std::vector<ObjectDef> objects;  // in file order: an object may call only earlier ones
};

// The program in `tokens` (from scanHyperFun), or nullopt after a syntax error in `log`.
// Parsing stops at the first syntax error, and at nesting deeper than the compiler's recursion
// should go (expressions over 4000 levels deep, parentheses or blocks over 1000). Unparenthesised mixes of set operators with + or -
// are legal but get a note in `log` saying how HyperFun groups them.
std::optional<Program> parseHyperFun(const SourceFile& file, const std::vector<Token>& tokens, DiagnosticLog& log);

}  // namespace pf::field::hyperfun
