// Source files, locations and diagnostics for the primitive language.
// Every error a primitive author sees goes through DiagnosticLog, in the form
//   file:line:col: error: message
//       the source line
//       ^
// so that editors and the conformance suite can parse it.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace pf {

struct SourceFile {
  std::string name;  // as shown in diagnostics
  std::string text;
  std::vector<size_t> line_starts;  // offsets of the first character of each line

  SourceFile(std::string name, std::string text);
  std::string_view line(int line_number) const;  // 1-based, without the newline
};

struct SourceLoc {
  const SourceFile* file = nullptr;
  int line = 0;  // 1-based
  int col = 0;   // 1-based, in bytes
};

enum class Severity { Error, Note };

struct Diagnostic {
  Severity severity;
  SourceLoc loc;
  std::string message;
};

class DiagnosticLog {
 public:
  // Errors shown: past these they are counted, not kept (the parser stops there too).
  static constexpr int kMaxErrors = 20;
  void error(SourceLoc loc, std::string message);
  void note(SourceLoc loc, std::string message);
  bool hasErrors() const { return error_count_ > 0; }
  int errorCount() const { return error_count_; }
  const std::vector<Diagnostic>& all() const { return diagnostics_; }
  // All diagnostics rendered with source line and caret, one after the other.
  std::string format() const;
  // The log owns the files its diagnostics point into, so they outlive the compilation.
  const SourceFile& addSource(std::string name, std::string text) {
    sources_.push_back(std::make_shared<SourceFile>(std::move(name), std::move(text)));
    return *sources_.back();
  }

 private:
  std::vector<std::shared_ptr<const SourceFile>> sources_;
  std::vector<Diagnostic> diagnostics_;
  int error_count_ = 0;
};

std::string formatDiagnostic(const Diagnostic& d);

// Thrown to abandon a compilation after an error has been logged (the parser recovers at
// statement boundaries; past a limit of errors, or in a phase that cannot go on, it stops).
struct CompileAbort : std::runtime_error {
  CompileAbort() : std::runtime_error("compilation abandoned") {}
};

}  // namespace pf
