// Which words of an instance's uniform record a pixel program reads, given the record's values
// where the program branches uniformly (PixelProgram::branch_slots): the words of the paths its
// uniform jumps take, conservatively everything else (varying ifs and loops both ways). A gang
// block (raster/gang_block.h) spreads only those words lane by lane -- its members agree on the
// branch slots -- instead of the whole record: a triangle whose vertices are all in front of the
// eye never reads its other coverage branch's planes.
#pragma once

#include <cstdint>
#include <vector>

#include "compiler/isa.h"

namespace pf {

// A run of record words [first, first + count).
struct RecordWordRun {
  uint32_t first, count;
};

// The walk's storage, kept by the caller so that a frame's walks allocate nothing.
struct RecordReadsScratch {
  std::vector<uint8_t> visited;
  std::vector<uint32_t> work;
};

// The runs of words `program`, drawn with `channels` interpolator_data channels, reads when its
// record is `record`, in increasing order.
void recordWordsRead(const PixelProgram& program, int channels, const uint32_t* record,
                     std::vector<RecordWordRun>& runs, RecordReadsScratch& scratch);

}  // namespace pf
