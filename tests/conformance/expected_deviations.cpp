// The expected deviations: the only way a failing conformance case is excused. Each entry names
// a case and says why primflow differs from OSMesa there on purpose (or where GL leaves the
// result open and the two choose differently). A case listed here still runs and still shows
// its images in the report; it is reported as "expected deviation" instead of failing.
#include <cstring>

#include "conformance.h"

namespace pfconf {

namespace {

struct Deviation {
  const char* name;
  const char* reason;
};

constexpr Deviation kDeviations[] = {
    {"bitmap_fog",
     "GL 1.5 section 3.7 fogs a bitmap's fragments by the raster position's distance; OSMesa (Mesa 22's state "
     "tracker) draws glBitmap as a textured quad without a fog coordinate, so its bitmaps come out unfogged"},
};

}  // namespace

const char* expectedDeviation(const std::string& name) {
  for (const Deviation& d : kDeviations)
    if (d.name && name == d.name) return d.reason;
  return nullptr;
}

}  // namespace pfconf
