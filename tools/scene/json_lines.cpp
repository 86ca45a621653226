// JSON pointer -> line (see json_lines.h). A small scanner over valid JSON: strings (with
// escapes), the structural characters, and everything else as the body of a scalar.
#include "scene/json_lines.h"

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

struct Frame {
  bool is_array;
  int next_index;        // arrays: the index of the next value
  std::string key;       // objects: the key whose value comes next
  bool expecting_key;    // objects: a string here is a key, not a value
};

}  // namespace

JsonLines::JsonLines(const std::string& text) {
  std::vector<Frame> stack;
  std::string path;                // pointer of the container on top of the stack
  std::vector<size_t> path_sizes;  // path's length before each push
  int line = 1;
  // Records the start of a value in the current container and returns its pointer.
  auto valueStarts = [&]() -> std::string {
    if (stack.empty()) {
      lines_.emplace("", line);
      return "";
    }
    Frame& f = stack.back();
    std::string p = path + "/" + (f.is_array ? std::to_string(f.next_index++) : pointerToken(f.key));
    lines_.emplace(p, line);
    return p;
  };
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
    } else if (c == '"') {
      std::string s;
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        if (text[i] == '\\' && i + 1 < text.size()) {
          ++i;
          s += text[i] == 'n' ? '\n' : text[i];  // only keys matter: their common escapes
        } else {
          if (text[i] == '\n') ++line;
          s += text[i];
        }
      }
      if (!stack.empty() && !stack.back().is_array && stack.back().expecting_key) {
        stack.back().key = s;
        stack.back().expecting_key = false;
      } else {
        valueStarts();
      }
    } else if (c == '{' || c == '[') {
      const std::string p = valueStarts();
      path_sizes.push_back(path.size());
      path = p;
      stack.push_back({c == '[', 0, "", c == '{'});
    } else if (c == '}' || c == ']') {
      if (stack.empty()) break;
      stack.pop_back();
      path.resize(path_sizes.back());
      path_sizes.pop_back();
    } else if (c == ',') {
      if (!stack.empty() && !stack.back().is_array) stack.back().expecting_key = true;
    } else if (c != ':' && c != ' ' && c != '\t' && c != '\r') {
      // The first character of a number, true, false or null; skip its body.
      valueStarts();
      while (i + 1 < text.size() && std::string(",]}\n \t\r").find(text[i + 1]) == std::string::npos) ++i;
    }
  }
}

int JsonLines::lineOf(std::string pointer) const {
  while (true) {
    auto it = lines_.find(pointer);
    if (it != lines_.end()) return it->second;
    if (pointer.empty()) return 1;
    pointer.resize(pointer.rfind('/'));
  }
}

}  // namespace pf::scene
