// Simplified tapes, recycled. The interval method simplifies the field's tape for every region
// it leaves undecided (thousands a frame); a fresh tape each time was a heap allocation for the
// tape, its instructions and its shared_ptr, and a third of the method's time on Prospero went to
// malloc, free and the copies. A tape that no one else holds any more -- its use count is the
// pool's alone: no region, slab or hit lane refers to it -- is rewritten in place for the next
// simplification, keeping its storage. Per ray caster, so per thread: no locking.
#pragma once

#include <memory>
#include <vector>

#include "compiler/field/field_tape.h"

namespace pf::field {

class TapePool {
 public:
  // `tape` simplified by `choices` (one entry per instruction, as IntervalEvaluator fills
  // them), or `tape` itself where nothing was decided.
  std::shared_ptr<const FieldTape> simplified(const std::shared_ptr<const FieldTape>& tape,
                                              const std::vector<Choice>& choices) {
    bool decided = false;
    for (Choice c : choices) decided = decided || c != Choice::Both;
    if (!decided) return tape;
    std::shared_ptr<FieldTape> out = take();
    simplifyInto(*tape, choices, *out, scratch_);
    return out;
  }

  size_t size() const { return tapes_.size(); }  // tapes made so far (tests)

 private:
  // A tape only the pool holds (searched round-robin from where the last one was found), or a
  // new one.
  std::shared_ptr<FieldTape> take() {
    const size_t n = tapes_.size();
    for (size_t k = 0; k < n; ++k) {
      const size_t i = (next_ + k) % n;
      if (tapes_[i].use_count() == 1) {
        next_ = i + 1;
        return tapes_[i];
      }
    }
    tapes_.push_back(std::make_shared<FieldTape>());
    next_ = 0;
    return tapes_.back();
  }

  std::vector<std::shared_ptr<FieldTape>> tapes_;
  size_t next_ = 0;
  SimplifyScratch scratch_;
};

}  // namespace pf::field
