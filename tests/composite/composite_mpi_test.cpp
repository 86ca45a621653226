// pfCompositeDepthMPI under mpirun (2, 3 and 4 ranks, tests/CMakeLists.txt): sort-last
// compositing (PixelFlow's image composition, Molnar et al. 1992, cited in seed 003 section 1)
// must give, bit for bit, the image and depth buffer ONE process draws -- computed here by the
// root in a context of its own, never through the compositor. Each rank draws its share of a
// small scene (spheres, quads, and objects that tie in depth exactly); every algorithm,
// compression, result mode and root is checked. Then the failures: a rank with no context, a
// wrong-sized buffer, bad or mismatched options -- every rank must return an error, not hang
// (the ctest TIMEOUT is the hang guard) -- and a rank that never arrives (the timeout).
#include <gtest/gtest.h>

#include <primflow/composite.h>
#include <primflow/gl.h>

#include <chrono>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace {

int g_rank = 0, g_ranks = 1;

// A context bound to its own buffer.
struct Frame {
  PFcontext ctx = nullptr;
  std::vector<unsigned char> pixels;
  int width, height;

  Frame(int w, int h) : width(w), height(h) {
    const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, 1, 0};
    ctx = pfCreateContextAttribs(attribs);
    pixels.assign(static_cast<size_t>(w) * h * 4, 0);
    bind();
  }
  ~Frame() { pfDestroyContext(ctx); }
  void bind() { EXPECT_EQ(pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, width, height), GL_TRUE); }
  std::vector<float> depth() const {
    GLint w = 0, h = 0, bytes = 0;
    void* d = nullptr;
    EXPECT_EQ(pfGetDepthBuffer(ctx, &w, &h, &bytes, &d), GL_TRUE);
    const float* f = static_cast<const float*>(d);
    return std::vector<float>(f, f + static_cast<size_t>(width) * height);
  }
};

// The scene: object i is one glBegin/glEnd. In the tie scene, objects 7/8, 9/10 and 11/12 are
// the same geometry in two colours (equal depths at every pixel) -- pairs that round-robin puts
// on ranks in the opposite order for 2, 3 and 4 ranks; the others are spheres and quads that
// overlap at different depths.
constexpr int kObjects = 14;

