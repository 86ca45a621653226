// The steady state allocates nothing per triangle: after a warm-up frame, frames of 2000 and of
// 4000 triangles -- submitted one glBegin / glEnd each, the worst case, and in one glBegin --
// make the same small number of heap allocations (the frame's state changes: a channel layout
// copied into the scene once), on the API thread and the rasterizer's threads alike (global
// operator new counted while drawing).
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t n, std::align_val_t a) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  const std::size_t align = static_cast<std::size_t>(a);
  if (void* p = std::aligned_alloc(align, (n + align - 1) / align * align)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace {

void drawFrame(bool one_begin_per_triangle, int triangles) {
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (!one_begin_per_triangle) pfglBegin(GL_TRIANGLES);
  for (int i = 0; i < triangles; ++i) {
    if (one_begin_per_triangle) pfglBegin(GL_TRIANGLES);
    const float x = static_cast<float>(i % 50) * 5.0f, y = static_cast<float>(i / 50 % 40) * 6.0f;
    pfglColor3f(1, 0, 0);
    pfglVertex3f(x, y, 0.1f);
    pfglColor3f(0, 1, 0);
    pfglVertex3f(x + 7, y + 1, 0.2f);
    pfglColor3f(0, 0, 1);
    pfglVertex3f(x + 2, y + 8, 0.3f);
    if (one_begin_per_triangle) pfglEnd();
  }
  if (!one_begin_per_triangle) pfglEnd();
  pfglFinish();
}

}  // namespace

TEST(Allocation, NoHeapAllocationPerTriangleInTheSteadyState) {
  std::vector<unsigned char> px(256 * 256 * 4);
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, 2, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  ASSERT_NE(ctx, nullptr);
  pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, 256, 256);
  pfglEnable(GL_DEPTH_TEST);
  pfglMatrixMode(GL_PROJECTION);
  pfglOrtho(0, 256, 0, 256, -1, 1);
  for (bool per_triangle : {false, true}) {
    drawFrame(per_triangle, 4000);  // warm-up: buffers grow to their working size
    long counts[2];
    for (int k = 0; k < 2; ++k) {
      g_allocations = 0;
      g_counting = true;
      drawFrame(per_triangle, 2000 * (k + 1));
      g_counting = false;
      counts[k] = g_allocations.load();
    }
    const char* how = per_triangle ? "a glBegin per triangle" : "one glBegin";
    EXPECT_EQ(counts[0], counts[1]) << how << ": allocations grow with the triangles";
    EXPECT_LE(counts[1], 4) << how;
  }
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
}
