// Nonblocking pixel traffic under a deadline, counted (transport.h). The sends of raw bands go
// straight from the caller's colour and depth buffers; receives land in an arena the transport
// owns, so that a timeout can abandon them without MPI ever writing into freed memory.
#include "transport.h"

#include <sched.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <mutex>
#include <new>
#include <thread>

namespace pf::composite {

namespace {

constexpr int kTagsPerPhase = 4;
constexpr int kColorTag = 0, kDepthTag = 1, kCodeTag = 2;

int tag(int phase, int kind) { return phase * kTagsPerPhase + kind; }

bool fitsInt(size_t n) { return n <= static_cast<size_t>(INT_MAX); }

}  // namespace

void keepAbandoned(void* memory) {
  static std::mutex mutex;
  static std::vector<void*>* kept = new std::vector<void*>;  // never destroyed: outlives every request
  std::lock_guard<std::mutex> lock(mutex);
  kept->push_back(memory);
}

Deadline::Deadline(double timeout_seconds) {
  if (timeout_seconds > 0) {
    set_ = true;
    at_ = std::chrono::steady_clock::now() +
          std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(timeout_seconds));
  }
}

bool Deadline::passed() const { return set_ && std::chrono::steady_clock::now() >= at_; }

WaitResult waitAll(std::vector<MPI_Request>& requests, std::vector<MPI_Status>& statuses, const Deadline& deadline) {
  statuses.assign(requests.size(), MPI_Status{});
  if (requests.empty()) return WaitResult::Done;
  for (unsigned polls = 0;; ++polls) {
    int done = 0;
    if (MPI_Testall(static_cast<int>(requests.size()), requests.data(), &done, statuses.data()) != MPI_SUCCESS)
      return WaitResult::Failed;
    if (done) return WaitResult::Done;
    if (deadline.passed()) return WaitResult::TimedOut;
    // Ranks may share cores with each other and with renderer threads: give the core away,
    // and after a while sleep between tests.
    if (polls < 2000) sched_yield();
    else std::this_thread::sleep_for(std::chrono::microseconds(50));
  }
}

Transport::Transport(MPI_Comm comm, bool compress, const Deadline& deadline)
    : comm_(comm), compress_(compress), deadline_(deadline) {}

Transport::~Transport() {
  if (abandoned_) {
    // MPI may still write into the arena: keep it (the communicator is unusable anyway).
    keepAbandoned(arena_);
    // Receives into the caller's buffers are cancelled so that MPI lets go of them.
    for (size_t i : into_user_)
      if (requests_[i] != MPI_REQUEST_NULL) {
        MPI_Cancel(&requests_[i]);
        MPI_Request_free(&requests_[i]);
      }
    return;
  }
  delete[] arena_;
}

bool Transport::reserve(size_t receive_pixels, size_t send_pixels, size_t bands) {
  // Raw: 2 words a pixel; coded: maxEncodedWords per band (2 a pixel and a header or two).
  const size_t per_band = maxEncodedWords(0) + 2;
  const size_t words = 2 * (receive_pixels + (compress_ ? send_pixels : 0)) + 2 * bands * per_band;
  arena_ = new (std::nothrow) uint32_t[words];
  if (!arena_) return false;
  arena_words_ = words;
  return true;
}

uint32_t* Transport::carve(size_t words) {
  if (arena_words_ - arena_used_ < words) return nullptr;
  uint32_t* p = arena_ + arena_used_;
  arena_used_ += words;
  return p;
}

PixelSpan Transport::scratch(size_t pixels) {
  uint32_t* p = carve(2 * pixels);
  if (!p) return {nullptr, nullptr, 0};
  return {p, reinterpret_cast<float*>(p + pixels), pixels};
}

