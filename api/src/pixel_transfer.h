// Client images in GL 1.x's external formats and types (GL 1.5 sections 3.6.4 and 4.3.2): where
// each pixel of an image lies under the pack or unpack modes of glPixelStore, and conversion
// between an image's pixels and RGBA floats. glTexImage / glTexSubImage unpack by it,
// glGetTexImage packs by it, and glReadPixels lays its rows out by the same imageLayout.
#pragma once

#include <cstddef>
#include <cstdint>

#include <GL/gl.h>

namespace pf {

struct PixelStore;

// GL's check of an external format and type (Mesa's order): GL_NO_ERROR; GL_INVALID_ENUM for a
// type or format that is none of GL 1.x's colour ones (a GL_BITMAP image of colours too);
// GL_INVALID_OPERATION for a packed type with a format it cannot hold (GL 1.2's packed types:
// 3_3_2 and 5_6_5 hold GL_RGB, the others GL_RGBA or GL_BGRA).
GLenum checkColorFormatAndType(GLenum format, GLenum type);

// glDrawPixels' check of a format and type (Mesa's _mesa_error_check_format_and_type, in its
// order): GL_BITMAP only for GL_COLOR_INDEX and GL_STENCIL_INDEX (else GL_INVALID_ENUM); a packed
// type only with a format it holds (else GL_INVALID_OPERATION); GL_COLOR_INDEX,
// GL_STENCIL_INDEX and GL_DEPTH_COMPONENT with a basic type; the colour formats as
// checkColorFormatAndType.
GLenum checkDrawFormatAndType(GLenum format, GLenum type);

// Where the pixels of a width x height image lie in client memory: pixel (x, y) starts at
// offset + y * row_bytes + x * pixel_bytes (rows of GL_*_ROW_LENGTH pixels, or `width`, padded
// to GL_*_ALIGNMENT, after GL_*_SKIP_ROWS rows and GL_*_SKIP_PIXELS pixels).
struct ImageLayout {
  size_t pixel_bytes = 0;      // a group's bytes (a packed type's: the type's size)
  size_t component_bytes = 0;  // what GL_*_SWAP_BYTES reverses: a component's, or a packed word's
  size_t row_bytes = 0;
  size_t offset = 0;
  size_t bytes(int width, int height) const {  // the extent of the image, skips included
    return width <= 0 || height <= 0 ? 0 : offset + (static_cast<size_t>(height) - 1) * row_bytes + static_cast<size_t>(width) * pixel_bytes;
  }
};
// For a checked colour format and type (checkColorFormatAndType), or GL_DEPTH_COMPONENT /
// GL_STENCIL_INDEX with a basic type.
ImageLayout imageLayout(const PixelStore& store, GLenum format, GLenum type, int width);

// Reads `width` x `height` pixels by the unpack modes into RGBA floats (4 a pixel, row 0 first):
// GL's conversion of each component to [0, 1] (signed ones to [-1, 1]), luminance to red, green
// and blue, missing colour components 0 and a missing alpha 1.
void unpackColors(const PixelStore& store, GLenum format, GLenum type, int width, int height, const void* data,
                  float* rgba);

// Writes RGBA floats (4 a pixel, row 0 first) as `width` x `height` pixels by the pack modes:
// each component clamped to [0, 1] and converted to the type (a luminance group takes red).
void packColors(const PixelStore& store, GLenum format, GLenum type, int width, int height, const float* rgba,
                void* data);

// Reads a `width` x `height` GL_BITMAP image (glBitmap's, GL 1.5 section 3.6.4) by the unpack
// modes into one byte a pixel, 1 for a set bit (row 0 first): rows of GL_UNPACK_ROW_LENGTH bits
// (or `width`) padded to whole bytes and to the alignment, after GL_UNPACK_SKIP_ROWS rows and
// GL_UNPACK_SKIP_PIXELS bits, each byte's bits from the most significant unless
// GL_UNPACK_LSB_FIRST.
void unpackBitmap(const PixelStore& store, int width, int height, const void* data, unsigned char* bits);

// Writes a `width` x `height` GL_BITMAP image (one byte a pixel, non-zero a set bit, row 0 first)
// by the pack modes, laid out as unpackBitmap reads one. As Mesa's _mesa_pack_bitmap: each byte
// that holds some of a row's bits is written whole, its other bits 0; other bytes are untouched.
void packBitmap(const PixelStore& store, int width, int height, const unsigned char* bits, void* data);

// Reads a `width` x `height` image of indices (GL_STENCIL_INDEX, GL_COLOR_INDEX) by the unpack
// modes into integers (row 0 first): each component as it is (a float truncated), a GL_BITMAP
// image's bits as 0 and 1.
void unpackIndices(const PixelStore& store, GLenum type, int width, int height, const void* data, uint32_t* out);

}  // namespace pf
