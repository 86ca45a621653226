// Fidget .vm reader (see fidget_reader.h for the format).
#include "compiler/field/fidget_reader.h"

#include <charconv>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace pf::field {
namespace {

struct Token {
  std::string_view text;
  int col = 0;  // 1-based
};

std::vector<Token> splitWords(std::string_view line) {
  std::vector<Token> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i >= line.size() || line[i] == '#') break;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' && line[i] != '#') ++i;
    words.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
  }
  return words;
}

struct OpSpelling {
  std::string_view name;
  FieldOp op;
};
// Fidget's operation names. Its `recip`, `atan`, `compare`, `and`, `or`, `not`, `mod`,
// `floor`/`ceil`/`round` and `copy` are not in primflow's field set and are reported by name.
constexpr OpSpelling kOps[] = {
    {"var-x", FieldOp::X},  {"var-y", FieldOp::Y},   {"var-z", FieldOp::Z},        {"const", FieldOp::Const},
    {"neg", FieldOp::Neg},  {"abs", FieldOp::Abs},   {"square", FieldOp::Square},  {"sqrt", FieldOp::Sqrt},
    {"exp", FieldOp::Exp},  {"ln", FieldOp::Log},    {"sin", FieldOp::Sin},        {"cos", FieldOp::Cos},
    {"add", FieldOp::Add},  {"sub", FieldOp::Sub},   {"mul", FieldOp::Mul},        {"div", FieldOp::Div},
    {"min", FieldOp::Min},  {"max", FieldOp::Max},
};

}  // namespace

std::optional<FieldTape> readFidgetModel(const std::string& name, std::string text, DiagnosticLog& log) {
  const SourceFile& file = log.addSource(name, std::move(text));
  const int errors_before = log.errorCount();
  auto error = [&](int line, int col, std::string message) {
    if (log.errorCount() - errors_before < DiagnosticLog::kMaxErrors) log.error({&file, line, col}, std::move(message));
  };
  FieldTapeBuilder builder;
  std::unordered_map<std::string_view, uint32_t> values;
  std::optional<uint32_t> last;
  const int lines = static_cast<int>(file.line_starts.size());
  for (int ln = 1; ln <= lines; ++ln) {
    const std::vector<Token> words = splitWords(file.line(ln));
    if (words.empty()) continue;
    if (words.size() < 2) {
      error(ln, words[0].col, "expected 'NAME OP ARGS...', found only '" + std::string(words[0].text) + "'");
      continue;
    }
    const Token& target = words[0];
    const Token& opword = words[1];
    const OpSpelling* spelling = nullptr;
    for (const OpSpelling& s : kOps)
      if (s.name == opword.text) spelling = &s;
    if (!spelling) {
      error(ln, opword.col, "unsupported operation '" + std::string(opword.text) +
                                "' (primflow's fields have: var-x var-y var-z const neg abs square sqrt exp ln "
                                "sin cos add sub mul div min max)");
      continue;
    }
    const FieldOp op = spelling->op;
    const size_t want = op == FieldOp::Const ? 1 : static_cast<size_t>(fieldOpArity(op));
    if (words.size() - 2 != want) {
      const Token& at = words.size() - 2 > want ? words[2 + want] : opword;
      error(ln, at.col, "'" + std::string(opword.text) + "' takes " + std::to_string(want) + " argument" +
                            (want == 1 ? "" : "s") + ", found " + std::to_string(words.size() - 2));
      continue;
    }
    uint32_t value = 0;
    if (op == FieldOp::Const) {
      const Token& number = words[2];
      float v = 0.0f;
      const char* begin = number.text.data();
      const char* end = begin + number.text.size();
      auto [ptr, ec] = std::from_chars(begin, end, v);
      if (ec != std::errc() || ptr != end || !std::isfinite(v)) {
        error(ln, number.col, "'" + std::string(number.text) + "' is not a finite number");
        continue;
      }
      value = builder.constant(v);
    } else if (fieldOpArity(op) == 0) {
      value = op == FieldOp::X ? builder.x() : op == FieldOp::Y ? builder.y() : builder.z();
    } else {
      uint32_t args[2] = {0, 0};
      bool ok = true;
      for (size_t k = 0; k < want; ++k) {
        const Token& arg = words[2 + k];
        auto it = values.find(arg.text);
        if (it == values.end()) {
          error(ln, arg.col, "'" + std::string(arg.text) + "' is not defined on an earlier line");
          ok = false;
        } else {
          args[k] = it->second;
        }
      }
      if (!ok) continue;
      value = want == 1 ? builder.unary(op, args[0]) : builder.binary(op, args[0], args[1]);
    }
    if (!values.try_emplace(target.text, value).second) {
      error(ln, target.col, "'" + std::string(target.text) + "' is defined twice (the format is SSA)");
      continue;
    }
    last = value;
  }
  if (log.errorCount() > errors_before) return std::nullopt;
  if (!last) {
    log.error({&file, 1, 1}, "the model has no operations");
    return std::nullopt;
  }
  // Fidget: negative inside. primflow: f >= 0 inside.
  return builder.finish(builder.unary(FieldOp::Neg, *last));
}

}  // namespace pf::field
