// pfc: the primitive-language compiler on the command line.
//   pfc FILE.pfl [--emit=ast|ir|setup|pixel|native|tape] [--field NAME --params V...]
//   --emit=native: each primitive's setup and pixel programs as native code (LLVM IR and
//   assembly), for the block shape, instruction set and channels --block, --isa and --channels give.
// Diagnostics go to stderr as file:line:col: error: message, with the line and a caret.
// Field units are compiled to tapes too (docs/language.md, "Fields"): those without parameters
// always, one with parameters when --field names it and --params gives their values.
// Exit status: 0 compiled, 1 compile error or unreadable file, 2 bad command line.
#include <algorithm>
#include <iterator>
#include <set>
#include <CLI/CLI.hpp>

#include "tools/command_line.h"

#include <fstream>
#include <iostream>
#include <sstream>

#include "tools/text_file.h"

#include "compiler/builtin_primitives.h"
#include "compiler/compiler.h"
#include "compiler/field/field_unit.h"
#include "compiler/native/native_cache.h"
#include "compiler/parser.h"

int main(int argc, char** argv) {
  CLI::App app{"pfc: compile primflow primitive-language source (.pfl)"};
  std::string file;
  std::string emit = "none";
  app.add_option("file", file, "source file (.pfl)")->required();
  bool explain = false;
  app.add_option("--emit", emit,
                 "print a stage: ast, ir, setup (per-instance program), pixel (per-block program), native (the setup "
                 "and pixel programs as machine code), tape (fields)")
      ->check(CLI::IsMember({"none", "ast", "ir", "setup", "pixel", "native", "tape"}));
  std::string block = "block", isa = "avx512";
  int channels = 4;
  app.add_option("--block", block, "--emit=native: block (aligned or packed lanes) or gang (several instances' lanes)")
      ->check(CLI::IsMember({"block", "gang"}));
  app.add_option("--isa", isa, "--emit=native: the instruction set (sse2, avx2, avx512)")
      ->check(CLI::IsMember({"sse2", "avx2", "avx512"}));
  app.add_option("--channels", channels, "--emit=native: perspective-correct channels drawn (e.g. 4: a colour)")
      ->check(CLI::Range(0, 64));
  std::string field_name;
  std::vector<float> params;
  app.add_option("--field", field_name, "the field unit --params are for");
  app.add_option("--params", params, "values of that field's parameters after its point")->needs("--field");
  app.add_flag("--explain", explain, "print why each optimization fired (folding, CSE, copies, dead code)");
  bool no_opt = false;
  app.add_flag("--no-optimize", no_opt, "skip the optimization passes (for comparison and debugging)");
  PF_PARSE_COMMAND_LINE(app, argc, argv);
  std::string source, why;
  if (!pf::tools::readTextFile(file, source, why)) {
    std::cerr << "pfc: cannot read '" << file << "': " << why << "\n";
    return 1;
  }
  pf::EmitStage stage = emit == "ast" ? pf::EmitStage::Ast : emit == "ir" ? pf::EmitStage::Ir
                        : emit == "setup" ? pf::EmitStage::Setup : emit == "pixel" ? pf::EmitStage::Pixel
                                                                   : pf::EmitStage::None;
  if (explain) stage = pf::EmitStage::Explain;
  pf::CompiledModule module;
  pf::DiagnosticLog log;
  std::string listing;
  // A user's primitives may call the built-in ones, as in a context.
  const pf::BuiltinPrimitives& builtins = pf::builtinPrimitives();
  std::set<std::string> interpolators;
  for (const auto& p : builtins.interpolators) interpolators.insert(p->name);
  bool ok = pf::compileSource(file, source, module, log, stage, &listing, !no_opt, &builtins.by_name, &interpolators);
  std::cerr << log.format();
  if (!ok) return 1;
  std::cout << listing;
  if (emit == "native") {
    // The variant an instance with `channels` perspective-correct channels draws with.
    pf::NativePixelVariant v;
    v.isa = isa == "sse2" ? pf::NativeIsa::Sse2 : isa == "avx2" ? pf::NativeIsa::Avx2 : pf::NativeIsa::Avx512;
    v.gang = block == "gang";
    v.channels = channels;
    v.kind_end[0] = v.kind_end[1] = v.kind_end[2] = channels;
    v.kind_begin[1] = v.kind_begin[2] = channels;
    pf::NativeSetupVariant sv;
    sv.isa = v.isa;
    sv.channels = channels;
    std::copy(std::begin(v.kind_begin), std::end(v.kind_begin), sv.kind_begin);
    std::copy(std::begin(v.kind_end), std::end(v.kind_end), sv.kind_end);
    for (const auto& prim : module.primitives) {
      v.writes_normal = prim->writes_normal;
      v.named_bound.assign(prim->named_interpolators.size(), false);
      sv.named_bound = v.named_bound;
      std::string text, error;
      if (!pf::nativeSetupListing(prim->setup, sv, text, error))
        std::cout << "primitive " << prim->name << ": no native setup code: " << error << "\n";
      else
        std::cout << "primitive " << prim->name << ": native setup program (" << pf::kNativeSetupLanes
                  << " instances, " << isa << ")\n"
                  << text;
      if (!pf::nativePixelListing(prim->pixel, v, text, error)) {
        std::cout << "primitive " << prim->name << ": no native code: " << error << "\n";
        continue;
      }
      std::cout << "primitive " << prim->name << ": native pixel program (" << block << " blocks, " << isa << ")\n"
                << text;
    }
  }
  // The field units, as tapes: what a point-dependent branch or an unsupported operation stops.
  pf::DiagnosticLog units_log;
  const pf::Program program = pf::parse(units_log.addSource(file, source), units_log);
  bool named_found = field_name.empty();
  for (const pf::Unit& u : program.units) {
    if (u.kind != pf::UnitKind::Field) continue;
    const bool named = u.name == field_name;
    named_found = named_found || named;
    if (u.params.size() > 1 && !named) continue;  // its parameters' values are not known here
    pf::DiagnosticLog field_log;
    const auto tape = pf::field::compileFieldUnit(file, source, u.name, named ? params : std::vector<float>{}, field_log);
    std::cerr << field_log.format();
    if (!tape) return 1;
    if (emit == "tape")
      std::cout << "field " << u.name << ": tape of " << tape->size() << " instructions\n" << tape->print();
  }
  if (!named_found) {
    std::cerr << "pfc: " << file << " has no field named '" << field_name << "'\n";
    return 1;
  }
  return 0;
}
