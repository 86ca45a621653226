// GL fog in the shading pass (see fog.h). Its own translation unit: the shading pass's loops are
// compiled once per instruction set (simd_clones.h), and exp2 must give every clone the same
// bits -- here it is the one scalar library function for all of them.
#include "raster/fog.h"

#include <cmath>

namespace pf {

float fogFactor(const FogParams& fog, float z) {
  float f;
  switch (fog.mode) {
    case FogMode::Linear: f = z * fog.scale + fog.offset; break;
    case FogMode::Exp: f = std::exp2(-(fog.scale * z)); break;
    default: {
      const float t = fog.scale * z;
      f = std::exp2(-(t * t));
      break;
    }
  }
  if (!(f > 0.0f)) return 0.0f;  // NaN too
  return f < 1.0f ? f : 1.0f;
}

void fogRun(const FogParams& fog, const float* coord, float (*c)[kTileSize], int n) {
  for (int i = 0; i < n; ++i) {
    const float f = fogFactor(fog, std::fabs(coord[i]));  // (a surface's P.z: see fog.h)
    for (int k = 0; k < 3; ++k) {
      float v = c[k][i];
      v = v > 0.0f ? v : 0.0f;  // NaN too
      v = v < 1.0f ? v : 1.0f;
      c[k][i] = f * v + (1.0f - f) * fog.color[k];
    }
  }
}

}  // namespace pf
