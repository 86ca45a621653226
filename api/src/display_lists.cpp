// Display lists (GL 1.5 section 5.4): glNewList / glEndList record the commands of
// commands.h into a list, glCallList and glCallLists replay them through the same functions the
// entry points call. Errors and limits are Mesa's, checked against OSMesa in the conformance
// suite (tests/conformance/cases_lists.inc): an error in a recorded command is raised when the
// list executes; glCallList(0) is GL_INVALID_VALUE, but inside a list, like an unknown list, it
// is ignored; nesting deeper than GL_MAX_LIST_NESTING (64) is ignored without an error.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <new>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"

namespace pf {

bool DisplayLists::isList(GLuint n) const {
  if (names->defined.count(n)) return true;
  auto it = names->reserved.upper_bound(n);
  return it != names->reserved.begin() && n <= std::prev(it)->second;
}

void DisplayLists::erase(GLuint first, GLuint last) {
  // Over the range or over the lists, whichever is shorter (glDeleteLists(1, 2^31 - 1) with a few
  // lists defined must not walk two billion names).
  if (uint64_t{last} - first < names->defined.size()) {
    for (uint64_t n = first; n <= last; ++n) names->defined.erase(static_cast<GLuint>(n));
  } else {
    std::erase_if(names->defined, [&](const auto& entry) { return entry.first >= first && entry.first <= last; });
  }
  auto it = names->reserved.upper_bound(first);
  if (it != names->reserved.begin() && std::prev(it)->second >= first) --it;
  while (it != names->reserved.end() && it->first <= last) {
    const GLuint a = it->first, b = it->second;
    it = names->reserved.erase(it);
    if (a < first) names->reserved.emplace(a, first - 1);
    if (b > last) it = names->reserved.emplace(last + 1, b).first;
  }
}

GLuint DisplayLists::generate(GLuint range) {
  constexpr GLuint kLastName = 0xfffffffeu;  // Mesa's highest key
  uint64_t first;
  if (range <= kLastName && kLastName - range > names->highest) {
    first = uint64_t{names->highest} + 1;
  } else {
    // The names above the highest are used up: the lowest free block of `range` names.
    std::vector<std::pair<GLuint, GLuint>> used(names->reserved.begin(), names->reserved.end());
    for (const auto& entry : names->defined) used.emplace_back(entry.first, entry.first);
    std::sort(used.begin(), used.end());
    first = 1;
    for (const auto& [a, b] : used) {
      if (a >= first + range) break;
      first = std::max<uint64_t>(first, uint64_t{b} + 1);
    }
    if (first + range - 1 > kLastName) return 0;
  }
  const GLuint last = static_cast<GLuint>(first + range - 1);
  auto before = names->reserved.lower_bound(static_cast<GLuint>(first));
  if (before != names->reserved.begin() && std::prev(before)->second + 1 == first) std::prev(before)->second = last;
  else names->reserved.emplace(static_cast<GLuint>(first), last);
  names->highest = std::max(names->highest, last);
  return static_cast<GLuint>(first);
}

void recordOutOfMemory(PFcontextRec& ctx) {
  ctx.setError(GL_OUT_OF_MEMORY);
  if (ctx.lists.dropped) return;  // one line a list
  ctx.lists.dropped = true;
  std::fprintf(stderr, "primflow: display list %u: out of memory: commands left out of it\n", ctx.lists.name);
}

namespace {

// glCallLists' types: GL_BYTE ... GL_4_BYTES, GL_FLOAT among them.
bool isListType(GLenum type) { return type >= GL_BYTE && type <= GL_4_BYTES; }

// The i-th offset of glCallLists' array, as Mesa reads it (added to the base modulo 2^32).
GLuint listOffset(GLenum type, const void* lists, GLsizei i) {
  const auto* bytes = static_cast<const unsigned char*>(lists);
  const size_t k = static_cast<size_t>(i);
  auto read = [&](auto v) {  // (memcpy: the caller's array need not be aligned)
    std::memcpy(&v, bytes + k * sizeof(v), sizeof(v));
    return v;
  };
  auto big_endian = [&](size_t n) {
    uint32_t v = 0;
    for (size_t b = 0; b < n; ++b) v = v << 8 | bytes[k * n + b];
    return v;
  };
  switch (type) {
    case GL_BYTE: return static_cast<GLuint>(static_cast<GLint>(read(GLbyte{})));
    case GL_UNSIGNED_BYTE: return read(GLubyte{});
    case GL_SHORT: return static_cast<GLuint>(static_cast<GLint>(read(GLshort{})));
    case GL_UNSIGNED_SHORT: return read(GLushort{});
    case GL_INT: return static_cast<GLuint>(read(GLint{}));
    case GL_UNSIGNED_INT: return read(GLuint{});
    case GL_FLOAT: {
      // Truncated toward zero; NaN and values beyond a GLint give INT_MIN, as the x86 conversion
      // OSMesa does (a C cast there) gives them.
      const float f = read(GLfloat{});
      const bool fits = f > -2147483649.0 && f < 2147483648.0;
      return static_cast<GLuint>(fits ? static_cast<GLint>(f) : INT32_MIN);
    }
    case GL_2_BYTES: return big_endian(2);
    case GL_3_BYTES: return big_endian(3);
    default: return big_endian(4);  // GL_4_BYTES
  }
}

// glCallLists: the lists base + offset(i), i < n. The base is read once, as Mesa does: a list
// that sets it affects the next glCallLists, not this one.
template <class Offset>
void callLists(PFcontextRec& ctx, GLsizei n, GLenum type, bool any, Offset offset) {
  if (!isListType(type)) {
    ctx.setError(GL_INVALID_ENUM);
    return;
  }
  if (n < 0) {
    ctx.setError(GL_INVALID_VALUE);
    return;
  }
  if (!any) return;  // n == 0, or a NULL array
  const GLuint base = ctx.lists.base;
  for (GLsizei i = 0; i < n; ++i) cmd::callList(ctx, base + offset(i));
}

// A recorded glCallLists: n, type, the number of offsets stored (n for a valid call, else 0),
// the offsets. Returns the words it takes after its opcode.
uint32_t replayCallLists(PFcontextRec& ctx, const uint32_t* args) {
  const uint32_t stored = args[2];
  const uint32_t* offsets = args + 3;
  callLists(ctx, static_cast<GLsizei>(args[0]), static_cast<GLenum>(args[1]), stored > 0,
            [&](GLsizei i) { return offsets[i]; });
  return 3 + stored;
}

// Executes a list's commands, one after another.
void execute(PFcontextRec& ctx, const std::vector<uint32_t>& list) {
  const uint32_t* p = list.data();
  const uint32_t* const end = p + list.size();
  while (p < end) {
    const GlOp op = static_cast<GlOp>(*p++);
    switch (op) {
#define PF_REPLAY(name, ...)                                              \
  case GlOp::name:                                                          \
    p += replayRecorded(Command<GlOp::name>::function, ctx, p);             \
    break;
      PF_LIST_COMMANDS(PF_REPLAY)
#undef PF_REPLAY
      case GlOp::CallLists: p += replayCallLists(ctx, p); break;
      case GlOp::TexImage: p += replayTexImage(ctx, p); break;
      case GlOp::Bitmap: p += replayBitmap(ctx, p); break;
      case GlOp::DrawPixels: p += replayDrawPixels(ctx, p); break;
    }
  }
}

}  // namespace

namespace cmd {

void callList(PFcontextRec& ctx, GLuint name) {
  DisplayLists& lists = ctx.lists;
  if (lists.depth >= kMaxListNesting) return;
  auto it = lists.names->defined.find(name);
  if (it == lists.names->defined.end()) return;
  // (Nothing a list executes can change the lists -- glNewList, glEndList, glDeleteLists and
  // glGenLists are never recorded -- so `it` stays valid while it runs.)
  ++lists.depth;
  execute(ctx, it->second);
  --lists.depth;
}

void listBase(PFcontextRec& ctx, GLuint base) {
  if (outsideBegin(ctx)) ctx.lists.base = base;
}

void raise(PFcontextRec& ctx, GLenum error) { ctx.setError(error); }

}  // namespace cmd

}  // namespace pf

