// The display lists of a context (GL 1.5 section 5.4): the names in use, the list being
// compiled, glListBase and the nesting of glCallList. What a list holds is a sequence of
// recorded commands (api/src/commands.h): an opcode word, then its arguments' bytes in whole
// words -- no allocation per command and nothing to call through but the command itself.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <unordered_map>
#include <vector>

#include <GL/gl.h>

namespace pf {

// GL_MAX_LIST_NESTING: Mesa's 64. A glCallList deeper than that is ignored, without an error.
constexpr int kMaxListNesting = 64;

// The lists and their names: what contexts sharing display lists share (OSMesa's `sharelist`;
// pf::shareDisplayLists).
struct ListNames {
  // Lists that hold commands, by name.
  std::unordered_map<GLuint, std::vector<uint32_t>> defined;
  // Names glGenLists handed out, as ranges first -> last: they are lists (glIsList) and empty
  // until defined. Ranges, not one entry a name: glGenLists(2^31 - 1) is a few bytes.
  std::map<GLuint, GLuint> reserved;
  // The highest name ever used: glGenLists hands out the names above it while there are enough,
  // as Mesa does (a deleted name is not handed out again until then).
  GLuint highest = 0;
};

struct DisplayLists {
  // Between glNewList and glEndList; `execute`: GL_COMPILE_AND_EXECUTE.
  bool compiling = false;
  bool execute = false;
  GLuint name = 0;                 // the list being compiled; it replaces `name` at glEndList
  std::vector<uint32_t> building;  // its commands so far
  bool dropped = false;            // a command was left out of it for want of memory
  // The lists themselves, this context's own or shared with others. Throws std::bad_alloc.
  std::shared_ptr<ListNames> names = std::make_shared<ListNames>();
  GLuint base = 0;  // glListBase
  int depth = 0;    // lists executing now, one inside another

  bool isList(GLuint n) const;
  // Frees names first .. last: their lists and reservations.
  void erase(GLuint first, GLuint last);
  // `range` free names in a row (none defined or reserved) and reserves them; 0 if there are not
  // that many. Throws std::bad_alloc.
  GLuint generate(GLuint range);
};

}  // namespace pf