void beginFrame(int w, int h) {
  pfglViewport(0, 0, w, h);
  pfglClearColor(0.1f, 0.2f, 0.3f, 1.0f);
  pfglClearDepth(1.0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglMatrixMode(GL_PROJECTION);
  pfglLoadIdentity();
  pfglFrustum(-0.6, 0.6, -0.4, 0.4, 1, 20);
  pfglMatrixMode(GL_MODELVIEW);
  pfglLoadIdentity();
  pfglTranslatef(0, 0, -6);
  pfglEnable(GL_LIGHTING);
  pfglEnable(GL_LIGHT0);
  pfglEnable(GL_COLOR_MATERIAL);
  const GLfloat dir[4] = {-0.3f, 0.5f, 0.8f, 0.0f};
  pfglLightfv(GL_LIGHT0, GL_POSITION, dir);
}

void quad(float x0, float y0, float x1, float y1, float z, float tilt) {
  pfglBegin(GL_QUADS);
  pfglNormal3f(0, 0, 1);
  pfglVertex3f(x0, y0, z - tilt);
  pfglVertex3f(x1, y0, z + tilt);
  pfglVertex3f(x1, y1, z + tilt);
  pfglVertex3f(x0, y1, z - tilt);
  pfglEnd();
}

void spheres(float x, float y, float z, float r, int n) {
  const GLenum mode = pfglGetPrimitiveEXT("sphere_impostors");
  const GLuint center = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
  pfglBegin(mode);
  for (int k = 0; k < n; ++k) {
    const GLfloat c[3] = {x + 0.35f * k, y - 0.2f * k, z + 0.1f * k};
    pfglRastParamfvEXT(center, 3, c);
    pfglRastParamfEXT(radius, r);
    pfglSequencePointEXT();
  }
  pfglEnd();
}

void drawObject(int i, bool ties) {
  const float hue = static_cast<float>(i) / kObjects;
  pfglColor3f(0.3f + 0.7f * hue, 1.0f - hue, 0.5f + 0.4f * (i % 3) / 2.0f);
  if (ties && i >= 7 && i <= 12) {  // 7/8, 9/10, 11/12: equal geometry, different colours
    const int pair = (i - 7) / 2;
    if (pair == 0) quad(-1.5f, -1.0f, 0.5f, 0.6f, 0.4f, 0.3f);
    else if (pair == 1) spheres(-0.2f, 0.1f, 0.8f, 0.45f, 2);
    else quad(-2.5f, -1.5f, 2.5f, 1.5f, -0.5f, 0.0f);  // behind most, ties itself only
    return;
  }
  switch (i % 4) {
    case 0: spheres(-1.4f + 0.3f * i, -0.6f + 0.1f * i, -0.3f * (i % 5), 0.5f, 3); break;
    case 1: quad(-2.0f + 0.25f * i, -1.2f, 0.2f + 0.25f * i, 0.3f, 0.2f * (i % 3), 0.4f); break;
    case 2: spheres(1.2f - 0.2f * i, 0.7f - 0.15f * i, 0.5f, 0.35f, 2); break;
    default: quad(-0.5f, -1.3f + 0.1f * i, 1.8f, 1.0f, -0.2f * (i % 4), -0.6f); break;
  }
}

enum class Split { RoundRobin, Block };

int rankOf(int object, Split split) {
  if (split == Split::RoundRobin) return object % g_ranks;
  // Block: objects [r*n/p, (r+1)*n/p) to rank r.
  for (int r = 0; r < g_ranks; ++r)
    if (object < (r + 1) * kObjects / g_ranks) return r;
  return g_ranks - 1;
}

// This rank's share.
void drawShare(Frame& f, Split split, bool ties) {
  f.bind();
  beginFrame(f.width, f.height);
  for (int i = 0; i < kObjects; ++i)
    if (rankOf(i, split) == g_rank) drawObject(i, ties);
  pfglFinish();
}

// One process: every object, in scene order, or rank-major (rank 0's objects, then rank 1's...).
void drawWhole(Frame& f, Split split, bool ties, bool rank_major) {
  f.bind();
  beginFrame(f.width, f.height);
  for (int r = 0; r < (rank_major ? g_ranks : 1); ++r)
    for (int i = 0; i < kObjects; ++i)
      if (!rank_major || rankOf(i, split) == r) drawObject(i, ties);
  pfglFinish();
}

// Rows [first, first + count) of a and b are bit-identical, colour and depth; where not, the
// first differing pixel is named.
void expectRowsEqual(const Frame& got, const Frame& want, int first, int count, const std::string& what) {
  const size_t from = static_cast<size_t>(first) * got.width, to = from + static_cast<size_t>(count) * got.width;
  const std::vector<float> gd = got.depth(), wd = want.depth();
  size_t bad = 0, first_bad = to;
  for (size_t i = from; i < to; ++i)
    if (std::memcmp(&got.pixels[4 * i], &want.pixels[4 * i], 4) != 0 || std::memcmp(&gd[i], &wd[i], 4) != 0) {
      if (!bad) first_bad = i;
      ++bad;
    }
  EXPECT_EQ(bad, 0u) << what << ": " << bad << " pixels differ, the first at (" << first_bad % got.width << ", "
                     << first_bad / got.width << "): depth " << gd[first_bad] << " vs " << wd[first_bad];
}

struct Case {
  int width, height;
  Split split;
  bool ties;
  bool rank_major;  // compare with the rank-major one-process image (the tie rule)
};

void compositeAndCompare(const Case& c, const PFcompositeOptions& options, const std::string& name) {
  Frame share(c.width, c.height);
  drawShare(share, c.split, c.ties);
  PFcompositeStats st;  // (share is current: binding it again would clear its depth buffer)
  const int rc = pfCompositeDepthMPI(MPI_COMM_WORLD, &options, &st);
  ASSERT_EQ(rc, PF_COMPOSITE_OK) << name << ": " << pfCompositeErrorString(rc);
  EXPECT_EQ(st.ranks, g_ranks);
  Frame whole(c.width, c.height);
  drawWhole(whole, c.split, c.ties, c.rank_major);
  if (options.result == PF_COMPOSITE_GATHER) {
    if (g_rank == options.root) expectRowsEqual(share, whole, 0, c.height, name);
    else EXPECT_EQ(st.row_count, 0);
  } else {
    // Every rank's band is final, and the bands tile the image.
    expectRowsEqual(share, whole, st.first_row, st.row_count, name + " (band)");
    int rows = 0;
    MPI_Allreduce(&st.row_count, &rows, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(rows, c.height) << name;
  }
  if (g_ranks > 1 && c.height * c.width > 64) {
    EXPECT_GT(st.bytes_sent + st.bytes_received, 0u) << name;
  }
}

PFcompositeOptions options(int algorithm, int compress, int result, int root) {
  PFcompositeOptions o;
  pfCompositeDefaultOptions(&o);
  o.algorithm = algorithm;
  o.compress = compress;
  o.result = result;
  o.root = root;
  o.timeout_seconds = 20;
  return o;
}

const char* algorithmName(int a) {
  return a == PF_COMPOSITE_AUTO ? "auto" : a == PF_COMPOSITE_BINARY_SWAP ? "binary-swap" : "direct-send";
}

// --- Identity with one process ---------------------------------------------------------------------

TEST(CompositeMpi, EveryAlgorithmAndCompressionGivesTheOneProcessImage) {
  for (int algorithm : {PF_COMPOSITE_AUTO, PF_COMPOSITE_BINARY_SWAP, PF_COMPOSITE_DIRECT_SEND})
    for (int compress : {0, 1})
      for (Split split : {Split::RoundRobin, Split::Block}) {
        const std::string name = std::string(algorithmName(algorithm)) + (compress ? ", compressed" : "") +
                                 (split == Split::Block ? ", block split" : ", round-robin split");
        compositeAndCompare({97, 61, split, false, false}, options(algorithm, compress, PF_COMPOSITE_GATHER, 0), name);
      }
}

// Equal depths on different ranks: with ranks holding consecutive objects in order (block), the
// lower rank holds the earlier object, so "lower rank wins" is GL_LESS's "first drawn wins" and
// the composite is the scene's own image; with round-robin it is the image of the objects drawn
// rank-major -- the documented tie rule, whatever the exchange pattern.
TEST(CompositeMpi, DepthTiesGoToTheLowerRank) {
  for (int algorithm : {PF_COMPOSITE_BINARY_SWAP, PF_COMPOSITE_DIRECT_SEND})
    for (int compress : {0, 1}) {
      const std::string name = std::string(algorithmName(algorithm)) + (compress ? ", compressed" : "");
      compositeAndCompare({80, 50, Split::Block, true, false}, options(algorithm, compress, PF_COMPOSITE_GATHER, 0),
                          name + ", ties, block split = one process in scene order");
      compositeAndCompare({80, 50, Split::RoundRobin, true, true},
                          options(algorithm, compress, PF_COMPOSITE_GATHER, 0),
                          name + ", ties, round-robin = one process rank-major");
    }
}

TEST(CompositeMpi, TheTieScenesTieAcrossRanks) {
  // So that the test above can fail: with 2+ ranks the round-robin tie image differs from the
  // scene-order image (a tie pair's objects sit on different ranks, the higher rank first).
  if (g_ranks < 2) GTEST_SKIP() << "one rank";
  Frame a(80, 50), b(80, 50);
  drawWhole(a, Split::RoundRobin, true, false);
  drawWhole(b, Split::RoundRobin, true, true);
  EXPECT_NE(a.pixels, b.pixels);
  EXPECT_EQ(a.depth(), b.depth());  // only colours differ: the depths tie
}

TEST(CompositeMpi, AnyRootAndDistributedBands) {
  for (int algorithm : {PF_COMPOSITE_BINARY_SWAP, PF_COMPOSITE_DIRECT_SEND})
    for (int compress : {0, 1}) {
      const std::string name = std::string(algorithmName(algorithm)) + (compress ? ", compressed" : "");
      compositeAndCompare({64, 45, Split::RoundRobin, false, false},
                          options(algorithm, compress, PF_COMPOSITE_GATHER, g_ranks - 1), name + ", last rank root");
      compositeAndCompare({64, 45, Split::RoundRobin, true, true},
                          options(algorithm, compress, PF_COMPOSITE_DISTRIBUTED, 0), name + ", distributed, ties");
      compositeAndCompare({64, 45, Split::Block, true, false},
                          options(algorithm, compress, PF_COMPOSITE_DISTRIBUTED, 0), name + ", distributed, ties, block");
    }
}

TEST(CompositeMpi, FewerRowsThanRanksAndOnePixel) {
  for (int algorithm : {PF_COMPOSITE_BINARY_SWAP, PF_COMPOSITE_DIRECT_SEND})
    for (const Case& c : {Case{40, 2, Split::RoundRobin, false, false}, Case{1, 1, Split::Block, false, false}}) {
      compositeAndCompare(c, options(algorithm, 1, PF_COMPOSITE_GATHER, 0),
                          std::string(algorithmName(algorithm)) + " " + std::to_string(c.width) + "x" +
                              std::to_string(c.height));
      compositeAndCompare(c, options(algorithm, 0, PF_COMPOSITE_DISTRIBUTED, 0),
                          std::string(algorithmName(algorithm)) + " distributed " + std::to_string(c.width) + "x" +
                              std::to_string(c.height));
    }
}

// --- Failures: every rank returns an error ------------------------------------------------------

// Runs the composite with this rank's frame prepared by `setup`, and checks every rank's code.
void expectAllFail(const std::function<void(Frame&, PFcompositeOptions&)>& setup, int culprit, int culprit_code,
                   int others_code) {
  Frame f(32, 24);
  drawShare(f, Split::RoundRobin, false);
  PFcompositeOptions o = options(PF_COMPOSITE_AUTO, 0, PF_COMPOSITE_GATHER, 0);
  setup(f, o);
  const auto t0 = std::chrono::steady_clock::now();
  const int rc = pfCompositeDepthMPI(MPI_COMM_WORLD, &o, nullptr);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(rc, culprit < 0 || g_rank == culprit ? culprit_code : others_code)
      << "rank " << g_rank << ": " << pfCompositeErrorString(rc);
  EXPECT_LT(seconds, 15.0) << "an error must not wait for the timeout (20 s)";
  f.bind();  // rebind for the next test
}

TEST(CompositeMpi, ARankWithoutAContextFailsEveryRank) {
  const int culprit = g_ranks - 1;
  expectAllFail([&](Frame&, PFcompositeOptions&) { if (g_rank == culprit) pfMakeCurrent(nullptr, nullptr, 0, 0, 0); },
                culprit, PF_COMPOSITE_NO_CONTEXT, PF_COMPOSITE_PEER_FAILED);
}

TEST(CompositeMpi, AWrongSizedBufferFailsEveryRank) {
  std::vector<unsigned char> other(33 * 24 * 4);
  expectAllFail(
      [&](Frame& f, PFcompositeOptions&) {
        if (g_rank == g_ranks - 1) pfMakeCurrent(f.ctx, other.data(), GL_UNSIGNED_BYTE, 33, 24);
      },
      -1, g_ranks > 1 ? PF_COMPOSITE_SIZE_MISMATCH : PF_COMPOSITE_OK, 0);
}

TEST(CompositeMpi, BadOrMismatchedOptionsFailEveryRank) {
  const int culprit = g_ranks > 1 ? 1 : 0;
  expectAllFail([&](Frame&, PFcompositeOptions& o) { if (g_rank == culprit) o.root = -1; }, culprit,
                PF_COMPOSITE_BAD_OPTIONS, PF_COMPOSITE_PEER_FAILED);
  expectAllFail([&](Frame&, PFcompositeOptions& o) { o.root = g_ranks; }, -1, PF_COMPOSITE_BAD_OPTIONS, 0);
  expectAllFail([&](Frame&, PFcompositeOptions& o) { if (g_rank == 0) o.compress = 1; }, -1,
                g_ranks > 1 ? PF_COMPOSITE_OPTIONS_MISMATCH : PF_COMPOSITE_OK, 0);
  expectAllFail([&](Frame&, PFcompositeOptions& o) { if (g_rank == culprit) o.timeout_seconds = -1; }, culprit,
                PF_COMPOSITE_BAD_OPTIONS, PF_COMPOSITE_PEER_FAILED);
}

TEST(CompositeMpi, AfterAFailureTheNextCompositeWorks) {
  compositeAndCompare({50, 30, Split::RoundRobin, false, false},
                      options(PF_COMPOSITE_AUTO, 1, PF_COMPOSITE_GATHER, 0), "after failures");
}

TEST(CompositeMpi, NullCommunicatorIsAnErrorNotACrash) {
  Frame f(8, 8);
  EXPECT_EQ(pfCompositeDepthMPI(MPI_COMM_NULL, nullptr, nullptr), PF_COMPOSITE_MPI_ERROR);
}

// A rank that never arrives: the others give up at their deadline with PF_COMPOSITE_TIMEOUT
// instead of waiting for ever. On a communicator of its own (a timed-out one must not be used
// again), and last: the late rank then calls in too and times out in its turn.
TEST(CompositeMpi, ARankThatNeverArrivesCostsTheOthersTheTimeout) {
  if (g_ranks < 2) GTEST_SKIP() << "one rank";
  MPI_Comm comm;
  MPI_Comm_dup(MPI_COMM_WORLD, &comm);
  Frame f(32, 24);
  drawShare(f, Split::RoundRobin, false);
  PFcompositeOptions o = options(PF_COMPOSITE_AUTO, 0, PF_COMPOSITE_GATHER, 0);
  o.timeout_seconds = 0.5;
  // The last rank comes only once the others have given up (the barrier on MPI_COMM_WORLD).
  const bool late = g_rank == g_ranks - 1;
  if (late) MPI_Barrier(MPI_COMM_WORLD);
  const auto t0 = std::chrono::steady_clock::now();
  const int rc = pfCompositeDepthMPI(comm, &o, nullptr);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!late) MPI_Barrier(MPI_COMM_WORLD);
  EXPECT_EQ(rc, PF_COMPOSITE_TIMEOUT) << "rank " << g_rank << ": " << pfCompositeErrorString(rc);
  EXPECT_GE(seconds, 0.45);
  EXPECT_LT(seconds, 20.0);
  // (comm is left as it is: it has abandoned requests.)
  MPI_Barrier(MPI_COMM_WORLD);
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_ranks);
  ::testing::InitGoogleTest(&argc, argv);
  // Every rank runs every test, in the same order (they are collective), and prints its results.
  const int failed = RUN_ALL_TESTS();
  int any = 0;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  if (any && g_rank == 0) std::printf("composite_mpi_test: a rank failed (%d ranks)\n", g_ranks);
  MPI_Finalize();
  return failed ? 1 : 0;
}
