// The steady state allocates nothing per triangle: after a warm-up frame, frames of 2000 and of
// 4000 triangles -- submitted one glBegin / glEnd each, the worst case, and in one glBegin --
// make the same small number of heap allocations (the frame's state changes: a channel layout
// copied into the scene once), on the API thread and the rasterizer's threads alike (global
// operator new counted while drawing). Nor per ray of an implicit surface's analytic method
// (CSG leaves' roots), nor per gradient of a short tape (the executor's scratch evaluator).
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "compiler/field/field_tape.h"
#include "compiler/native/native_cache.h"
#include "raster/field/gradient_evaluator.h"
#include "raster/field/polynomial_roots.h"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
// Not 0: every allocation of at least this many bytes fails (the OutOfMemory test's "memory").
std::atomic<std::size_t> g_fail_from_bytes{0};
void failIfTooLarge(std::size_t n) {
  const std::size_t limit = g_fail_from_bytes.load(std::memory_order_relaxed);
  if (limit != 0 && n >= limit) throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t n) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  failIfTooLarge(n);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t n, std::align_val_t a) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  failIfTooLarge(n);
  const std::size_t align = static_cast<std::size_t>(a);
  if (void* p = std::aligned_alloc(align, (n + align - 1) / align * align)) return p;
  throw std::bad_alloc();
}
// This file replaces the global operator new with malloc, so free is the matching release; GCC
// cannot see the replacement when it inlines a std::allocator, hence the pragma.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
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
  // Native code compiled on a program's first block: in the warm-up (a compile allocates).
  pf::NativeProgramCache::instance().setThreshold(0);
  pf::NativeProgramCache::instance().setWalkThreshold(0);
  std::vector<unsigned char> px(256 * 256 * 4);
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, 2, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  ASSERT_NE(ctx, nullptr);
  pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, 256, 256);
  pfglEnable(GL_DEPTH_TEST);
  pfglMatrixMode(GL_PROJECTION);
  pfglOrtho(0, 256, 0, 256, -1, 1);
  for (bool per_triangle : {false, true}) {
    // Warm-up: buffers grow to their working size -- each worker's too, which a loaded machine
    // may leave without a tile in one frame (then its first tile allocates in a counted frame).
    for (int w = 0; w < 5; ++w) drawFrame(per_triangle, 4000);
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

namespace {

// Fidget text (negative inside): the union of two spheres of radius 0.6, centred at x = -0.3 and
// x = 0.4 -- the min of two quadrics, a CSG tree the analytic method solves leaf by leaf.
constexpr const char* kTwoSpheresVm =
    "x var-x\ny var-y\nz var-z\ny2 square y\nz2 square z\nyz add y2 z2\nr const 0.36\n"
    "ca const 0.3\nxa add x ca\nxa2 square xa\nsa add xa2 yz\na sub sa r\n"
    "cb const 0.4\nxb sub x cb\nxb2 square xb\nsb add xb2 yz\nb sub sb r\nout min a b\n";

// `instances` copies of the field, side by side, by the analytic method.
void drawAnalyticFrame(GLuint field, int instances) {
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const GLuint f = pfglGetParamNameEXT("field"), lo = pfglGetParamNameEXT("box_min"),
               hi = pfglGetParamNameEXT("box_max"), m = pfglGetParamNameEXT("method"),
               steps = pfglGetParamNameEXT("steps");
  for (int i = 0; i < instances; ++i) {
    pfglMatrixMode(GL_MODELVIEW);
    pfglLoadIdentity();
    pfglTranslatef(-2.0f + 2.0f * static_cast<float>(i), 0.0f, 0.0f);
    pfglBegin(pfglGetPrimitiveEXT("implicit"));
    pfglRastParamfEXT(f, static_cast<float>(field));
    pfglRastParam3fEXT(lo, -1, -1, -1);
    pfglRastParam3fEXT(hi, 1, 1, 1);
    pfglRastParamfEXT(m, static_cast<float>(GL_FIELD_METHOD_ANALYTIC_EXT));
    pfglRastParamfEXT(steps, 0.0f);
    pfglSequencePointEXT();
    pfglEnd();
  }
  pfglFinish();
}

}  // namespace

// Frames of one and of three CSG surfaces (the analytic method: each ray's leaf polynomials and
// their roots, CsgTree::firstHit) make the same few allocations after a warm-up: none per ray.
TEST(Allocation, NoHeapAllocationPerRayOfTheAnalyticMethod) {
  pf::NativeProgramCache::instance().setThreshold(0);
  pf::NativeProgramCache::instance().setWalkThreshold(0);  // native code made in the warm-up
  std::vector<unsigned char> px(192 * 64 * 4);
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, 2, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  ASSERT_NE(ctx, nullptr);
  pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, 192, 64);
  pfglEnable(GL_DEPTH_TEST);
  pfglMatrixMode(GL_PROJECTION);
  pfglOrtho(-3, 3, -1, 1, -5, 5);
  const GLuint field = pfglCompileFieldEXT(GL_FIELD_FIDGET_EXT, "two_spheres.vm", kTwoSpheresVm, 0.0f);
  ASSERT_NE(field, 0u);
  for (int k = 0; k < 2; ++k) drawAnalyticFrame(field, 3);  // warm-up: per-thread scratch grows
  long counts[2];
  for (int k = 0; k < 2; ++k) {
    g_allocations = 0;
    g_counting = true;
    drawAnalyticFrame(field, 1 + 2 * k);
    g_counting = false;
    counts[k] = g_allocations.load();
  }
  long covered = 0;
  for (size_t i = 1; i < px.size(); i += 4) covered += px[i] != 0 || px[i - 1] != 0 || px[i + 1] != 0;
  std::printf("analytic frames of 1 and 3 surfaces: %ld and %ld allocations, %ld pixels covered\n", counts[0],
              counts[1], covered);
  EXPECT_GT(covered, 3 * 1000) << "the three surfaces are drawn";
  EXPECT_EQ(counts[0], counts[1]) << "allocations grow with the rays";
  EXPECT_LE(counts[1], 12);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
}

