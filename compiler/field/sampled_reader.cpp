// Reading .pfgrid files (sampled_reader.h): the header line by line, then the raw samples.
#include "compiler/field/sampled_reader.h"

#include <cmath>
#include <cstring>
#include <new>
#include <optional>
#include <sstream>
#include <vector>

namespace pf::field {

namespace {

// One whitespace-separated word of a header line and the column (1-based) it starts at.
struct Word {
  std::string text;
  int col = 0;
};

std::vector<Word> wordsOf(std::string_view line) {
  std::vector<Word> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i >= line.size()) break;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    out.push_back({std::string(line.substr(start, i - start)), static_cast<int>(start) + 1});
  }
  return out;
}

std::optional<double> number(const std::string& s) {
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

std::shared_ptr<const SampledGrid> readSampledField(const std::string& name, const std::string& bytes,
                                                    DiagnosticLog& log) {
  // The header is the text up to and including the `data` line; only it is kept for carets.
  size_t data_at = std::string::npos, pos = 0;
  int data_line = 0, line_no = 0;
  while (pos < bytes.size()) {
    const size_t eol = bytes.find('\n', pos);
    ++line_no;
    const std::string_view line(bytes.data() + pos, (eol == std::string::npos ? bytes.size() : eol) - pos);
    const std::vector<Word> w = wordsOf(line);
    if (w.size() == 1 && w[0].text == "data") {
      data_line = line_no;
      data_at = eol == std::string::npos ? bytes.size() : eol + 1;
      break;
    }
    if (eol == std::string::npos) break;
    pos = eol + 1;
  }
  const SourceFile& file = log.addSource(name, bytes.substr(0, data_at == std::string::npos ? bytes.size() : data_at));
  auto fail = [&](int line, int col, const std::string& message) {
    log.error({&file, line, col}, message);
    return nullptr;
  };

  long long size[3] = {0, 0, 0};
  double box[6] = {0, 0, 0, 0, 0, 0};
  std::optional<SampleInterpolation> interpolation;
  bool has_size = false, has_box = false, magic = false;
  const int header_lines = data_at == std::string::npos ? line_no : data_line - 1;
  for (int l = 1; l <= header_lines; ++l) {
    const std::vector<Word> w = wordsOf(file.line(l));
    if (w.empty() || w[0].text[0] == '#') {
      if (l == 1) return fail(1, 1, "a sampled field file starts with 'pfgrid 1'");
      continue;
    }
    const Word& key = w[0];
    if (l == 1 || !magic) {
      if (key.text != "pfgrid" || w.size() != 2 || w[1].text != "1")
        return fail(l, key.col, "a sampled field file starts with 'pfgrid 1'");
      magic = true;
      continue;
    }
    auto wantWords = [&](size_t n, const char* what) -> bool {
      if (w.size() == n + 1) return true;
      fail(l, w.size() > n + 1 ? w[n + 1].col : key.col,
           "'" + key.text + "' takes " + what + " (found " + std::to_string(w.size() - 1) + ")");
      return false;
    };
    if (key.text == "size") {
      if (has_size) return fail(l, key.col, "'size' is given twice");
      if (!wantWords(3, "3 whole numbers, the samples along x, y and z")) return nullptr;
      for (int a = 0; a < 3; ++a) {
        const std::optional<double> v = number(w[1 + a].text);
        if (!v || *v != std::floor(*v) || *v < 2 || *v > 1e9)
          return fail(l, w[1 + a].col, "'" + w[1 + a].text + "' is not a sample count: a whole number, at least 2");
        size[a] = static_cast<long long>(*v);
      }
      has_size = true;
    } else if (key.text == "box") {
      if (has_box) return fail(l, key.col, "'box' is given twice");
      if (!wantWords(6, "6 numbers, the corners x0 y0 z0 x1 y1 z1")) return nullptr;
      for (int a = 0; a < 6; ++a) {
        const std::optional<double> v = number(w[1 + a].text);
        if (!v) return fail(l, w[1 + a].col, "'" + w[1 + a].text + "' is not a finite number");
        box[a] = *v;
      }
      for (int a = 0; a < 3; ++a)
        if (!(box[a] < box[3 + a])) return fail(l, w[4 + a].col, "the box's second corner must be above its first on each axis");
      has_box = true;
    } else if (key.text == "interpolation") {
      if (interpolation) return fail(l, key.col, "'interpolation' is given twice");
      if (!wantWords(1, "one word, trilinear or tricubic")) return nullptr;
      if (w[1].text == "trilinear") interpolation = SampleInterpolation::Trilinear;
      else if (w[1].text == "tricubic") interpolation = SampleInterpolation::CubicBSpline;
      else return fail(l, w[1].col, "unknown interpolation '" + w[1].text + "' (trilinear or tricubic)");
    } else {
      return fail(l, key.col, "unknown header line '" + key.text + "' (size, box, interpolation, data)");
    }
  }
  if (!magic) return fail(1, 1, "a sampled field file starts with 'pfgrid 1'");
  const int end_line = data_at == std::string::npos ? std::max(line_no, 1) : data_line;
  if (data_at == std::string::npos) return fail(end_line, 1, "the header does not end with a 'data' line");
  const char* missing = !has_size ? "size" : !has_box ? "box" : !interpolation ? "interpolation" : nullptr;
  if (missing) return fail(end_line, 1, std::string("the header has no '") + missing + "' line");

  const double lo[3] = {box[0], box[1], box[2]}, hi[3] = {box[3], box[4], box[5]};
  bool too_large = false;
  std::string wrong = SampledGrid::checkGrid(size[0], size[1], size[2], lo, hi, nullptr, &too_large);
  if (too_large) return fail(end_line, 1, wrong);
  const size_t count = static_cast<size_t>(size[0] * size[1] * size[2]);
  const size_t have = bytes.size() - data_at, need = count * 4;
  if (have < need)
    return fail(end_line, 1, "the data ends at byte offset " + std::to_string(have) + " of the " + std::to_string(need) +
                                 " that " + std::to_string(count) + " samples need (the file is truncated)");
  if (have > need)
    return fail(end_line, 1, "the data has " + std::to_string(have - need) + " bytes past its " + std::to_string(count) +
                                 " samples, from byte offset " + std::to_string(need));
  try {
    std::vector<float> values(count);
    for (size_t i = 0; i < count; ++i) {
      uint32_t bits = 0;
      for (int b = 0; b < 4; ++b)
        bits |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[data_at + 4 * i + static_cast<size_t>(b)])) << (8 * b);
      std::memcpy(&values[i], &bits, 4);
      if (!std::isfinite(values[i]))
        return fail(end_line, 1, "sample " + std::to_string(i) + " (at byte offset " + std::to_string(4 * i) +
                                     " of the data) is not a finite number");
    }
    return std::make_shared<const SampledGrid>(static_cast<int>(size[0]), static_cast<int>(size[1]),
                                               static_cast<int>(size[2]), lo, hi, *interpolation, std::move(values));
  } catch (const std::bad_alloc&) {
    return fail(end_line, 1, "out of memory for " + std::to_string(count) + " samples");
  }
}

FieldTape sampledFieldTape(std::shared_ptr<const SampledGrid> grid) {
  FieldTapeBuilder builder;
  return builder.finish(builder.sample(std::move(grid)));
}

}  // namespace pf::field
