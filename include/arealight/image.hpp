// Pictures in memory: linear float radiance and 8-bit display values, both RGB,
// row 0 at the top.
#pragma once

#include <cstdint>
#include <vector>

namespace arealight {

struct LinearImage {
    int width = 0, height = 0;
    std::vector<float> rgb;  // width * height * 3
};

struct Image8 {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;  // width * height * 3
};

}  // namespace arealight
