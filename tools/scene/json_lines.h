// Where each value of a JSON text starts, by JSON pointer ("/objects/3/params/radius"), so a
// scene error can name the line of the key it is about. nlohmann-json parses the values but
// keeps no positions; this scans the (already valid) text once more, tracking the path.
#pragma once

#include <string>
#include <unordered_map>

namespace pf::scene {

class JsonLines {
 public:
  explicit JsonLines(const std::string& text);
  // The 1-based line where the value at `pointer` starts; for a pointer not in the text, the
  // line of its longest prefix that is (the whole document: line 1).
  int lineOf(std::string pointer) const;

 private:
  std::unordered_map<std::string, int> lines_;
};

// A JSON pointer's token, escaped ("~" -> "~0", "/" -> "~1").
std::string pointerToken(const std::string& key);

}  // namespace pf::scene
