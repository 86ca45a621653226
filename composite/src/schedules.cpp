// Binary-swap, direct-send and the final gather (schedules.h). Ties: a band merged from a group
// of lower ranks wins equal depths (src_wins_ties), one from higher ranks loses them, so each
// pixel ends as the minimum of (depth, rank) -- an order the reduction tree cannot change.
#include "schedules.h"

#include <cstdint>

namespace pf::composite {

namespace {

constexpr int kFoldPhase = 1, kSwapPhase = 2, kDirectPhase = 64, kGatherPhase = 65;

Outcome waited(Transport& t) {
  switch (t.wait()) {
    case WaitResult::Done: return Outcome::Ok;
    case WaitResult::TimedOut: return Outcome::Timeout;
    case WaitResult::Failed: break;
  }
  return Outcome::MpiError;
}

int rowAt(int64_t j, int64_t height, int64_t ranks) { return static_cast<int>(j * height / ranks); }

ConstPixelSpan constant(PixelSpan s) { return {s.color, s.depth, s.count}; }

}  // namespace

// --- binary-swap ---------------------------------------------------------------------------------

BinarySwap::BinarySwap(int ranks, int height) : height_(height) {
  while ((2 << rounds_) <= ranks) ++rounds_;
  extra_ = ranks - (1 << rounds_);
}

int BinarySwap::activeIndex(int rank) const {
  if (rank < 2 * extra_) return rank % 2 == 0 ? rank / 2 : -1;
  return rank - extra_;
}

int BinarySwap::rankOfActive(int v) const { return v < extra_ ? 2 * v : v + extra_; }

Band BinarySwap::finalBand(int rank) const {
  const int v = activeIndex(rank);
  if (v < 0) return {};
  int a = 0, b = height_;
  for (int i = 0; i < rounds_; ++i) {
    const int mid = a + (b - a) / 2;
    if (v & (1 << i)) a = mid;
    else b = mid;
  }
  return {a, b - a};
}

size_t BinarySwap::receivePixels(int rank, size_t frame_pixels) const {
  const bool fold_receiver = rank < 2 * extra_ && rank % 2 == 0;
  return (fold_receiver ? frame_pixels : 0) + frame_pixels;
}

size_t BinarySwap::sendPixels(int rank, size_t frame_pixels) const {
  const bool fold_sender = rank < 2 * extra_ && rank % 2 == 1;
  return fold_sender ? frame_pixels : 2 * frame_pixels;  // the rounds' halves, then the gather
}

Outcome BinarySwap::run(Transport& t, const Frame& f, int rank) const {
  const PixelSpan whole = f.rows(0, f.height);
  // The fold: rank 2j+1 (higher) gives its whole frame to 2j, which keeps its own pixels on ties.
  if (rank < 2 * extra_) {
    if (rank % 2 == 1) {
      if (!t.postSend(constant(whole), rank - 1, kFoldPhase)) return Outcome::MpiError;
      return waited(t);
    }
    Transport::Inbox box;
    if (!t.postReceive(box, whole.count, rank + 1, kFoldPhase)) return Outcome::NoMemory;
    if (Outcome o = waited(t); o != Outcome::Ok) return o;
    if (!t.merge(whole, box, false)) return Outcome::BadMessage;
  }
  const int v = activeIndex(rank);
  int a = 0, b = height_;
  for (int i = 0; i < rounds_; ++i) {
    const int bit = 1 << i, partner_v = v ^ bit, partner = rankOfActive(partner_v);
    const int mid = a + (b - a) / 2;
    const bool upper = (v & bit) != 0;
    const int keep_a = upper ? mid : a, keep_b = upper ? b : mid;
    const int give_a = upper ? a : mid, give_b = upper ? mid : b;
    const PixelSpan keep = f.rows(keep_a, keep_b - keep_a);
    Transport::Inbox box;
    if (!t.postReceive(box, keep.count, partner, kSwapPhase + i)) return Outcome::NoMemory;
    if (!t.postSend(constant(f.rows(give_a, give_b - give_a)), partner, kSwapPhase + i)) return Outcome::MpiError;
    if (Outcome o = waited(t); o != Outcome::Ok) return o;
    // The partner's group is lower exactly when this rank is the upper one of the pair.
    if (!t.merge(keep, box, upper)) return Outcome::BadMessage;
    a = keep_a;
    b = keep_b;
  }
  return Outcome::Ok;
}

// --- direct-send ---------------------------------------------------------------------------------

Band DirectSend::finalBand(int rank) const {
  const int a = rowAt(rank, height_, ranks_), b = rowAt(rank + 1, height_, ranks_);
  return {a, b - a};
}

size_t DirectSend::receivePixels(int, size_t frame_pixels) const { return 2 * frame_pixels; }

size_t DirectSend::sendPixels(int, size_t frame_pixels) const { return 2 * frame_pixels; }

Outcome DirectSend::run(Transport& t, const Frame& f, int rank) const {
  const Band mine = finalBand(rank);
  const PixelSpan own = f.rows(mine.first_row, mine.row_count);
  std::vector<Transport::Inbox> boxes(static_cast<size_t>(ranks_));
  for (int s = 0; s < ranks_; ++s)
    if (s != rank && !t.postReceive(boxes[static_cast<size_t>(s)], own.count, s, kDirectPhase))
      return Outcome::NoMemory;
  for (int j = 0; j < ranks_; ++j) {
    if (j == rank) continue;
    const Band band = finalBand(j);
    if (!t.postSend(constant(f.rows(band.first_row, band.row_count)), j, kDirectPhase)) return Outcome::MpiError;
  }
  if (Outcome o = waited(t); o != Outcome::Ok) return o;
  // Lower ranks first, into an accumulator (each later one loses ties to it), which then wins
  // ties against this rank's own pixels; higher ranks lose ties to the result.
  if (rank > 0 && own.count > 0) {
    const PixelSpan lower = t.scratch(own.count);
    if (!lower.color) return Outcome::NoMemory;
    if (!t.copy(lower, boxes[0])) return Outcome::BadMessage;
    for (int s = 1; s < rank; ++s)
      if (!t.merge(lower, boxes[static_cast<size_t>(s)], false)) return Outcome::BadMessage;
    mergeByDepth(own, constant(lower), true);
  }
  for (int s = rank + 1; s < ranks_; ++s)
    if (!t.merge(own, boxes[static_cast<size_t>(s)], false)) return Outcome::BadMessage;
  return Outcome::Ok;
}

// --- gather --------------------------------------------------------------------------------------

Outcome gatherBands(Transport& t, const Frame& f, int rank, int ranks, int root,
                    const std::function<Band(int)>& band_of) {
  if (rank != root) {
    const Band b = band_of(rank);
    if (!t.postSend(constant(f.rows(b.first_row, b.row_count)), root, kGatherPhase)) return Outcome::MpiError;
    return waited(t);
  }
  std::vector<Transport::Inbox> boxes(static_cast<size_t>(ranks));
  for (int s = 0; s < ranks; ++s) {
    if (s == root) continue;
    const Band b = band_of(s);
    const PixelSpan dst = f.rows(b.first_row, b.row_count);
    const bool ok = t.compress() ? t.postReceive(boxes[static_cast<size_t>(s)], dst.count, s, kGatherPhase)
                                 : t.postReceiveInto(dst, s, kGatherPhase);
    if (!ok) return Outcome::NoMemory;
  }
  if (Outcome o = waited(t); o != Outcome::Ok) return o;
  if (t.compress())
    for (int s = 0; s < ranks; ++s) {
      if (s == root) continue;
      const Band b = band_of(s);
      if (!t.copy(f.rows(b.first_row, b.row_count), boxes[static_cast<size_t>(s)])) return Outcome::BadMessage;
    }
  return Outcome::Ok;
}

}  // namespace pf::composite
