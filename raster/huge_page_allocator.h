// An allocator for the scene's big arenas (records, instances): blocks of 2 MiB and more are
// aligned to 2 MiB and offered to the kernel as transparent huge pages (madvise; on Linux with
// THP in "madvise" or "always" mode). The rasterizer reads records in a sparse walk -- each
// tile's instances -- where 4 KiB pages cost a TLB miss per record: measured on 100k small
// spheres (26 MB of records), the walk's loads and prefetches waited on page walks. Smaller
// blocks, and systems without THP, get ordinary memory. (100k impostors, 1 thread, 15 frames
// alternated three times: 2-4% less CPU time; perf: the tile walk 10.7% -> 4.6% of the frame.)
// The big blocks are mapped fresh (mmap), not taken from the heap: memory the heap hands back
// after others freed it is already faulted in as 4 KiB pages, and the advice only shapes later
// faults -- in pfbench, after OSMesa had churned the heap, the 200k small triangles' arenas
// got no huge page at all.
#pragma once

#include <cstddef>
#include <cstdint>
#include <new>
#include <utility>

#include "compiler/sanitizers.h"

// Big blocks mapped with mmap: on Linux, and not under ASan, whose checks cover only the memory
// its own allocator hands out (an overrun of a record must still be caught there).
#if defined(__linux__) && !defined(PF_UNDER_ASAN)
#define PF_HUGE_PAGES_MAPPED 1
#include <sys/mman.h>
#endif

namespace pf {

template <class T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr size_t kHugePage = size_t{2} << 20;
  static constexpr size_t kSmallAlign = alignof(T) < 64 ? 64 : alignof(T);  // a cache line

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  static size_t roundedUp(size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

  T* allocate(size_t n) {
    if (n > static_cast<size_t>(-1) / sizeof(T)) throw std::bad_alloc();
    const size_t bytes = n * sizeof(T);
    if (bytes < kHugePage) return static_cast<T*>(::operator new(bytes, std::align_val_t{kSmallAlign}));
    const size_t rounded = roundedUp(bytes);
#if defined(PF_HUGE_PAGES_MAPPED)
    // A mapping one huge page longer than asked, trimmed to the aligned part.
    void* mapped = ::mmap(nullptr, rounded + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) throw std::bad_alloc();
    const uintptr_t start = reinterpret_cast<uintptr_t>(mapped);
    const uintptr_t aligned = (start + kHugePage - 1) & ~(kHugePage - 1);
    if (aligned > start) ::munmap(mapped, aligned - start);
    const uintptr_t end = start + rounded + kHugePage;
    if (end > aligned + rounded) ::munmap(reinterpret_cast<void*>(aligned + rounded), end - aligned - rounded);
#if defined(MADV_HUGEPAGE)
    ::madvise(reinterpret_cast<void*>(aligned), rounded, MADV_HUGEPAGE);  // advice only: a refusal leaves ordinary pages
#endif
    return reinterpret_cast<T*>(aligned);
#else
    return static_cast<T*>(::operator new(rounded, std::align_val_t{kHugePage}));
#endif
  }
  void deallocate(T* p, size_t n) noexcept {
    const size_t bytes = n * sizeof(T);
    if (bytes < kHugePage) {
      ::operator delete(p, std::align_val_t{kSmallAlign});
      return;
    }
#if defined(PF_HUGE_PAGES_MAPPED)
    ::munmap(p, roundedUp(bytes));
#else
    ::operator delete(p, std::align_val_t{kHugePage});
#endif
  }
  // An element made without a value (a vector's resize) is left uninitialised: the scene's
  // records are written by setup before anything reads them, and a vector of this allocator
  // value-initialises element by element -- zeroing a frame's 32 MB of records cost more than
  // setting them up. Elements made from a value are made from it.
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
};

}  // namespace pf
