// Whether the calling thread's stack is nearly used up, for the passes that recurse over a
// syntax tree (parsers, semantic analysis, lowering). Their nesting limits (docs/reliability.md)
// keep them within a 1 MB stack; an application may still compile on a thread with less, and
// there the check turns what would be a stack overflow into a compile error.
#pragma once

namespace pf {

// True when less than a reserve (64 KB; 256 KB under AddressSanitizer, whose frames are larger)
// of the calling thread's stack remains. Reads the thread's stack bounds once per thread.
bool stackNearlyExhausted();

}  // namespace pf
