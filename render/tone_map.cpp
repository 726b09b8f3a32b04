#include "arealight/tone_map.hpp"

#include <algorithm>
#include <cmath>

namespace arealight {

std::uint8_t srgb8(double linear) {
    const double x = std::clamp(linear, 0.0, 1.0);
    const double s = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
    return static_cast<std::uint8_t>(std::lround(s * 255.0));
}

Image8 tone_map(const LinearImage& image, double exposure) {
    Image8 out;
    out.width = image.width;
    out.height = image.height;
    out.rgb.resize(image.rgb.size());
    for (std::size_t px = 0; px + 2 < image.rgb.size(); px += 3) {
        const float* c = &image.rgb[px];
        const bool finite = std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]);
        for (int k = 0; k < 3; ++k)
            out.rgb[px + k] = finite ? srgb8(exposure * c[k]) : (k == 1 ? 0 : 255);
    }
    return out;
}

}  // namespace arealight
