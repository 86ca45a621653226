// What libprimflow-osmesa (api/osmesa) needs from inside primflow beyond the public API: a call
// after glFinish / glFlush have executed the drawing -- where OSMesa copies its frame into the
// caller's buffer, in the caller's format --, display lists shared between contexts, and the
// error an entry point primflow does not implement records. Declarations only: no internal type leaks into api/osmesa.
#pragma once

struct PFcontextRec;

namespace pf {

using FrameHook = void (*)(void* user);

// glFinish and glFlush on `ctx` call hook(user) once its drawing has executed, when some
// drawing (or a clear) has executed since the hook last ran (null: none).
void setFrameHook(PFcontextRec* ctx, FrameHook hook, void* user);

// `ctx` uses the display lists of `with` from now on (its own are dropped): the lists and their
// names are one table for every context sharing them, as with OSMesa's `sharelist`.
void shareDisplayLists(PFcontextRec* ctx, PFcontextRec* with);

// An entry point of GL that primflow does not implement was called: GL_INVALID_OPERATION on
// the current context (none: nothing), and once per name a line on stderr.
void unsupportedEntryPoint(const char* name);

}  // namespace pf
