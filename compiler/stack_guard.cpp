// The stack check (see stack_guard.h): the thread's lowest stack address, from glibc's
// pthread_getattr_np once per thread, against the current frame's address.
#include "compiler/stack_guard.h"

#include "compiler/sanitizers.h"

#include <pthread.h>

#include <cstddef>
#include <cstdint>

namespace pf {
namespace {

#if defined(PF_UNDER_ASAN)
constexpr uintptr_t kReserve = 256 * 1024;
#else
constexpr uintptr_t kReserve = 64 * 1024;
#endif

// The lowest address the thread's stack may reach plus the reserve (0: unknown, never exhausted).
uintptr_t stackFloor() {
  pthread_attr_t attr;
  if (pthread_getattr_np(pthread_self(), &attr) != 0) return 0;
  void* low = nullptr;
  size_t size = 0;
  const int rc = pthread_attr_getstack(&attr, &low, &size);
  pthread_attr_destroy(&attr);
  if (rc != 0 || !low || size <= kReserve) return 0;
  return reinterpret_cast<uintptr_t>(low) + kReserve;
}

}  // namespace

bool stackNearlyExhausted() {
  thread_local const uintptr_t floor = stackFloor();
  // The frame's own address: a local's may live on ASan's fake stack, far from the real one.
  return floor != 0 && reinterpret_cast<uintptr_t>(__builtin_frame_address(0)) < floor;
}

}  // namespace pf
