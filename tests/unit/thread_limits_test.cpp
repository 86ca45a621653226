// Contexts where the system refuses threads (docs/reliability.md): under an address-space limit
// that leaves room for a few dozen thread stacks, 256-thread contexts are created and draw --
// with the threads the system allows -- instead of aborting on an escaped std::system_error.
// Each case runs in a child process (the limit must not reach the other tests) and is skipped
// under ASan and TSan, which reserve far more address space than any such limit.
#include <gtest/gtest.h>

#include <primflow/gl.h>
#include <primflow/gl_mangle.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdlib>
#include <memory>
#include <vector>

#include "compiler/sanitizers.h"

namespace {

#if defined(PF_SANITIZED)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

// Address space in use now, from /proc/self/statm (pages).
rlim_t addressSpaceInUse() {
  FILE* f = std::fopen("/proc/self/statm", "r");
  unsigned long pages = 0;
  if (f) {
    if (std::fscanf(f, "%lu", &pages) != 1) pages = 0;
    std::fclose(f);
  }
  return static_cast<rlim_t>(pages) * 4096;
}

// In the child: 256-thread contexts under a limit of what is in use plus 400 MB (about 50 thread
// stacks of 8 MB), each drawing a triangle that must land in its buffer.
[[noreturn]] void drawUnderThreadLimit() {
  alarm(60);  // a pool that hangs where threads fail (as it once did, unwinding) fails the test
  const rlim_t limit = addressSpaceInUse() + (rlim_t{400} << 20);
  const struct rlimit rl = {limit, limit};
  if (setrlimit(RLIMIT_AS, &rl) != 0) std::_Exit(3);
  std::vector<PFcontext> contexts;
  for (int k = 0; k < 3; ++k) {
    const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, 256, PF_JIT, 0, 0};
    PFcontext ctx = pfCreateContextAttribs(attribs);
    if (!ctx) continue;  // allowed too: NULL, never an abort
    contexts.push_back(ctx);
    std::vector<unsigned char> px(64 * 64 * 4, 0);
    if (!pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, 64, 64)) std::_Exit(4);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor3f(1, 0, 0);
    glBegin(GL_TRIANGLES);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(0, 1);
    glEnd();
    glFinish();
    if (px[(32 * 64 + 32) * 4] != 255) std::_Exit(5);
    pfMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  }
  for (PFcontext c : contexts) pfDestroyContext(c);
  std::_Exit(contexts.empty() ? 6 : 0);
}

TEST(ThreadLimits, ContextsStartWithTheThreadsTheSystemAllows) {
  if (kSanitized) GTEST_SKIP() << "the sanitizers' shadow memory does not fit an address-space limit";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(drawUnderThreadLimit(), ::testing::ExitedWithCode(0), "");
}

}  // namespace
