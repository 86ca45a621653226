// pfc: the primitive-language compiler on the command line.
//   pfc FILE.pfl [--emit=ast|ir|setup|pixel]
// Diagnostics go to stderr as file:line:col: error: message, with the line and a caret.
// Exit status: 0 compiled, 1 compile error or unreadable file, 2 bad command line.
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <sstream>

#include "compiler/builtin_primitives.h"
#include "compiler/compiler.h"

int main(int argc, char** argv) {
  CLI::App app{"pfc: compile primflow primitive-language source (.pfl)"};
  std::string file;
  std::string emit = "none";
  app.add_option("file", file, "source file (.pfl)")->required();
  bool explain = false;
  app.add_option("--emit", emit, "print a stage: ast, ir, setup (per-instance program), pixel (per-block program)")
      ->check(CLI::IsMember({"none", "ast", "ir", "setup", "pixel"}));
  app.add_flag("--explain", explain, "print why each optimization fired (folding, CSE, copies, dead code)");
  bool no_opt = false;
  app.add_flag("--no-optimize", no_opt, "skip the optimization passes (for comparison and debugging)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    std::cerr << "pfc: cannot read '" << file << "'\n";
    return 1;
  }
  std::stringstream ss;
  ss << in.rdbuf();
  pf::EmitStage stage = emit == "ast" ? pf::EmitStage::Ast : emit == "ir" ? pf::EmitStage::Ir
                        : emit == "setup" ? pf::EmitStage::Setup : emit == "pixel" ? pf::EmitStage::Pixel
                                                                   : pf::EmitStage::None;
  if (explain) stage = pf::EmitStage::Explain;
  pf::CompiledModule module;
  pf::DiagnosticLog log;
  std::string listing;
  // A user's primitives may call the built-in ones, as in a context.
  const pf::BuiltinPrimitives& builtins = pf::builtinPrimitives();
  bool ok = pf::compileSource(file, ss.str(), module, log, stage, &listing, !no_opt, &builtins.by_name);
  std::cerr << log.format();
  if (!ok) return 1;
  std::cout << listing;
  return 0;
}
