// Writing RGBA8 images as PNG (libpng). Rows are given bottom-up, as GL and primflow store them.
#pragma once

#include <cstdint>
#include <string>

namespace pf {

// Returns false and fills `error` if the file cannot be written.
bool writePngBottomUp(const std::string& path, const uint8_t* rgba, int width, int height, std::string* error);

}  // namespace pf
