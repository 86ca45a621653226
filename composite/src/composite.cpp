// pfCompositeDepthMPI (primflow/composite.h): sort-last compositing of the ranks' frames by
// depth, PixelFlow's image composition (Molnar et al. 1992, cited in seed 003 section 1) over
// MPI. The order of a call: check this rank's context and options; reserve scratch; agree with
// every rank in one MPI_Iallreduce on sizes, options and status (so a failing rank stops all of
// them before any pixel moves); exchange (schedules.cpp) on a duplicate of the communicator;
// gather; agree once more on the outcome, so all ranks return the same verdict.
#include <primflow/composite.h>

#include <cmath>
#include <cstdint>
#include <new>

#include "schedules.h"

using namespace pf::composite;

namespace {

// The status every rank contributes, reduced with MPI_MAX: minima ride along negated.
enum StatusSlot { kFailed, kWidth, kNegWidth, kHeight, kNegHeight, kRoot, kNegRoot, kResult, kNegResult,
                  kAlgorithm, kNegAlgorithm, kCompress, kNegCompress, kSlots };

bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

int fromOutcome(Outcome o) {
  switch (o) {
    case Outcome::Ok: return PF_COMPOSITE_OK;
    case Outcome::Timeout: return PF_COMPOSITE_TIMEOUT;
    case Outcome::MpiError: return PF_COMPOSITE_MPI_ERROR;
    case Outcome::BadMessage: return PF_COMPOSITE_BAD_MESSAGE;
    case Outcome::NoMemory: return PF_COMPOSITE_NO_MEMORY;
  }
  return PF_COMPOSITE_MPI_ERROR;
}

// An MPI_MAX all-reduce of `n` ints under the deadline. The buffers are heap-allocated and,
// if the deadline passes, kept for good (keepAbandoned): MPI may still write into them.
WaitResult agree(MPI_Comm comm, const int* mine, int* out, int n, const Deadline& deadline) {
  int* buffers = new int[2 * static_cast<size_t>(n)];
  for (int i = 0; i < n; ++i) buffers[i] = mine[i];
  std::vector<MPI_Request> request(1, MPI_REQUEST_NULL);
  if (MPI_Iallreduce(buffers, buffers + n, n, MPI_INT, MPI_MAX, comm, &request[0]) != MPI_SUCCESS) {
    delete[] buffers;
    return WaitResult::Failed;
  }
  std::vector<MPI_Status> statuses;
  const WaitResult r = waitAll(request, statuses, deadline);
  if (r == WaitResult::TimedOut) {
    keepAbandoned(buffers);  // MPI may still write into them
    return r;
  }
  for (int i = 0; i < n; ++i) out[i] = buffers[n + i];
  delete[] buffers;
  return r;
}

// This rank's own checks: options and context. Fills the frame when they pass.
int checkLocal(const PFcompositeOptions& o, int ranks, Frame& frame) {
  if (o.result != PF_COMPOSITE_GATHER && o.result != PF_COMPOSITE_DISTRIBUTED) return PF_COMPOSITE_BAD_OPTIONS;
  if (o.algorithm < PF_COMPOSITE_AUTO || o.algorithm > PF_COMPOSITE_DIRECT_SEND) return PF_COMPOSITE_BAD_OPTIONS;
  if (o.root < 0 || o.root >= ranks) return PF_COMPOSITE_BAD_OPTIONS;
  if (o.compress != 0 && o.compress != 1) return PF_COMPOSITE_BAD_OPTIONS;
  if (!(o.timeout_seconds >= 0) || !std::isfinite(o.timeout_seconds)) return PF_COMPOSITE_BAD_OPTIONS;
  PFcontext ctx = pfGetCurrentContext();
  if (!ctx) return PF_COMPOSITE_NO_CONTEXT;
  GLint w = 0, h = 0, format = 0, dw = 0, dh = 0, bytes = 0;
  void *color = nullptr, *depth = nullptr;
  if (!pfGetColorBuffer(ctx, &w, &h, &format, &color) || format != GL_RGBA ||
      !pfGetDepthBuffer(ctx, &dw, &dh, &bytes, &depth) || bytes != 4 || dw != w || dh != h)
    return PF_COMPOSITE_NO_CONTEXT;
  // One 32-bit word per pixel: the caller's buffer must be 4-byte aligned (malloc'd ones are).
  if (reinterpret_cast<uintptr_t>(color) % alignof(uint32_t) != 0) return PF_COMPOSITE_BAD_BUFFER;
  frame = {static_cast<uint32_t*>(color), static_cast<float*>(depth), w, h};
  return PF_COMPOSITE_OK;
}

}  // namespace

