// The exchange patterns of sort-last compositing (IceT's binary-swap and direct-send), over a
// Transport: which rank sends which rows to whom, and in which order the received bands are
// merged so that every pixel ends as the nearest over all ranks, equal depths going to the
// lower rank -- whatever the pattern (PixelFlow's composition by depth, Molnar et al. 1992 as
// cited in seed 003 section 1, done as a reduction over MPI).
#pragma once

#include <cstddef>
#include <functional>

#include "transport.h"

namespace pf::composite {

// The caller's frame: width x height pixels, row 0 at the bottom, rows contiguous.
struct Frame {
  uint32_t* color;
  float* depth;
  int width, height;

  PixelSpan rows(int first, int count) const {
    const size_t at = static_cast<size_t>(first) * width;
    return {color + at, depth + at, static_cast<size_t>(count) * width};
  }
};

struct Band {
  int first_row = 0, row_count = 0;
};

enum class Outcome { Ok, Timeout, MpiError, BadMessage, NoMemory };

// Binary-swap over p ranks: a rank count that is not a power of two is first folded to the
// largest power of two below it (ranks 2j+1 < 2m send their frame to 2j, m = p - 2^k), so that
// every group stays a contiguous range of ranks and the lower group wins ties.
class BinarySwap {
 public:
  BinarySwap(int ranks, int height);
  // The rows rank r holds at the end (empty for a folded-away rank).
  Band finalBand(int rank) const;
  // Upper bounds of the pixels this rank receives and sends, and of the bands.
  size_t receivePixels(int rank, size_t frame_pixels) const;
  size_t sendPixels(int rank, size_t frame_pixels) const;
  int rounds() const { return rounds_; }
  Outcome run(Transport& t, const Frame& f, int rank) const;

 private:
  int activeIndex(int rank) const;  // -1: folded away
  int rankOfActive(int v) const;
  int height_, rounds_ = 0, extra_ = 0;
};

// Direct-send: band j is rows [j*H/p, (j+1)*H/p); every rank sends band j to rank j in one round,
// and rank j merges what it got in rank order.
class DirectSend {
 public:
  DirectSend(int ranks, int height) : ranks_(ranks), height_(height) {}
  Band finalBand(int rank) const;
  size_t receivePixels(int rank, size_t frame_pixels) const;
  size_t sendPixels(int rank, size_t frame_pixels) const;
  Outcome run(Transport& t, const Frame& f, int rank) const;

 private:
  int ranks_, height_;
};

// Gathers every rank's final band (band_of(rank)) into the root's frame.
Outcome gatherBands(Transport& t, const Frame& f, int rank, int ranks, int root, const std::function<Band(int)>& band_of);

}  // namespace pf::composite
