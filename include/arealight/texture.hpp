// A 2-D table the shaders sample as a texture: RGBA, fp32, row-major (texel (x, y)
// at rgba[4 (y width + x) + c]). The Vulkan runner uploads it as a sampled image
// (R32G32B32A32_SFLOAT, linear filtering, clamp to edge); the CPU mirror samples the
// same data with the same bilinear rule (include/arealight/mirror_support.hpp).
#pragma once

#include <cstdint>
#include <vector>

namespace arealight {

struct Texture2D {
    std::uint32_t width = 0, height = 0;
    std::vector<float> rgba;  // width * height * 4

    std::size_t bytes() const { return rgba.size() * sizeof(float); }
};

}  // namespace arealight
