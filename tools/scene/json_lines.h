// Where each value of a JSON text starts, by JSON pointer ("/objects/3/params/radius"), so a
// scene error can name the line of the key it is about. nlohmann-json parses the values but
// keeps no positions; this scans the (already valid) text once more for the one pointer asked,
// in time linear in the text and memory linear in its nesting (never a map of every path: the
// paths of a deeply nested text are quadratic in its depth).
#pragma once

#include <string>

namespace pf::scene {

class JsonLines {
 public:
  // `text` must outlive this object.
  explicit JsonLines(const std::string& text) : text_(text) {}
  // The 1-based line where the value at `pointer` starts; for a pointer not in the text, the
  // line of its longest prefix that is (the whole document: line 1).
  int lineOf(const std::string& pointer) const;

 private:
  const std::string& text_;
};

// A JSON pointer's token, escaped ("~" -> "~0", "/" -> "~1").
std::string pointerToken(const std::string& key);

// How deep arrays and objects nest in a JSON text, and the line where that depth is first
// reached (strings skipped): checked before parsing, so a deeply nested file is refused cheaply.
struct JsonNesting {
  int depth = 0;
  int line = 1;
};
JsonNesting jsonNesting(const std::string& text);

}  // namespace pf::scene