extern "C" {

void pfglNewList(GLuint list, GLenum mode) {
  PFcontextRec* ctx = pf::currentContext();
  if (!ctx) return;
  pf::DisplayLists& lists = ctx->lists;
  // (Mesa's order: a glNewList while compiling is GL_INVALID_OPERATION whatever its arguments.)
  if (ctx->in_begin || lists.compiling) return ctx->setError(GL_INVALID_OPERATION);
  if (list == 0) return ctx->setError(GL_INVALID_VALUE);
  if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE) return ctx->setError(GL_INVALID_ENUM);
  lists.compiling = true;
  lists.execute = mode == GL_COMPILE_AND_EXECUTE;
  lists.name = list;
  lists.dropped = false;
  lists.building.clear();  // (its capacity stays: the next list records without reallocating)
}

// Under GL_COMPILE_AND_EXECUTE a glEndList between glBegin and glEnd ends the list without an
// error, as in Mesa; the glBegin goes on.
void pfglEndList(void) {
  PFcontextRec* ctx = pf::currentContext();
  if (!ctx) return;
  pf::DisplayLists& lists = ctx->lists;
  if (!lists.compiling) return ctx->setError(GL_INVALID_OPERATION);
  lists.compiling = false;
  lists.execute = false;
  try {
    // Stored at its size (the recording buffer grew by doubling); the old list is replaced now.
    std::vector<uint32_t> compact(lists.building.begin(), lists.building.end());
    lists.names->defined[lists.name] = std::move(compact);
    lists.names->highest = std::max(lists.names->highest, lists.name);
  } catch (const std::bad_alloc&) {
    pf::recordOutOfMemory(*ctx);
  }
  lists.building.clear();
}

