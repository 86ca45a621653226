// Test helper for per-pixel comparisons with a double-precision reference: whether the
// reference's answer changes within a small distance of a pixel centre -- a silhouette, a
// border or a fold that close, where float and double may legitimately decide differently, so
// the pixel is not judged.
#pragma once

namespace pf::test {

// Whether differs(px, py) holds at one of the four diagonal points `reach` pixels from the
// centre of pixel (x, y).
template <class Differs>
bool changesNear(int x, int y, Differs&& differs, double reach = 0.02) {
  for (int k = 0; k < 4; ++k)
    if (differs(x + 0.5 + (k % 2 ? reach : -reach), y + 0.5 + (k / 2 ? reach : -reach))) return true;
  return false;
}

}  // namespace pf::test