extern "C" {

void pfCompositeDefaultOptions(PFcompositeOptions* options) {
  if (!options) return;
  options->result = PF_COMPOSITE_GATHER;
  options->root = 0;
  options->algorithm = PF_COMPOSITE_AUTO;
  options->compress = 0;
  options->timeout_seconds = 0.0;
}

const char* pfCompositeErrorString(int code) {
  switch (code) {
    case PF_COMPOSITE_OK: return "no error";
    case PF_COMPOSITE_NO_CONTEXT: return "no current context with a bound colour buffer and a depth buffer";
    case PF_COMPOSITE_BAD_OPTIONS: return "bad options (root, result, algorithm, compression or timeout)";
    case PF_COMPOSITE_SIZE_MISMATCH: return "the ranks' buffers differ in size";
    case PF_COMPOSITE_OPTIONS_MISMATCH: return "the ranks passed different options";
    case PF_COMPOSITE_PEER_FAILED: return "another rank failed";
    case PF_COMPOSITE_TIMEOUT: return "timed out (the communicator must not be used again)";
    case PF_COMPOSITE_MPI_ERROR: return "MPI error (not initialised, a null communicator, or a failed call)";
    case PF_COMPOSITE_NO_MEMORY: return "out of memory for scratch buffers";
    case PF_COMPOSITE_BAD_MESSAGE: return "a compressed band did not decode";
    case PF_COMPOSITE_BAD_BUFFER: return "the colour buffer is not 4-byte aligned";
  }
  return "unknown error code";
}

int pfCompositeDepthMPI(MPI_Comm comm, const PFcompositeOptions* options, PFcompositeStats* stats) {
  PFcompositeStats local_stats{};
  PFcompositeStats& st = stats ? *stats : local_stats;
  st = PFcompositeStats{};
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (!initialized || finalized || comm == MPI_COMM_NULL) return PF_COMPOSITE_MPI_ERROR;
  int inter = 0, ranks = 0, rank = 0;
  if (MPI_Comm_test_inter(comm, &inter) != MPI_SUCCESS || inter || MPI_Comm_size(comm, &ranks) != MPI_SUCCESS ||
      MPI_Comm_rank(comm, &rank) != MPI_SUCCESS)
    return PF_COMPOSITE_MPI_ERROR;
  const double t0 = MPI_Wtime();
  PFcompositeOptions o;
  pfCompositeDefaultOptions(&o);
  if (options) o = *options;
  st.ranks = ranks;

  Frame frame{nullptr, nullptr, 0, 0};
  int local = checkLocal(o, ranks, frame);
  // (A rank whose options are bad still keeps a valid timeout while it tells the others.)
  const bool timeout_ok = o.timeout_seconds >= 0 && std::isfinite(o.timeout_seconds);
  const Deadline deadline(timeout_ok ? o.timeout_seconds : 0.0);
  const int algorithm = o.algorithm != PF_COMPOSITE_AUTO ? o.algorithm
                        : isPowerOfTwo(ranks)          ? PF_COMPOSITE_BINARY_SWAP
                                                       : PF_COMPOSITE_DIRECT_SEND;
  const BinarySwap swap(ranks, frame.height);
  const DirectSend direct(ranks, frame.height);
  auto band_of = [&](int r) { return algorithm == PF_COMPOSITE_BINARY_SWAP ? swap.finalBand(r) : direct.finalBand(r); };

  // Scratch before anyone moves a pixel: running short here is a status every rank hears of.
  Transport* transport = nullptr;
  const size_t pixels = static_cast<size_t>(frame.width) * static_cast<size_t>(frame.height);
  if (local == PF_COMPOSITE_OK && ranks > 1) {
    const bool gather_root = o.result == PF_COMPOSITE_GATHER && rank == o.root;
    size_t receive = algorithm == PF_COMPOSITE_BINARY_SWAP ? swap.receivePixels(rank, pixels)
                                                           : direct.receivePixels(rank, pixels);
    if (gather_root && o.compress) receive += pixels;
    const size_t send = algorithm == PF_COMPOSITE_BINARY_SWAP ? swap.sendPixels(rank, pixels)
                                                              : direct.sendPixels(rank, pixels);
    transport = new (std::nothrow) Transport(MPI_COMM_NULL, o.compress == 1, deadline);
    if (!transport || !transport->reserve(receive, send, 2 * static_cast<size_t>(ranks) + 70)) {
      local = PF_COMPOSITE_NO_MEMORY;
      delete transport;
      transport = nullptr;
    }
  }

  // One all-reduce: everyone's status, sizes and options.
  const int flag = local != PF_COMPOSITE_OK;
  const int mine[kSlots] = {flag,        frame.width,  -frame.width,  frame.height, -frame.height,
                            o.root,      -o.root,      o.result,      -o.result,    o.algorithm,
                            -o.algorithm, o.compress,  -o.compress};
  int all[kSlots];
  const WaitResult agreed = agree(comm, mine, all, kSlots, deadline);
  if (agreed != WaitResult::Done) {
    delete transport;
    st.seconds = MPI_Wtime() - t0;
    return agreed == WaitResult::TimedOut ? PF_COMPOSITE_TIMEOUT : PF_COMPOSITE_MPI_ERROR;
  }
  int verdict = PF_COMPOSITE_OK;
  if (all[kFailed]) verdict = local != PF_COMPOSITE_OK ? local : PF_COMPOSITE_PEER_FAILED;
  else if (all[kWidth] != -all[kNegWidth] || all[kHeight] != -all[kNegHeight]) verdict = PF_COMPOSITE_SIZE_MISMATCH;
  else if (all[kRoot] != -all[kNegRoot] || all[kResult] != -all[kNegResult] || all[kAlgorithm] != -all[kNegAlgorithm] ||
           all[kCompress] != -all[kNegCompress])
    verdict = PF_COMPOSITE_OPTIONS_MISMATCH;
  st.algorithm = algorithm;
  if (verdict != PF_COMPOSITE_OK || ranks == 1) {
    delete transport;
    if (verdict == PF_COMPOSITE_OK) st.row_count = frame.height;
    st.seconds = MPI_Wtime() - t0;
    return verdict;
  }

  // Pixels move on a communicator of their own, so they never meet the application's messages.
  MPI_Comm work = MPI_COMM_NULL;
  {
    std::vector<MPI_Request> request(1, MPI_REQUEST_NULL);
    std::vector<MPI_Status> statuses;
    const WaitResult r = MPI_Comm_idup(comm, &work, &request[0]) == MPI_SUCCESS
                             ? waitAll(request, statuses, deadline) : WaitResult::Failed;
    if (r != WaitResult::Done) {
      delete transport;  // nothing was posted on it
      st.seconds = MPI_Wtime() - t0;
      return r == WaitResult::TimedOut ? PF_COMPOSITE_TIMEOUT : PF_COMPOSITE_MPI_ERROR;
    }
  }
  MPI_Comm_set_errhandler(work, MPI_ERRORS_RETURN);
  Transport& t = *transport;
  t.setCommunicator(work);
  Outcome outcome = algorithm == PF_COMPOSITE_BINARY_SWAP ? swap.run(t, frame, rank) : direct.run(t, frame, rank);
  if (outcome == Outcome::Ok && o.result == PF_COMPOSITE_GATHER)
    outcome = gatherBands(t, frame, rank, ranks, o.root, band_of);
  local = fromOutcome(outcome);

  // The outcome, agreed: a rank that failed during the exchange fails every rank.
  if (outcome != Outcome::Timeout) {
    const int failed = local != PF_COMPOSITE_OK;
    int any = 0;
    const WaitResult r = agree(work, &failed, &any, 1, deadline);
    if (r == WaitResult::TimedOut) outcome = Outcome::Timeout, local = PF_COMPOSITE_TIMEOUT;
    else if (r != WaitResult::Done) local = PF_COMPOSITE_MPI_ERROR;
    else if (any && local == PF_COMPOSITE_OK) local = PF_COMPOSITE_PEER_FAILED;
  }
  st.bytes_sent = t.bytesSent();
  st.bytes_received = t.bytesReceived();
  st.pixels_merged = t.pixelsMerged();
  st.merge_seconds = t.mergeSeconds();
  const Band mine_band = o.result == PF_COMPOSITE_GATHER ? (rank == o.root ? Band{0, frame.height} : Band{})
                                                         : band_of(rank);
  st.first_row = mine_band.first_row;
  st.row_count = mine_band.row_count;
  delete transport;  // after a timeout it keeps its scratch, which MPI may still write into
  if (outcome != Outcome::Timeout) MPI_Comm_free(&work);  // (after one, leaked with its requests)
  st.seconds = MPI_Wtime() - t0;
  return local;
}

}  // extern "C"