GLuint pfglGenLists(GLsizei range) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return 0;
  if (range < 0) {
    ctx->setError(GL_INVALID_VALUE);
    return 0;
  }
  if (range == 0) return 0;
  try {
    return ctx->lists.generate(static_cast<GLuint>(range));
  } catch (const std::bad_alloc&) {
    ctx->setError(GL_OUT_OF_MEMORY);
    return 0;
  }
}

void pfglDeleteLists(GLuint list, GLsizei range) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  if (range < 0) return ctx->setError(GL_INVALID_VALUE);
  if (range == 0) return;
  const uint64_t last = std::min<uint64_t>(uint64_t{list} + static_cast<uint64_t>(range) - 1, 0xffffffffu);
  try {
    ctx->lists.erase(list, static_cast<GLuint>(last));
  } catch (const std::bad_alloc&) {  // splitting a reserved range
    ctx->setError(GL_OUT_OF_MEMORY);
  }
}

GLboolean pfglIsList(GLuint list) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  return ctx && list != 0 && ctx->lists.isList(list) ? GL_TRUE : GL_FALSE;
}

void pfglCallList(GLuint list) {
  PFcontextRec* ctx = pf::currentContext();
  if (!ctx) return;
  if (ctx->lists.compiling) {
    pf::record(*ctx, pf::GlOp::CallList, 0, list);
    if (!ctx->lists.execute) return;
  }
  if (list == 0) return ctx->setError(GL_INVALID_VALUE);
  pf::cmd::callList(*ctx, list);
}

void pfglCallLists(GLsizei n, GLenum type, const GLvoid* lists) {
  PFcontextRec* ctx = pf::currentContext();
  if (!ctx) return;
  const bool any = n > 0 && lists;
  if (ctx->lists.compiling) {
    // The offsets are read now, as GL requires; the base when the list executes.
    const uint32_t stored = pf::isListType(type) && any ? static_cast<uint32_t>(n) : 0;
    if (uint32_t* out = pf::record(*ctx, pf::GlOp::CallLists, stored, static_cast<uint32_t>(n), type, stored))
      for (uint32_t i = 0; i < stored; ++i) out[i] = pf::listOffset(type, lists, static_cast<GLsizei>(i));
    if (!ctx->lists.execute) return;
  }
  pf::callLists(*ctx, n, type, any, [&](GLsizei i) { return pf::listOffset(type, lists, i); });
}

void pfglListBase(GLuint base) { pf::dispatch<pf::GlOp::ListBase>(base); }

}  // extern "C"
