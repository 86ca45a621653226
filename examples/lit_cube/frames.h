// The animation strip both mains write: kFrames frames of kSize x kSize side by side.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

constexpr int kFrames = 4;
constexpr int kSize = 256;

// Copies one frame (RGBA, bottom-up) into its place in the strip.
inline void placeFrame(std::vector<uint8_t>& strip, const std::vector<uint8_t>& frame, int index) {
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize * 4; ++x)
      strip[(static_cast<size_t>(y) * kSize * kFrames + static_cast<size_t>(index) * kSize) * 4 + x] =
          frame[static_cast<size_t>(y) * kSize * 4 + x];
}