// The pieces on their own: roots of quartics (every case rootsIn splits on: tangent and
// clustered roots, roots at the ends), and the scratch gradient evaluator reset from tape to tape
// once its storage has grown, allocate nothing at all.
TEST(Allocation, RootsAndScratchGradientsAllocateNothing) {
  using namespace pf::field;
  FieldTapeBuilder small, big;
  const FieldTape a = small.finish(small.binary(FieldOp::Mul, small.x(), small.y()));
  uint32_t v = big.x();
  for (int i = 0; i < 40; ++i)
    v = big.binary(i % 2 ? FieldOp::Min : FieldOp::Add, v,
                   big.binary(FieldOp::Mul, big.y(), big.constant(static_cast<float>(i + 1))));
  const FieldTape b = big.finish(v);
  GradientEvaluator scratch;
  scratch.reset(b);  // warm-up: the storage grows to the bigger tape
  scratch.reset(a);
  float x[GradientEvaluator::kBatch] = {}, y[GradientEvaluator::kBatch] = {}, z[GradientEvaluator::kBatch] = {};
  FieldGradient out[GradientEvaluator::kBatch];
  const std::array<std::array<double, 5>, 4> quartics = {{
      {24, -50, 35, -10, 1},      // roots 1, 2, 3, 4
      {1, -4, 6, -4, 1},          // (t - 1)^4: touching
      {0.25, 0, -1.25, 0, 1},     // roots +-0.5, +-1
      {-1, 0, 0, 0, 1e-12},       // far roots, tiny leading coefficient
  }};
  double sum = 0.0;
  g_allocations = 0;
  g_counting = true;
  for (int k = 0; k < 100; ++k) {
    scratch.reset(k % 2 ? a : b);
    scratch.evaluate(x, y, z, GradientEvaluator::kBatch, out);
    for (const auto& c : quartics)
      for (int degree = 1; degree <= 4; ++degree) {
        for (double r : rootsIn(c, degree, -2.0, 4.0 + k)) sum += r;
        if (auto r = firstRootIn(c, degree, 0.5, 1.0)) sum += *r;
      }
  }
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0);
  EXPECT_NE(sum, 0.0);
}

namespace {

// A red triangle over pixel (100, 100) of a 256x256 drawable in window coordinates.
void drawRedTriangle() {
  pfglBegin(GL_TRIANGLES);
  pfglColor3f(1, 0, 0);
  pfglVertex3f(60, 60, 0);
  pfglVertex3f(160, 70, 0);
  pfglVertex3f(90, 170, 0);
  pfglEnd();
}

bool redAt(const std::vector<unsigned char>& px, int x, int y) {
  const unsigned char* p = px.data() + (static_cast<size_t>(y) * 256 + x) * 4;
  return p[0] == 255 && p[1] == 0 && p[2] == 0;
}

// A 256x256 context on 2 threads, made current on `px`, projecting window coordinates.
PFcontext windowContext(std::vector<unsigned char>& px) {
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, 2, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  if (!ctx || !pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, 256, 256)) return nullptr;
  pfglMatrixMode(GL_PROJECTION);
  pfglOrtho(0, 256, 0, 256, -1, 1);
  return ctx;
}

// After a failure: the current context draws the red triangle again, with no error.
void expectDrawsAgain(const std::vector<unsigned char>& px) {
  drawRedTriangle();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_TRUE(redAt(px, 100, 100));
}

}  // namespace

