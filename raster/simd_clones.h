// Loops compiled for AVX-512, AVX2 and the baseline, the widest the machine runs chosen at load
// time (GCC's target_clones): the shading pass's, the field rays'. The same operations in the
// same order in every clone (no contraction: CMakeLists' -ffp-contract=off; IEEE operations
// round the same in a vector lane as in a scalar register), so the same bits on every machine.
// (Not under the sanitizers: an instrumented ifunc resolver runs at load time before
// ThreadSanitizer's runtime is up, and crashes; those builds run the baseline loops, the same
// bits.)
#pragma once

#include "compiler/sanitizers.h"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(PF_SANITIZED)
#define PF_SIMD_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define PF_SIMD_CLONES
#endif
