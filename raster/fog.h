// GL fog (GL 1.5 section 3.10) as the shading pass applies it: after texturing, before the
// fragment operations, from a fog coordinate the primitive interpolated into the G-buffer
// (|z| in eye coordinates at each sequence point, interpolated perspective-correctly, as
// Mesa's fixed-function vertex program computes and llvmpipe interpolates it) -- or, for a
// primitive that sets its surface point P and normal N (a sphere, a quadric, an implicit
// surface), |P.z| of each pixel's own surface point: the eye distance GL's formula measures,
// exact where tessellation would interpolate it. The factor is
// computed per pixel whatever GL_FOG_HINT says, as llvmpipe does, with Mesa's constants
// (STATE_FOG_PARAMS_OPTIMIZED): linear f = z * scale + offset, exp f = 2^-(d / ln 2 * z),
// exp2 f = 2^-((d / sqrt(ln 2) * z)^2), clamped to [0, 1]; then rgb = f * rgb + (1 - f) * fog
// colour, alpha unchanged.
#pragma once

#include <cstdint>

#include "raster/limits.h"

namespace pf {

enum class FogMode : uint8_t { Linear, Exp, Exp2 };

struct FogParams {
  bool on = false;
  FogMode mode = FogMode::Exp;
  // Linear: f = z * scale + offset (scale -1 / (end - start), offset end / (end - start); Mesa's
  // scale 1 and offset -end when end == start). Exp: scale d / ln 2. Exp2: scale d / sqrt(ln 2).
  float scale = 0.0f, offset = 0.0f;
  float color[3] = {0, 0, 0};  // in [0, 1]

  bool operator==(const FogParams&) const = default;
};

// The fog factor of fog coordinate z.
float fogFactor(const FogParams& fog, float z);

// Fogs n colours c[k][i] (i < n) by the fog coordinates |coord[i]| -- a fog coordinate channel's
// non-negative values, or the z of a surface's eye-space point P, negative in front of the eye --:
// each colour component
// clamped to [0, 1] first (GL's clamped fragment colour), rgb blended towards the fog colour.
void fogRun(const FogParams& fog, const float* coord, float (*c)[kTileSize], int n);

}  // namespace pf
