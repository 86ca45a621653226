// AST dump: one node per line, indented by depth.
#include "compiler/ast_print.h"

namespace pf {
namespace {

std::string qual(Qualifier q) {
  switch (q) {
    case Qualifier::Uniform: return "uniform ";
    case Qualifier::Varying: return "varying ";
    case Qualifier::Inout: return "inout ";
    case Qualifier::InoutVarying: return "inout varying ";
    default: return "";
  }
}

void expr(const Expr& e, std::string& out) {
  switch (e.kind) {
    case ExprKind::IntLit: out += std::to_string(static_cast<long long>(e.number)); return;
    case ExprKind::FloatLit: {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%g", e.number);
      out += buf;
      return;
    }
    case ExprKind::BoolLit: out += e.boolean ? "true" : "false"; return;
    case ExprKind::Name: out += e.name; return;
    case ExprKind::Unary: out += "(" + e.name; expr(*e.args[0], out); out += ")"; return;
    case ExprKind::Binary:
      out += "(";
      expr(*e.args[0], out);
      out += " " + e.name + " ";
      expr(*e.args[1], out);
      out += ")";
      return;
    case ExprKind::Ternary:
      out += "(";
      expr(*e.args[0], out);
      out += " ? ";
      expr(*e.args[1], out);
      out += " : ";
      expr(*e.args[2], out);
      out += ")";
      return;
    case ExprKind::Member: expr(*e.args[0], out); out += "." + e.name; return;
    case ExprKind::Index:
      expr(*e.args[0], out);
      out += "[";
      expr(*e.args[1], out);
      out += "]";
      return;
    case ExprKind::Call:
      out += e.name + "(";
      for (size_t i = 0; i < e.args.size(); ++i) {
        if (i) out += ", ";
        expr(*e.args[i], out);
      }
      out += ")";
      return;
  }
}

void stmts(const std::vector<StmtPtr>& body, int depth, std::string& out);

void stmt(const Stmt& s, int depth, std::string& out) {
  std::string pad(static_cast<size_t>(depth) * 2, ' ');
  switch (s.kind) {
    case StmtKind::Block:
      if (s.op == "decls") {
        stmts(s.body, depth, out);
      } else {
        out += pad + "block\n";
        stmts(s.body, depth + 1, out);
      }
      return;
    case StmtKind::Decl:
      out += pad + "decl " + qual(s.qualifier) + typeName(s.decl_type) + " " + s.name;
      if (s.value) { out += " = "; expr(*s.value, out); }
      out += "\n";
      return;
    case StmtKind::Assign:
      out += pad + "assign ";
      expr(*s.target, out);
      out += " " + s.op + " ";
      expr(*s.value, out);
      out += "\n";
      return;
    case StmtKind::ExprStmt: out += pad + "expr "; expr(*s.value, out); out += "\n"; return;
    case StmtKind::If:
      out += pad + "if ";
      expr(*s.value, out);
      out += "\n";
      stmts(s.body, depth + 1, out);
      if (s.has_else) {
        out += pad + "else\n";
        stmts(s.else_body, depth + 1, out);
      }
      return;
    case StmtKind::Return: out += pad + "return\n"; return;
    case StmtKind::Break: out += pad + "break\n"; return;
    case StmtKind::Continue: out += pad + "continue\n"; return;
    case StmtKind::Loop:
      out += pad + (s.op == "for" ? "for" : "while");
      if (s.value) {
        out += " ";
        expr(*s.value, out);
      }
      out += s.varying_loop ? "  (varying)\n" : "\n";
      if (s.init) {
        out += pad + " init\n";
        stmt(*s.init, depth + 2, out);
      }
      if (s.step) {
        out += pad + " step\n";
        stmt(*s.step, depth + 2, out);
      }
      stmts(s.body, depth + 1, out);
      return;
    case StmtKind::Bound:
      out += pad + "bound";
      for (const ExprPtr& a : s.bound_args) { out += " "; expr(*a, out); }
      out += "\n";
      return;
    case StmtKind::Interpolation:
      out += pad + "interpolation\n";
      for (const InterpolationCase& c : s.cases) {
        out += pad + " ";
        for (InterpKind k : c.kinds) out += std::string(" ") + interpKindName(k) + ":";
        for (const std::string& n : c.interpolators) out += " " + n + ":";
        out += "\n";
        stmts(c.body, depth + 2, out);
      }
      return;
    case StmtKind::InterpReturn:
      out += pad + "interpolator_return";
      if (s.value) { out += " "; expr(*s.value, out); }
      out += "\n";
      return;
  }
}

void stmts(const std::vector<StmtPtr>& body, int depth, std::string& out) {
  for (const StmtPtr& s : body) stmt(*s, depth, out);
}

}  // namespace

std::string printAst(const Program& p) {
  std::string out;
  for (const Unit& u : p.units) {
    switch (u.kind) {
      case UnitKind::Primitive: out += "primitive " + u.name + "\n"; break;
      case UnitKind::Interpolator: out += "interpolator " + u.name + "\n"; break;
      case UnitKind::Function: out += "function " + typeName(u.return_type) + " " + u.name + "\n"; break;
      case UnitKind::Field: out += "field " + typeName(u.return_type) + " " + u.name + "\n"; break;
    }
    for (const Param& prm : u.params) out += "  param " + qual(prm.qualifier) + typeName(prm.type) + " " + prm.name + "\n";
    stmts(u.body, 1, out);
  }
  return out;
}

}  // namespace pf