bool Transport::postSend(ConstPixelSpan band, int dest, int phase) {
  if (band.count == 0) return true;
  if (compress_) {
    uint32_t* code = carve(maxEncodedWords(band.count));
    if (!code) return false;
    const double t0 = MPI_Wtime();
    const size_t words = encodeRuns(band, code);
    arena_used_ -= maxEncodedWords(band.count) - words;  // give back what the code did not need
    merge_seconds_ += MPI_Wtime() - t0;
    if (!fitsInt(words)) return false;
    requests_.push_back(MPI_REQUEST_NULL);
    coded_.push_back(nullptr);
    bytes_sent_ += words * sizeof(uint32_t);
    return MPI_Isend(code, static_cast<int>(words), MPI_UINT32_T, dest, tag(phase, kCodeTag), comm_,
                     &requests_.back()) == MPI_SUCCESS;
  }
  if (!fitsInt(band.count)) return false;
  const int n = static_cast<int>(band.count);
  for (int kind : {kColorTag, kDepthTag}) {
    requests_.push_back(MPI_REQUEST_NULL);
    coded_.push_back(nullptr);
    const int rc = kind == kColorTag
                       ? MPI_Isend(band.color, n, MPI_UINT32_T, dest, tag(phase, kind), comm_, &requests_.back())
                       : MPI_Isend(band.depth, n, MPI_FLOAT, dest, tag(phase, kind), comm_, &requests_.back());
    if (rc != MPI_SUCCESS) return false;
  }
  bytes_sent_ += band.count * 8;
  return true;
}

bool Transport::postReceive(Inbox& box, size_t pixels, int source, int phase) {
  box.pixels = pixels;
  if (pixels == 0) return true;
  if (compress_) {
    const size_t capacity = maxEncodedWords(pixels);
    box.code = carve(capacity);
    if (!box.code || !fitsInt(capacity)) return false;
    requests_.push_back(MPI_REQUEST_NULL);
    coded_.push_back(&box);
    return MPI_Irecv(box.code, static_cast<int>(capacity), MPI_UINT32_T, source, tag(phase, kCodeTag), comm_,
                     &requests_.back()) == MPI_SUCCESS;
  }
  const PixelSpan s = scratch(pixels);
  if (!s.color) return false;
  box.color = s.color;
  box.depth = s.depth;
  return postRaw(s, source, phase, false);
}

bool Transport::postReceiveInto(PixelSpan band, int source, int phase) { return postRaw(band, source, phase, true); }

bool Transport::postRaw(PixelSpan band, int source, int phase, bool user_memory) {
  if (band.count == 0) return true;
  if (!fitsInt(band.count)) return false;
  const int n = static_cast<int>(band.count);
  for (int kind : {kColorTag, kDepthTag}) {
    if (user_memory) into_user_.push_back(requests_.size());
    requests_.push_back(MPI_REQUEST_NULL);
    coded_.push_back(nullptr);
    const int rc = kind == kColorTag
                       ? MPI_Irecv(band.color, n, MPI_UINT32_T, source, tag(phase, kind), comm_, &requests_.back())
                       : MPI_Irecv(band.depth, n, MPI_FLOAT, source, tag(phase, kind), comm_, &requests_.back());
    if (rc != MPI_SUCCESS) return false;
  }
  bytes_received_ += band.count * 8;
  return true;
}

WaitResult Transport::wait() {
  std::vector<MPI_Status> statuses;
  const WaitResult r = waitAll(requests_, statuses, deadline_);
  if (r == WaitResult::TimedOut) {
    abandoned_ = true;
    return r;
  }
  if (r == WaitResult::Done)
    for (size_t i = 0; i < coded_.size(); ++i)
      if (coded_[i]) {
        int words = 0;
        MPI_Get_count(&statuses[i], MPI_UINT32_T, &words);
        coded_[i]->code_words = words > 0 ? static_cast<size_t>(words) : 0;
        bytes_received_ += coded_[i]->code_words * sizeof(uint32_t);
      }
  requests_.clear();
  coded_.clear();
  into_user_.clear();
  return r;
}

bool Transport::merge(PixelSpan dst, const Inbox& box, bool src_wins_ties) {
  if (dst.count != box.pixels) return false;
  if (box.pixels == 0) return true;
  const double t0 = MPI_Wtime();
  bool ok = true;
  if (compress_) ok = mergeRuns(dst, box.code, box.code_words, src_wins_ties);
  else mergeByDepth(dst, {box.color, box.depth, box.pixels}, src_wins_ties);
  merge_seconds_ += MPI_Wtime() - t0;
  pixels_merged_ += box.pixels;
  return ok;
}

bool Transport::copy(PixelSpan dst, const Inbox& box) {
  if (dst.count != box.pixels) return false;
  if (box.pixels == 0) return true;
  const double t0 = MPI_Wtime();
  bool ok = true;
  if (compress_) {
    ok = decodeRuns(dst, box.code, box.code_words);
  } else {
    std::memcpy(dst.color, box.color, box.pixels * sizeof(uint32_t));
    std::memcpy(dst.depth, box.depth, box.pixels * sizeof(float));
  }
  merge_seconds_ += MPI_Wtime() - t0;
  return ok;
}

}  // namespace pf::composite
