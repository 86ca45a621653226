// Gang blocks: the pixels of several small instances packed into one block. A sphere 6 pixels
// across is about 30 pixels; on packed lanes of its own (PixelExecutor::runPackedBlock) it still
// runs a whole 64-lane block, and with 100k of them half the lanes of a frame started empty.
// Consecutive instances of a tile's bin that share primitive, state, channel layout, shade and
// shared interpolators fill one block together (PixelExecutor::runGangBlock: each lane reads
// its own instance's uniforms), as long as none of them shares a pixel with another in the
// block -- lanes of one block test and write the depth buffer at once, so two lanes of one
// pixel would not see each other. Blocks still run in bin order: any instance that does not
// join runs only after the block being filled, so every pixel sees its instances in order and
// the image is the same to the bit as one instance at a time (raster_packed_lanes_test.cpp).
#pragma once

#include <cstdint>

#include "raster/coarse_depth.h"
#include "raster/pixel_executor.h"
#include "raster/scene.h"

namespace pf {

class GangBlock {
 public:
  // A pixel rectangle [x0, x1) x [y0, y1).
  struct Rect {
    int x0, y0, x1, y1;
  };

  bool empty() const { return members_ == 0; }
  bool full() const { return lanes_ == kLanes; }
  // Whether `inst` (its record; its pixels `rect` within the tile) may join the block: not full,
  // the same primitive, state, layout, shade and shared records as its members, the same values
  // in the slots its program branches on, and no pixel of theirs in its rectangle.
  bool accepts(const Instance& inst, const uint32_t* record, const Rect& rect) const;
  // Makes `inst` the member whose pixels add() adds (accepts() said yes, or the block is empty).
  void join(const Instance& inst, const uint32_t* record, const Rect& rect);
  // Adds pixel (x, y) of the last member (the block is not full).
  void add(int x, int y) {
    pixels_.x[lanes_] = x;
    pixels_.y[lanes_] = y;
    ++lanes_;
  }
  // Runs the block's lanes and empties it. `keep_last`: the last member goes on in the next
  // block (its pixels did not all fit). Depths written mark `coarse`'s blocks (the tile at
  // (tile_x0, tile_y0)) for measuring again.
  void run(PixelExecutor& executor, const Scene& scene, const BlockTarget& target, CoarseDepth* coarse,
           bool keep_last);
  // Forgets everything (a tile that failed part-way leaves no members behind).
  void clear() {
    members_ = 0;
    lanes_ = 0;
  }

 private:
  const Instance* key_ = nullptr;        // the first member (the others match it)
  const uint32_t* key_record_ = nullptr;
  GangMember member_[kLanes];
  Rect rect_[kLanes];
  int members_ = 0;
  int lanes_ = 0;
  PackedLanes pixels_;
};

}  // namespace pf
