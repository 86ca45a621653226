// Gang blocks (see gang_block.h).
#include "raster/gang_block.h"

namespace pf {

bool GangBlock::accepts(const Instance& inst, const uint32_t* record, const Rect& rect) const {
  if (full() || members_ == kLanes) return false;
  if (members_ == 0) return true;
  const Instance& k = *key_;
  if (inst.prim != k.prim || inst.state != k.state || inst.layout != k.layout || inst.shade_id != k.shade_id ||
      inst.shared_offset != k.shared_offset)
    return false;
  for (uint32_t slot : inst.prim->pixel.branch_slots)
    if (record[slot] != key_record_[slot]) return false;
  for (int m = 0; m < members_; ++m) {
    const Rect& r = rect_[m];
    if (rect.x0 < r.x1 && r.x0 < rect.x1 && rect.y0 < r.y1 && r.y0 < rect.y1) return false;
  }
  return true;
}

void GangBlock::join(const Instance& inst, const uint32_t* record, const Rect& rect) {
  if (members_ == 0) {
    key_ = &inst;
    key_record_ = record;
  }
  // The last member added no lane (the depth filter left out all its pixels): it has nothing
  // in the block, so the new one takes its place -- else such members would pile up past
  // kLanes.
  if (members_ > 0 && member_[members_ - 1].first_lane == lanes_) --members_;
  member_[members_] = GangMember{record, lanes_};
  rect_[members_] = rect;
  ++members_;
}

void GangBlock::run(PixelExecutor& executor, const Scene& scene, const BlockTarget& target, CoarseDepth* coarse,
                    bool keep_last) {
  if (lanes_ > 0) {
    const Instance& k = *key_;
    const RasterState& state = scene.states[k.state];
    const uint32_t* shared = k.shared_offset == kNoShared ? nullptr : scene.records.data() + k.shared_offset;
    // The last member may have no lane (the depth filter left out all its pixels): leave it
    // out, so that every member's lanes run to the next one's first.
    int n = 0;
    for (int m = 0; m < members_; ++m) {
      const int end = m + 1 < members_ ? member_[m + 1].first_lane : lanes_;
      if (end == member_[m].first_lane) continue;
      member_[n] = member_[m];
      rect_[n] = rect_[m];
      ++n;
    }
    members_ = n;
    const uint64_t committed = executor.counters.lanes_committed;
    const uint64_t mask = lanes_ == kLanes ? ~0ull : (1ull << lanes_) - 1;
    executor.runGangBlock(*k.prim, member_, members_, scene.layouts[k.layout], state, k.shade_id, pixels_, mask,
                          target, shared);
    if (coarse && state.depth_test && state.depth_write && executor.counters.lanes_committed != committed)
      for (int m = 0; m < members_; ++m)
        coarse->written(rect_[m].x0 - target.tile_x0, rect_[m].y0 - target.tile_y0, rect_[m].x1 - target.tile_x0,
                        rect_[m].y1 - target.tile_y0);
  }
  lanes_ = 0;
  if (keep_last && members_ > 0) {
    member_[0] = GangMember{member_[members_ - 1].record, 0};
    rect_[0] = rect_[members_ - 1];
    members_ = 1;
    // The key stays: the member kept matches it.
  } else {
    members_ = 0;
  }
}

}  // namespace pf
