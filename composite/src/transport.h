// The MPI side of compositing: nonblocking sends and receives of pixel bands, waited for under
// one deadline, with the bytes counted (the figures of docs/performance.md, "Compositing over
// MPI"). Everything waits with MPI_Test in a loop, never in a blocking call, so a rank that never
// arrives costs the others the timeout, not a hang. PixelFlow's network moved pixels in hardware
// (Molnar et al. 1992, seed 003 section 1); here MPI does.
#pragma once

#include <mpi.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pixel_merge.h"

namespace pf::composite {

enum class WaitResult { Done, TimedOut, Failed };

// Memory MPI may still write into after a timeout: kept for the life of the process, reachable
// (so leak checkers do not report it), never freed.
void keepAbandoned(void* memory);

// A deadline: none when timeout_seconds <= 0.
class Deadline {
 public:
  explicit Deadline(double timeout_seconds);
  bool passed() const;

 private:
  bool set_ = false;
  std::chrono::steady_clock::time_point at_;
};

// Waits for every request (MPI_Testall in a loop, yielding the core between tests). On
// TimedOut the requests stay pending, and their buffers must outlive them.
WaitResult waitAll(std::vector<MPI_Request>& requests, std::vector<MPI_Status>& statuses, const Deadline& deadline);

// Pixel traffic on one communicator, counted. A band goes as two messages (colours, depths:
// sent from the caller's buffers without a copy) or, compressed, as one message of the run-length
// code (pixel_merge.h). Tags: phase * 4 + 0 (colours), + 1 (depths), + 2 (code). Scratch comes
// from one arena reserved before any pixel moves (reserve), so running out of memory is found
// while every rank can still be told; after a timeout the arena is kept, never freed under a
// pending receive.
class Transport {
 public:
  Transport(MPI_Comm comm, bool compress, const Deadline& deadline);
  ~Transport();
  Transport(const Transport&) = delete;
  Transport& operator=(const Transport&) = delete;

  // The communicator, when it is known only after the scratch was reserved.
  void setCommunicator(MPI_Comm comm) { comm_ = comm; }
  // Scratch for receiving `receive_pixels` and sending `send_pixels` pixels in all, in at most
  // `bands` pieces each. False when it cannot be allocated.
  bool reserve(size_t receive_pixels, size_t send_pixels, size_t bands);

  // A band received into scratch: raw colour and depth planes, or a code.
  struct Inbox {
    uint32_t* color = nullptr;
    float* depth = nullptr;
    uint32_t* code = nullptr;
    size_t code_words = 0;  // received
    size_t pixels = 0;
  };

  // Raw scratch of `pixels` pixels (a direct-send accumulator); empty if the arena is short.
  PixelSpan scratch(size_t pixels);
  // Posts the send of `band` to `dest` (encoding it first when compressing).
  bool postSend(ConstPixelSpan band, int dest, int phase);
  // Posts the receive of a band of `pixels` pixels from `source` into `box`.
  bool postReceive(Inbox& box, size_t pixels, int source, int phase);
  // Posts the receive of a band straight into the caller's `band` (uncompressed only).
  bool postReceiveInto(PixelSpan band, int source, int phase);
  // Waits for everything posted. After Done, the code sizes of coded inboxes are known.
  WaitResult wait();
  // Merges a received band into dst (raw or coded). False for a malformed code.
  bool merge(PixelSpan dst, const Inbox& box, bool src_wins_ties);
  // Copies a received band into dst (raw or coded). False for a malformed code.
  bool copy(PixelSpan dst, const Inbox& box);

  uint64_t bytesSent() const { return bytes_sent_; }
  uint64_t bytesReceived() const { return bytes_received_; }
  double mergeSeconds() const { return merge_seconds_; }
  uint64_t pixelsMerged() const { return pixels_merged_; }
  bool compress() const { return compress_; }

 private:
  uint32_t* carve(size_t words);
  bool postRaw(PixelSpan band, int source, int phase, bool user_memory);

  MPI_Comm comm_;
  bool compress_;
  const Deadline& deadline_;
  uint32_t* arena_ = nullptr;
  size_t arena_words_ = 0, arena_used_ = 0;
  std::vector<MPI_Request> requests_;
  std::vector<Inbox*> coded_;      // per request: the inbox of a coded receive (its size comes with the status)
  std::vector<size_t> into_user_;  // requests receiving into the caller's buffers
  uint64_t bytes_sent_ = 0, bytes_received_ = 0, pixels_merged_ = 0;
  double merge_seconds_ = 0;
  bool abandoned_ = false;
};

}  // namespace pf::composite
