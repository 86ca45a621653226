// libprimflow-osmesa: the caller's buffer layouts OSMesa (Mesa 22.3) accepts, and the copies of
// primflow's frame (RGBA, 8 bits a channel, row 0 at the bottom; float depth) into them.
#pragma once

#include <cstddef>
#include <cstdint>

#include <GL/gl.h>

namespace pf::osmesa {

// Bytes a pixel of the caller's colour buffer takes for an OSMESA_* format and a type; 0 where
// OSMesaMakeCurrent refuses the pair (Mesa 22.3: BGRA, ARGB take GL_UNSIGNED_SHORT and GL_FLOAT
// but store them as RGBA; RGB takes all three; BGR and COLOR_INDEX none; RGB_565 only
// GL_UNSIGNED_SHORT_5_6_5).
int colorPixelBytes(GLenum format, GLenum type);

// Writes `frame` (width x height RGBA8, row 0 at the bottom) into `dst` in format/type, rows
// `row_pixels` pixels apart, row 0 at the bottom if y_up else at the top.
void writeColor(const uint8_t* frame, int width, int height, GLenum format, GLenum type, void* dst,
                int row_pixels, bool y_up);

// Depth as OSMesa lays it out: 2 bytes (16 bits), or 4 bytes with Z in the low 24 bits (24).
// The bytes a value takes for the depth bits OSMesa gives (16 or 24); 0 for no depth buffer.
int depthValueBytes(int depth_bits);
// Writes width x height depth values in [0, 1] (row 0 at the bottom) as depth_bits integers,
// rounded to nearest as llvmpipe does.
void writeDepth(const float* depth, int width, int height, int depth_bits, void* dst);

}  // namespace pf::osmesa
