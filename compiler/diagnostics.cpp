// Diagnostic formatting: file:line:col: severity: message, the source line, a caret.
#include "compiler/diagnostics.h"

namespace pf {

SourceFile::SourceFile(std::string n, std::string t) : name(std::move(n)), text(std::move(t)) {
  line_starts.push_back(0);
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') line_starts.push_back(i + 1);
}

std::string_view SourceFile::line(int line_number) const {
  if (line_number < 1 || line_number > static_cast<int>(line_starts.size())) return {};
  size_t begin = line_starts[line_number - 1];
  size_t end = text.find('\n', begin);
  if (end == std::string::npos) end = text.size();
  if (end > begin && text[end - 1] == '\r') --end;
  return std::string_view(text).substr(begin, end - begin);
}

void DiagnosticLog::error(SourceLoc loc, std::string message) {
  diagnostics_.push_back({Severity::Error, loc, std::move(message)});
  ++error_count_;
}

void DiagnosticLog::note(SourceLoc loc, std::string message) {
  diagnostics_.push_back({Severity::Note, loc, std::move(message)});
}

std::string formatDiagnostic(const Diagnostic& d) {
  std::string out;
  const char* kind = d.severity == Severity::Error ? "error" : "note";
  if (d.loc.file) {
    out += d.loc.file->name + ":" + std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) +
           ": " + kind + ": " + d.message + "\n";
    std::string_view src = d.loc.file->line(d.loc.line);
    out += "    ";
    out += src;
    out += "\n    ";
    // Keep tabs so the caret lines up with the source line as the terminal shows it.
    for (int i = 1; i < d.loc.col && i - 1 < static_cast<int>(src.size()); ++i)
      out += src[i - 1] == '\t' ? '\t' : ' ';
    out += "^\n";
  } else {
    out += std::string(kind) + ": " + d.message + "\n";
  }
  return out;
}

std::string DiagnosticLog::format() const {
  std::string out;
  for (const Diagnostic& d : diagnostics_) out += formatDiagnostic(d);
  return out;
}

}  // namespace pf