// A request past memory gives GL_OUT_OF_MEMORY, never a crash, and the context draws again
// afterwards: allocations of 64 KB or more made to fail while a glBegin records its vertices,
// while the rasterizer's threads draw a frame (their tile buffers), and for a framebuffer.
TEST(OutOfMemory, FailedAllocationsAreGlOutOfMemoryAndTheContextGoesOn) {
  std::vector<unsigned char> px(256 * 256 * 4);
  PFcontext ctx = windowContext(px);
  ASSERT_NE(ctx, nullptr);

  // While a glBegin records: its vertex rows outgrow 64 KB.
  g_fail_from_bytes = 64 * 1024;
  pfglBegin(GL_TRIANGLES);
  for (int i = 0; i < 30000; ++i) {
    pfglVertex3f(10, 10, 0);
    pfglVertex3f(20, 10, 0);
    pfglVertex3f(10, 20, 0);
  }
  pfglEnd();
  g_fail_from_bytes = 0;
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_OUT_OF_MEMORY));
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  pfglClear(GL_COLOR_BUFFER_BIT);
  expectDrawsAgain(px);

  // While the frame is drawn: a fresh context's first frame sizes its tiles' buffers.
  std::vector<unsigned char> px2(256 * 256 * 4);
  PFcontext fresh = windowContext(px2);
  ASSERT_NE(fresh, nullptr);
  pfglClear(GL_COLOR_BUFFER_BIT);
  drawRedTriangle();
  g_fail_from_bytes = 16 * 1024;
  pfglFinish();
  g_fail_from_bytes = 0;
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_OUT_OF_MEMORY));
  pfglClear(GL_COLOR_BUFFER_BIT);
  expectDrawsAgain(px2);

  // A glClear after drawing draws first: the same failure there.
  std::vector<unsigned char> px3(256 * 256 * 4);
  PFcontext third = windowContext(px3);
  ASSERT_NE(third, nullptr);
  drawRedTriangle();
  g_fail_from_bytes = 16 * 1024;
  pfglClear(GL_COLOR_BUFFER_BIT);
  g_fail_from_bytes = 0;
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_OUT_OF_MEMORY));
  expectDrawsAgain(px3);
  pfDestroyContext(third);
  ASSERT_TRUE(pfMakeCurrent(fresh, px2.data(), GL_UNSIGNED_BYTE, 256, 256));

  // A framebuffer past memory: pfMakeCurrent fails, the context keeps its drawable.
  std::vector<unsigned char> big(16);
  g_fail_from_bytes = 64 * 1024;
  testing::internal::CaptureStderr();
  EXPECT_FALSE(pfMakeCurrent(fresh, big.data(), GL_UNSIGNED_BYTE, 8192, 8192));
  g_fail_from_bytes = 0;
  EXPECT_EQ(testing::internal::GetCapturedStderr(),
            "primflow: pfMakeCurrent: out of memory for a 8192x8192 drawable: the context keeps its previous one\n");
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_OUT_OF_MEMORY));
  pfglClear(GL_COLOR_BUFFER_BIT);
  drawRedTriangle();
  pfglFinish();
  EXPECT_TRUE(redAt(px2, 100, 100));

  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(fresh);
  pfDestroyContext(ctx);
}

// An accumulation buffer past memory: pfMakeCurrent fails with GL_OUT_OF_MEMORY and the context
// keeps its drawable, accumulation buffer and all.
TEST(OutOfMemory, AccumulationBufferPastMemoryKeepsTheDrawable) {
  std::vector<unsigned char> px(64 * 64 * 4);
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_ACCUM_BITS, 16, PF_THREADS, 1, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  ASSERT_NE(ctx, nullptr);
  ASSERT_TRUE(pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, 64, 64));
  pfglClearColor(0.6f, 0.2f, 1.0f, 1.0f);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglAccum(GL_LOAD, 1.0f);
  std::vector<unsigned char> big(16);
  g_fail_from_bytes = 1024 * 1024;  // the accumulation buffer alone is 8 bytes a pixel
  testing::internal::CaptureStderr();
  EXPECT_FALSE(pfMakeCurrent(ctx, big.data(), GL_UNSIGNED_BYTE, 4096, 4096));
  g_fail_from_bytes = 0;
  testing::internal::GetCapturedStderr();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_OUT_OF_MEMORY));
  pfglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglAccum(GL_RETURN, 1.0f);  // what was loaded before the failure
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(px[(10 * 64 + 10) * 4 + 0], 153);
  EXPECT_EQ(px[(10 * 64 + 10) * 4 + 2], 255);
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
}

