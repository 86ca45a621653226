// Diagnostic formatting: file:line:col: severity: message, the source line, a caret.
#include "compiler/diagnostics.h"

#include <algorithm>

namespace pf {

SourceFile::SourceFile(std::string n, std::string t) : name(std::move(n)), text(std::move(t)) {
  // Old Mac line endings: a CR alone ends a line as LF does (CR LF stays one line end), for
  // the lexers' line numbers and the lines shown alike.
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) text[i] = '\n';
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

namespace {

constexpr size_t kMaxMessageBytes = 400;  // a message quoting a huge token is cut
constexpr size_t kShownLineBytes = 120;   // of a long source line, this much around the column

// A message as shown: control bytes but newline and tab (a NUL read from a model file, say)
// escaped as \xNN, and cut short past kMaxMessageBytes.
std::string printable(const std::string& message) {
  std::string out;
  size_t i = 0;
  for (; i < message.size() && out.size() < kMaxMessageBytes; ++i) {
    const unsigned char c = static_cast<unsigned char>(message[i]);
    if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f) {
      static const char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  if (i < message.size()) out += "...";
  return out;
}

}  // namespace

void DiagnosticLog::error(SourceLoc loc, std::string message) {
  ++error_count_;
  if (error_count_ > DiagnosticLog::kMaxErrors) return;
  diagnostics_.push_back({Severity::Error, loc, printable(message)});
}

void DiagnosticLog::note(SourceLoc loc, std::string message) {
  if (error_count_ > DiagnosticLog::kMaxErrors) return;
  diagnostics_.push_back({Severity::Note, loc, printable(message)});
}

std::string formatDiagnostic(const Diagnostic& d) {
  std::string out;
  const char* kind = d.severity == Severity::Error ? "error" : "note";
  if (d.loc.file) {
    out += d.loc.file->name + ":" + std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) +
           ": " + kind + ": " + d.message + "\n";
    std::string_view src = d.loc.file->line(d.loc.line);
    // Of a long line, the part around the column, marked "..." where it is cut.
    size_t from = 0, col = d.loc.col > 0 ? static_cast<size_t>(d.loc.col - 1) : 0;
    const bool cut_front = src.size() > kShownLineBytes && col > kShownLineBytes / 2;
    if (cut_front) from = std::min(col - kShownLineBytes / 2, src.size() - kShownLineBytes);
    const bool cut_back = src.size() - from > kShownLineBytes;
    std::string shown = cut_front ? "..." : "";
    for (char c : src.substr(from, kShownLineBytes)) {
      const unsigned char u = static_cast<unsigned char>(c);
      shown += (u < 0x20 && c != '\t') || u == 0x7f ? '?' : c;  // one byte for one: the caret stays put
    }
    if (cut_back) shown += "...";
    out += "    " + shown + "\n    ";
    // Keep tabs so the caret lines up with the source line as the terminal shows it.
    const size_t caret = (cut_front ? 3 : 0) + (col >= from ? col - from : 0);
    for (size_t i = 0; i < caret && i < shown.size(); ++i) out += shown[i] == '\t' ? '\t' : ' ';
    out += "^\n";
  } else {
    out += std::string(kind) + ": " + d.message + "\n";
  }
  return out;
}

std::string DiagnosticLog::format() const {
  std::string out;
  for (const Diagnostic& d : diagnostics_) out += formatDiagnostic(d);
  if (error_count_ > DiagnosticLog::kMaxErrors)
    out += "error: " + std::to_string(error_count_ - DiagnosticLog::kMaxErrors) + " more error(s) not shown\n";
  return out;
}

}  // namespace pf
