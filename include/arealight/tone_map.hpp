// Linear radiance to display values: exposure, clamp to [0, 1], then the sRGB transfer
// function (IEC 61966-2-1), rounded to 8 bits. No filmic curve: what is brighter than
// 1 / exposure clips to white, so that equal radiance looks equal in every rendering.
#pragma once

#include <cstdint>

#include "arealight/image.hpp"

namespace arealight {

// One linear value in [0, 1] (clamped) to its sRGB 8-bit code.
std::uint8_t srgb8(double linear);

// A pixel with a non-finite channel shows magenta, so that a NaN cannot hide as black.
Image8 tone_map(const LinearImage& image, double exposure = 1.0);

}  // namespace arealight