// A display list past memory: the commands that do not fit are left out with GL_OUT_OF_MEMORY
// (and one line on stderr), the list keeps those recorded before, and the context goes on --
// compiling and calling lists again. Recording allocates nothing per command once its buffer
// has grown: a second list of the same length makes no allocation but its stored copy.
TEST(OutOfMemory, ADisplayListPastMemoryLeavesCommandsOutAndTheContextGoesOn) {
  std::vector<unsigned char> px(256 * 256 * 4);
  PFcontext ctx = windowContext(px);
  ASSERT_NE(ctx, nullptr);
  auto triangles = [](int n) {  // (the list holds the vertices; glBegin and glEnd come from outside)
    for (int i = 0; i < n; ++i) {
      pfglVertex3f(10, 10, 0);
      pfglVertex3f(20, 10, 0);
      pfglVertex3f(10, 20, 0);
    }
  };
  g_fail_from_bytes = 64 * 1024;
  testing::internal::CaptureStderr();
  pfglNewList(1, GL_COMPILE);
  triangles(30000);  // 90,000 vertices of 16 bytes each
  pfglEndList();
  g_fail_from_bytes = 0;
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "primflow: display list 1: out of memory: commands left out of it\n");
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_OUT_OF_MEMORY));
  EXPECT_EQ(pfglIsList(1), GL_TRUE);
  pfglBegin(GL_TRIANGLES);
  pfglCallList(1);  // the vertices that fit
  pfglEnd();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglNewList(2, GL_COMPILE);
  drawRedTriangle();
  pfglEndList();
  pfglCallList(2);
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_TRUE(redAt(px, 100, 100));

  pfglNewList(3, GL_COMPILE);
  triangles(1000);
  pfglEndList();
  g_allocations = 0;
  g_counting = true;
  pfglNewList(4, GL_COMPILE);
  triangles(1000);
  pfglEndList();
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 2) << "the list's stored copy and its entry among the lists";
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
}

// Registering a primitive costs the same however many a context holds (each of 10,000 separate
// pfglCompilePrimitivesEXT calls was once slower than the last: every compile copied the whole
// table of callable primitives). Counted in heap allocations of one compile, after 50 and after
// 2,000 primitives.
TEST(Allocation, CompilingAPrimitiveCostsTheSameWithManyRegistered) {
  std::vector<unsigned char> px(16 * 16 * 4);
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  ASSERT_NE(ctx, nullptr);
  pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, 16, 16);
  auto source = [](int i) {
    return "primitive user" + std::to_string(i) + "(varying float X, Y; inout varying float Z) { Z = 0.5; }\n";
  };
  long counts[2];
  int registered = 0;
  for (int k = 0; k < 2; ++k) {
    for (; registered < (k == 0 ? 50 : 2000); ++registered)
      ASSERT_NE(pfglCompilePrimitivesEXT(source(registered).c_str()), 0u);
    // The same length of name each time, so the strings allocate alike.
    const std::string probe = "primitive probe" + std::to_string(1000 + k) +
                              "(varying float X, Y; inout varying float Z) { Z = 0.5; }\n";
    g_allocations = 0;
    g_counting = true;
    const GLuint module = pfglCompilePrimitivesEXT(probe.c_str());
    g_counting = false;
    ASSERT_NE(module, 0u);
    counts[k] = g_allocations.load();
  }
  // (The registry's own containers may grow by one step between the two.)
  EXPECT_LE(counts[1], counts[0] + 4) << "after 50: " << counts[0] << " allocations, after 2000: " << counts[1];
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
}

// A texture image past memory: glTexImage2D answers GL_OUT_OF_MEMORY and keeps the level it had;
// glTexSubImage2D and a draw sampling the texture go on; a smaller image then fits.
TEST(OutOfMemory, ATextureImagePastMemoryIsAnErrorNotACrash) {
  std::vector<unsigned char> px(256 * 256 * 4);
  PFcontext ctx = windowContext(px);
  ASSERT_NE(ctx, nullptr);
  const GLubyte blue[4] = {0, 0, 255, 255};
  pfglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  pfglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, blue);
  g_fail_from_bytes = 1024 * 1024;
  pfglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4096, 4096, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);  // 64 MB
  g_fail_from_bytes = 0;
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_OUT_OF_MEMORY));
  GLint width = -1;
  pfglGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(width, 1);
  pfglEnable(GL_TEXTURE_2D);
  pfglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  drawRedTriangle();  // replaced by the texture's blue
  pfglFinish();
  const unsigned char* p = px.data() + (static_cast<size_t>(100) * 256 + 100) * 4;
  EXPECT_TRUE(p[0] == 0 && p[1] == 0 && p[2] == 255);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
}
