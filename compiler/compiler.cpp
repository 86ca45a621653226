// The compiler driver: lex -> parse -> analyze -> lower -> generate, per primitive.
#include "compiler/compiler.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "compiler/ast_print.h"
#include "compiler/embedded_primitives.h"
#include "compiler/lower.h"
#include "compiler/parser.h"
#include "compiler/passes.h"
#include "compiler/sema.h"

namespace pf {

namespace {
const char* unitWord(const Unit& u) { return u.kind == UnitKind::Interpolator ? "interpolator" : "primitive"; }

// The names of the functions an expression or statement calls.
void calledNames(const Expr& e, std::set<std::string>& out) {
  if (e.kind == ExprKind::Call) out.insert(e.name);
  for (const ExprPtr& a : e.args) calledNames(*a, out);
}
void calledNames(const Stmt& s, std::set<std::string>& out) {
  for (const Expr* e : {s.value.get(), s.target.get()})
    if (e) calledNames(*e, out);
  for (const ExprPtr& a : s.bound_args) calledNames(*a, out);
  for (const std::vector<StmtPtr>* body : {&s.body, &s.else_body})
    for (const StmtPtr& c : *body) calledNames(*c, out);
  for (const InterpolationCase& k : s.cases)
    for (const StmtPtr& c : k.body) calledNames(*c, out);
  for (const Stmt* c : {s.init.get(), s.step.get()})
    if (c) calledNames(*c, out);
}
// The standard library's functions: which file defines each, and what each calls. Built once
// per process, so that a compilation parses only the library files it calls into.
struct StandardLibraryIndex {
  struct Function {
    int file = 0;
    std::set<std::string> calls;
  };
  std::map<std::string, Function> functions;
};

const StandardLibraryIndex& standardLibraryIndex() {
  static const StandardLibraryIndex index = [] {
    StandardLibraryIndex out;
    for (int i = 0; i < kStandardLibraryCount; ++i) {
      DiagnosticLog log;
      const Program p = parse(log.addSource(kStandardLibrary[i].file_name, kStandardLibrary[i].text), log);
      for (const Unit& u : p.units) {
        StandardLibraryIndex::Function& f = out.functions[u.name];
        f.file = i;
        for (const StmtPtr& st : u.body) calledNames(*st, f.calls);
      }
    }
    return out;
  }();
  return index;
}
// Every identifier-shaped word of a source text, comments and all.
std::set<std::string> identifiersIn(const std::string& text) {
  std::set<std::string> out;
  auto starts = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
  auto continues = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (size_t i = 0; i < text.size();) {
    if (!starts(text[i])) {
      // (a word never starts inside a number or another word)
      while (i < text.size() && continues(text[i])) ++i;
      if (i < text.size() && !starts(text[i])) ++i;
      continue;
    }
    const size_t from = i;
    while (i < text.size() && continues(text[i])) ++i;
    out.insert(text.substr(from, i - from));
  }
  return out;
}
}  // namespace

bool analyzeSource(const std::string& filename, const std::string& text, DiagnosticLog& log, Program& program,
                   const std::map<std::string, PrimitiveSignature>& callable, EmitStage emit, std::string* listing,
                   const std::set<std::string>& interpolators) {
  const SourceFile& file = log.addSource(filename, text);
  program = parse(file, log);
  if (log.hasErrors()) return false;
  // The standard library's functions come first, only those the source calls (directly or
  // through each other): the rest would cost parsing and analysis on every compilation (every
  // context compiles its built-in primitives) and change nothing. A user's function of a library
  // function's name is an error that names it as the library's.
  const StandardLibraryIndex& index = standardLibraryIndex();
  for (const Unit& u : program.units)
    if (index.functions.count(u.name)) {
      log.error(u.loc, "'" + u.name + "' is a function of the standard library (choose another name)");
      return false;
    }
  std::set<std::string> called, pending;
  for (const Unit& u : program.units)
    for (const StmtPtr& st : u.body) calledNames(*st, pending);
  while (!pending.empty()) {
    const std::string n = *pending.begin();
    pending.erase(pending.begin());
    auto it = index.functions.find(n);
    if (it == index.functions.end() || !called.insert(n).second) continue;
    pending.insert(it->second.calls.begin(), it->second.calls.end());
  }
  std::vector<Unit> units;
  for (int i = 0; i < kStandardLibraryCount; ++i) {
    bool needed = false;
    for (const std::string& n : called) needed = needed || index.functions.at(n).file == i;
    if (!needed) continue;
    const SourceFile& lib = log.addSource(std::string("<stdlib>/") + kStandardLibrary[i].file_name, kStandardLibrary[i].text);
    Program p = parse(lib, log);
    for (Unit& u : p.units)
      if (called.count(u.name)) units.push_back(std::move(u));
  }
  for (Unit& u : program.units) units.push_back(std::move(u));
  program.units = std::move(units);
  if (log.hasErrors()) return false;
  if (emit == EmitStage::Ast && listing) {
    // The listing shows the source's own units, not the standard library's.
    Program own, library;
    for (Unit& u : program.units) (u.loc.file == &file ? own : library).units.push_back(std::move(u));
    *listing += printAst(own);
    program.units = std::move(library.units);
    for (Unit& u : own.units) program.units.push_back(std::move(u));
  }
  return analyze(program, log, callable, interpolators);
}

bool compileSource(const std::string& filename, const std::string& text, CompiledModule& out,
                   DiagnosticLog& log, EmitStage emit, std::string* listing, bool optimize_ir,
                   const PrimitiveTable* callable, const std::set<std::string>* interpolators) {
  std::map<std::string, PrimitiveSignature> signatures;
  PrimitiveTable primitives;  // what the primitive being compiled may call
  if (callable) {
    // Only those the source names (any identifier: a superset of its calls). Copying every one
    // registered would make each compilation in a context slower than the one before.
    for (const std::string& name : identifiersIn(text))
      if (auto it = callable->find(name); it != callable->end()) {
        primitives.insert(*it);
        signatures[name] = it->second->signature;
      }
  }
  Program program;
  if (!analyzeSource(filename, text, log, program, signatures, emit, listing,
                     interpolators ? *interpolators : std::set<std::string>{}))
    return false;
  std::map<std::string, const Unit*> functions;
  for (const Unit& u : program.units)
    if (u.kind == UnitKind::Function || u.kind == UnitKind::Field) functions[u.name] = &u;
  for (const Unit& u : program.units) {
    // Functions are inlined where called; fields become tapes (compileFieldUnit), not programs.
    if (u.kind == UnitKind::Function || u.kind == UnitKind::Field) continue;
    IrFunction ir;
    if (!lowerPrimitive(u, functions, primitives, ir, log)) return false;
    std::vector<std::string> reasons;
    if (optimize_ir) optimize(ir, emit == EmitStage::Explain ? &reasons : nullptr);
    if (listing && emit == EmitStage::Explain)
      for (const std::string& r : reasons) *listing += filename + ":" + r + "\n";
    CodegenResult code = generateCode(ir);
    for (const auto& [loc, message] : code.errors) log.error(loc, message);
    if (!code.errors.empty()) return false;
    auto prim = std::make_shared<CompiledPrimitive>();
    prim->name = u.name;
    prim->signature = signatureOf(u);
    prim->params = ir.params;
    prim->param_floats = ir.param_floats;
    prim->sequence_points = ir.sequence_points;
    prim->count_slot = ir.count_slot;
    prim->sized_floats = ir.sized_floats;
    for (const std::string& callee : ir.callees) {
      prim->callees.push_back(primitives.at(callee));
      prim->call_depth = std::max(prim->call_depth, prim->callees.back()->call_depth + 1);
    }
    if (prim->call_depth > kMaxPrimitiveCallDepth) {
      log.error(u.loc, "primitive '" + u.name + "' nests primitive calls " + std::to_string(prim->call_depth) +
                           " deep; the limit is " + std::to_string(kMaxPrimitiveCallDepth));
      return false;
    }
    prim->has_interp_data = ir.has_interp_data;
    prim->kinds_handled = ir.kinds_handled;
    prim->named_interpolators = ir.named_interpolators;
    // A primitive whose calls set N is lit per pixel too (the cylinder: its quadric and disks).
    prim->writes_normal = ir.writes_normal;
    for (const auto& callee : prim->callees) prim->writes_normal |= callee->writes_normal;
    prim->setup = std::move(code.setup);
    prim->pixel = std::move(code.pixel);
    auto kept = std::make_shared<IrFunction>(std::move(ir));
    if (listing) {
      if (emit == EmitStage::Ir) *listing += "primitive " + u.name + ":\n" + dumpIr(*kept);
      if (emit == EmitStage::Setup)
        *listing += std::string(unitWord(u)) + " " + u.name + ": setup program (once per instance)\n" + disassemble(prim->setup, false);
      if (emit == EmitStage::Pixel)
        *listing += std::string(unitWord(u)) + " " + u.name + ": pixel program (per 8x8 block, masked)\n" + disassemble(prim->pixel, true);
      if (emit == EmitStage::Pixel && prim->pixel.covered)
        *listing += std::string(unitWord(u)) + " " + u.name +
                    ": pixel program for blocks it certainly covers (no leading returns)\n" +
                    disassemble(*prim->pixel.covered, true);
    }
    prim->ir = std::move(kept);
    prim->is_interpolator = u.kind == UnitKind::Interpolator;
    if (prim->is_interpolator) {
      out.interpolators.push_back(std::move(prim));
      continue;
    }
    primitives[prim->name] = prim;
    out.primitives.push_back(std::move(prim));
  }
  return true;
}

}  // namespace pf
