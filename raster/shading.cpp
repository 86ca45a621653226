// The shading pass (see shading.h).
//
// A tile is shaded row by row: a row with one shading state as one span from its first shaded
// pixel to its last (the gaps computed and not written), a row with several in runs of pixels
// with the same state. A lit span goes through LightingEquation::shadeRun with each quantity one
// array per component -- the G-buffer's planes are already laid out that way -- so that the
// equation's loops vectorize.
#include "raster/shading.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>

#include "raster/limits.h"

namespace pf {
namespace {

static_assert(LitPoints::kMax >= kTileSize, "a run is at most a tile's row");

// Runs are lit in whole groups of this many pixels: AVX-512's floats per vector.
constexpr int kLaneGroup = 16;
static_assert(kTileSize % kLaneGroup == 0, "a row is whole groups");

// The colour of `n` pixels from plane index i0 of the G-buffer under shading state `s`
// (the colour parameter, or the state's constant colour), into c[component][pixel].
void runColour(const ShadeState& s, const float* const* slots, size_t i0, int n, float c[4][kTileSize]) {
  for (int k = 0; k < 4; ++k) {
    if (s.color_slot >= 0) {
      const float* plane = slots[s.color_slot + k] + i0;
      for (int i = 0; i < n; ++i) c[k][i] = plane[i];
    } else {
      for (int i = 0; i < n; ++i) c[k][i] = s.constant_color[k];
    }
  }
}

// GL's lighting at the run's pixels from the G-buffer's P and N: the normal normalised (as
// glm::normalize: n * (1 / sqrt(dot(n, n))), where its length is not zero), the back face's
// material and reversed normal where two-sided lighting shows the back, the tracked material
// properties taking the pixel's colour. `c` is the colour on entry, the lit colour on return.
PF_SIMD_CLONES void lightRun(const ShadeState& s, const LightingState& l, const LightingEquation& eq, const float* const* slots,
              size_t i0, int n, float c[4][kTileSize]) {
  alignas(64) float normal[3][kTileSize], material[4][4][kTileSize], shininess[kTileSize];
  alignas(64) int32_t face[kTileSize];  // 1: the back face shows (int, as wide as the floats it selects)
  const float* p[3];
  for (int k = 0; k < 3; ++k) p[k] = slots[s.surface_slot + k] + i0;
  const float* const nx = slots[s.surface_slot + 3] + i0;
  const float* const ny = slots[s.surface_slot + 4] + i0;
  const float* const nz = slots[s.surface_slot + 5] + i0;
  for (int i = 0; i < n; ++i) {
    // (Every product computed, then chosen: an operation in one arm of a select is one the
    // compiler may not run for every lane -- it could raise a floating-point exception -- and
    // the loop would not vectorize.)
    const float x = nx[i], y = ny[i], z = nz[i];
    const float len = std::sqrt(x * x + y * y + z * z);
    const float inv = 1.0f / len;
    const bool unit = len > 0.0f;
    const float ux = x * inv, uy = y * inv, uz = z * inv;
    normal[0][i] = unit ? ux : x;
    normal[1][i] = unit ? uy : y;
    normal[2][i] = unit ? uz : z;
  }
  // Two-sided lighting: a normal facing away from the eye (dot(n, -p) < 0) shows the back face.
  // (Without it P is not read: the lighting may not need it, and then it was not written --
  // ChannelLayout::surface_eye.)
  int any_back = 0;
  if (l.two_side) {
    for (int i = 0; i < n; ++i) {
      const float d = normal[0][i] * -p[0][i] + normal[1][i] * -p[1][i] + normal[2][i] * -p[2][i];
      face[i] = d < 0.0f ? 1 : 0;
      any_back |= face[i];
    }
  } else {
    for (int i = 0; i < n; ++i) face[i] = 0;
  }
  if (any_back)
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < n; ++i) normal[k][i] = face[i] ? -normal[k][i] : normal[k][i];
  // The material of each pixel's face (trackedMaterial, property by property): `props[q][k]`
  // is component k of property q at the run's pixels -- the face's own material (one value
  // where no pixel shows its back), or the pixel's colour where GL_COLOR_MATERIAL tracks the
  // property on that face (then, on both faces, the colour itself, not a copy).
  enum { kAmbient, kDiffuse, kSpecular, kEmission };
  int tracked[2] = {-1, -1};
  const bool front_tracks = l.color_material_face != GL_BACK, back_tracks = l.color_material_face != GL_FRONT;
  if (l.color_material) {
    tracked[0] = kAmbient, tracked[1] = kDiffuse;  // GL_AMBIENT_AND_DIFFUSE (and trackedMaterial's default)
    switch (l.color_material_mode) {
      case GL_AMBIENT: tracked[1] = -1; break;
      case GL_DIFFUSE: tracked[0] = -1; break;
      case GL_SPECULAR: tracked[0] = kSpecular, tracked[1] = -1; break;
      case GL_EMISSION: tracked[0] = kEmission, tracked[1] = -1; break;
      default: break;
    }
  }
  const float* props[4][4];
  for (int q = 0; q < 4; ++q) {
    const bool follows_colour = (q == tracked[0] || q == tracked[1]) && front_tracks && back_tracks;
    const glm::vec4& front = q == kAmbient ? l.material[0].ambient : q == kDiffuse ? l.material[0].diffuse
                           : q == kSpecular ? l.material[0].specular : l.material[0].emission;
    const glm::vec4& back = q == kAmbient ? l.material[1].ambient : q == kDiffuse ? l.material[1].diffuse
                          : q == kSpecular ? l.material[1].specular : l.material[1].emission;
    for (int k = 0; k < 4; ++k) {
      if (follows_colour) {
        props[q][k] = c[k];
        continue;
      }
      const float f = front[k], b = back[k];
      float* const m = material[q][k];
      if (any_back)
        for (int i = 0; i < n; ++i) m[i] = face[i] ? b : f;
      else
        for (int i = 0; i < n; ++i) m[i] = f;
      props[q][k] = m;
    }
  }
  const float front_shininess = l.material[0].shininess, back_shininess = l.material[1].shininess;
  for (int i = 0; i < n; ++i) shininess[i] = face[i] ? back_shininess : front_shininess;
  // A property tracked on one face only: the colour where that face shows, the material elsewhere.
  if (front_tracks != back_tracks)
    for (int t : tracked) {
      if (t < 0) continue;
      const int32_t tracking_face = back_tracks ? 1 : 0;
      for (int k = 0; k < 4; ++k) {
        const float* const colour = c[k];
        float* const m = material[t][k];
        for (int i = 0; i < n; ++i) {
          const float a = colour[i], b = m[i];
          m[i] = face[i] == tracking_face ? a : b;
        }
      }
    }
  LitPoints in;
  in.n = n;
  for (int k = 0; k < 3; ++k) {
    in.eye[k] = p[k];
    in.normal[k] = normal[k];
  }
  for (int k = 0; k < 4; ++k) {
    in.ambient[k] = props[kAmbient][k];
    in.diffuse[k] = props[kDiffuse][k];
    in.specular[k] = props[kSpecular][k];
    in.emission[k] = props[kEmission][k];
  }
  in.shininess = shininess;
  float* const out[4] = {c[0], c[1], c[2], c[3]};
  eq.shadeRun(in, out);
}

// What shading a tile reads besides its ids: the G-buffer and the frame's lighting states.
struct TileShading {
  const uint32_t* shade_ids;  // the whole tile's (a textured pixel's neighbours)
  const float* const* slots;
  const ShadeState* shades;
  const LightingState* lightings;
  const LightingEquation* equations;
};

// Pixels [x, end) of tile row y, with one shading state `id`: all of them (a run), or -- `holes`,
// a row whose pixels all have that state or none -- those with that id, the gaps computed and not
// written.
struct RowSpan {
  int y, x, end;
  uint32_t id;
  bool holes;
};

// Shades a span of the row whose ids are `ids`; returns the pixels shaded. (Inlined into each
// of shadeTile's clones.)
[[gnu::always_inline]] inline uint64_t shadeSpan(const TileShading& in, const ShadeTarget& t, const uint32_t* ids,
                                                 const RowSpan& r, float c[4][kTileSize]) {
  const int y = r.y, x = r.x, end = r.end;
  const bool holes = r.holes;
  const int n = end - x;
  // The colour and the lighting run over the span widened to whole groups of kLaneGroup pixels
  // of the row (the G-buffer's rows are kTileSize wide whatever the tile's width), so that their
  // loops have no scalar remainder; the pixels widened over are computed -- lane by lane, without
  // effect on the others -- and not written.
  const int first = x & ~(kLaneGroup - 1);
  const int span = std::min((end + kLaneGroup - 1) & ~(kLaneGroup - 1), kTileSize) - first;
  const int skip = x - first;
  const size_t i0 = static_cast<size_t>(y) * kTileSize + static_cast<size_t>(first);
  const ShadeState& s = in.shades[r.id - 1];
  runColour(s, in.slots, i0, span, c);
  if (s.lighting >= 0) lightRun(s, in.lightings[s.lighting], in.equations[s.lighting], in.slots, i0, span, c);
  if (s.texture) {
    TextureSpan ts;
    for (int k = 0; k < 4; ++k) ts.coord[k] = in.slots[s.texcoord_slot + k];
    ts.ids = in.shade_ids;
    ts.tile_w = t.w;
    ts.tile_h = t.h;
    ts.y = y;
    ts.x = x;
    ts.n = n;
    ts.id = r.id;
    textureSpan(*s.texture, ts, c, skip);
  }
  if (s.fog_slot >= 0) fogRun(s.fog, in.slots[s.fog_slot] + i0, c, span);
  uint8_t* px = t.color + (static_cast<size_t>(t.y0 + y) * t.stride + t.x0 + x) * 4;
  const uint32_t* const span_ids = ids + x;
  uint64_t shaded = static_cast<uint64_t>(n);
  if (holes) {
    shaded = 0;
    for (int i = 0; i < n; ++i) shaded += span_ids[i] != 0 ? 1u : 0u;
  }
  if (t.fragments) {
    writeFragments(*t.fragments, t.color_mask, c, skip, n, span_ids, px,
                   t.discarded + static_cast<size_t>(y) * kTileSize + x);
  } else if (t.color_mask == 0xf) {
    // toUnorm8 without a branch, a plane at a time, so that the loops vectorize (the same bytes);
    // then the four planes interleaved into RGBA words (byte 0 red: little-endian), a gap's pixel
    // keeping the word it has.
    alignas(64) uint32_t q[4][kTileSize];
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < n; ++i) {
        const float v = c[k][skip + i];
        const float clamped = v > 0.0f ? v : 0.0f;  // NaN too: 0
        const float rounded = clamped * 255.0f + 0.5f;
        const float scaled = clamped >= 1.0f ? 255.0f : rounded;
        q[k][i] = static_cast<uint32_t>(static_cast<int>(scaled));
      }
    if constexpr (std::endian::native == std::endian::little) {
      if (holes) {
        for (int i = 0; i < n; ++i) {
          uint32_t word = q[0][i] | q[1][i] << 8 | q[2][i] << 16 | q[3][i] << 24, old;
          std::memcpy(&old, px + 4 * i, sizeof old);
          word = span_ids[i] != 0 ? word : old;
          std::memcpy(px + 4 * i, &word, sizeof word);
        }
      } else {
        for (int i = 0; i < n; ++i) {
          const uint32_t word = q[0][i] | q[1][i] << 8 | q[2][i] << 16 | q[3][i] << 24;
          std::memcpy(px + 4 * i, &word, sizeof word);
        }
      }
    } else {
      for (int i = 0; i < n; ++i)
        if (span_ids[i] != 0)
          for (int k = 0; k < 4; ++k) px[4 * i + k] = static_cast<uint8_t>(q[k][i]);
    }
  } else {
    for (int i = 0; i < n; ++i)
      if (span_ids[i] != 0)
        for (int k = 0; k < 4; ++k)
          if (t.color_mask & (1u << k)) px[4 * i + k] = toUnorm8(c[k][skip + i]);
  }
  return shaded;
}

}  // namespace

