// JSON pointer -> line (see json_lines.h). A small scanner over valid JSON: strings (with
// escapes), the structural characters, and everything else as the body of a scalar.
#include "scene/json_lines.h"

#include <cstring>
#include <vector>

namespace pf::scene {

std::string pointerToken(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

namespace {

// The pointer's tokens, still escaped as pointerToken escapes them ("" -> none).
std::vector<std::string> tokensOf(const std::string& pointer) {
  std::vector<std::string> out;
  size_t at = 0;
  while (at < pointer.size() && pointer[at] == '/') {
    const size_t next = pointer.find('/', at + 1);
    out.push_back(pointer.substr(at + 1, (next == std::string::npos ? pointer.size() : next) - at - 1));
    at = next == std::string::npos ? pointer.size() : next;
  }
  return out;
}

// An open array or object.
struct Frame {
  bool is_array;
  bool on_path;       // its pointer is a prefix of the one looked for
  int next_index;     // arrays: the index of the next value
  std::string key;    // objects: the key whose value comes next (escaped), kept only on the path
  bool expecting_key; // objects: a string here is a key, not a value
};

}  // namespace

int JsonLines::lineOf(const std::string& pointer) const {
  const std::vector<std::string> want = tokensOf(pointer);
  const std::string& text = text_;
  std::vector<Frame> stack;
  int line = 1;
  size_t matched = 0;  // tokens of `want` matched by the deepest value found on the path
  int matched_line = 1;
  // A value starts here, in the container on top of the stack: whether it is on the path.
  auto valueStarts = [&]() -> bool {
    if (stack.empty()) {
      matched_line = line;
      return true;
    }
    Frame& f = stack.back();
    const size_t depth = stack.size();  // the tokens in this value's pointer
    const bool on_path = f.on_path && depth == matched + 1 && depth <= want.size() &&
                         want[depth - 1] == (f.is_array ? std::to_string(f.next_index) : f.key);
    if (f.is_array) ++f.next_index;
    if (on_path) {
      matched = depth;
      matched_line = line;
    }
    return on_path;
  };
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
    } else if (c == '"') {
      const bool is_key = !stack.empty() && !stack.back().is_array && stack.back().expecting_key;
      const bool keep = is_key && stack.back().on_path;
      std::string s;
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        if (text[i] == '\\' && i + 1 < text.size()) {
          ++i;
          if (keep) s += text[i] == 'n' ? '\n' : text[i];  // only keys matter: their common escapes
        } else {
          if (text[i] == '\n') ++line;
          if (keep) s += text[i];
        }
      }
      if (is_key) {
        stack.back().key = keep ? pointerToken(s) : std::string();
        stack.back().expecting_key = false;
      } else if (valueStarts() && matched == want.size()) {
        return line;
      }
    } else if (c == '{' || c == '[') {
      const bool on_path = valueStarts();
      if (on_path && matched == want.size()) return line;
      stack.push_back({c == '[', on_path, 0, "", c == '{'});
    } else if (c == '}' || c == ']') {
      // Leaving a container on the path without meeting the pointer: it is not in the text.
      if (stack.empty() || stack.back().on_path) break;
      stack.pop_back();
    } else if (c == ',') {
      if (!stack.empty() && !stack.back().is_array) stack.back().expecting_key = true;
    } else if (c != ':' && c != ' ' && c != '\t' && c != '\r') {
      // The first character of a number, true, false or null; skip its body.
      if (valueStarts() && matched == want.size()) return line;
      while (i + 1 < text.size() && std::strchr(",]}\n \t\r", text[i + 1]) == nullptr) ++i;
    }
  }
  return matched_line;
}

JsonNesting jsonNesting(const std::string& text) {
  JsonNesting deepest;
  int depth = 0, line = 1;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
    } else if (c == '"') {
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        if (text[i] == '\\') ++i;
        else if (text[i] == '\n') ++line;
      }
    } else if (c == '{' || c == '[') {
      if (++depth > deepest.depth) deepest = {depth, line};
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
  return deepest;
}

}  // namespace pf::scene