PF_SIMD_CLONES uint64_t shadeTile(const uint32_t* shade_ids, const float* const* slots, const ShadeState* shades,
                   const LightingState* lightings, const LightingEquation* equations, const ShadeTarget& t) {
  const TileShading in{shade_ids, slots, shades, lightings, equations};
  uint64_t shaded = 0;
  alignas(64) float c[4][kTileSize];
  const int row_end = t.row_end < 0 ? t.h : t.row_end;
  for (int y = t.row_begin; y < row_end; ++y) {
    const uint32_t* const ids = shade_ids + static_cast<size_t>(y) * kTileSize;
    // Most rows of most tiles are empty, or hold one shading state (a mesh's triangles, the
    // spheres of one glBegin): an empty row is found with one vectorized pass, and a row with
    // one state is shaded as one span from its first shaded pixel to its last, gaps and all --
    // small primitives leave many short runs, and a run costs far more than a pixel.
    uint32_t any = 0;
    for (int x = 0; x < t.w; ++x) any |= ids[x];
    if (any == 0) continue;
    int x0 = 0, x1 = t.w;
    while (ids[x0] == 0) ++x0;
    while (ids[x1 - 1] == 0) --x1;
    const uint32_t first_id = ids[x0];
    uint32_t mixed = 0;
    for (int x = x0; x < x1; ++x) mixed |= ids[x] != 0 ? ids[x] ^ first_id : 0u;
    if (mixed == 0) {
      shaded += shadeSpan(in, t, ids, RowSpan{y, x0, x1, first_id, true}, c);
      continue;
    }
    // Several states: run by run.
    for (int x = x0; x < x1;) {
      while (x < x1 && ids[x] == 0) ++x;
      if (x == x1) break;
      const uint32_t id = ids[x];
      int end = x + 1;
      for (; end + 8 <= x1; end += 8) {  // eight at a time while all eight belong to the run
        uint32_t differ = 0;
        for (int j = 0; j < 8; ++j) differ |= ids[end + j] ^ id;
        if (differ != 0) break;
      }
      while (end < x1 && ids[end] == id) ++end;
      shaded += shadeSpan(in, t, ids, RowSpan{y, x, end, id, false}, c);
      x = end;
    }
  }
  return shaded;
}

}  // namespace pf
