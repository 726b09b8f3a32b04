// The shader's two textures built from a table (include/arealight/ltc_table.hpp).
#include <algorithm>
#include <cmath>

#include "arealight/ltc_table.hpp"

namespace arealight {

std::vector<Texture2D> ltc_textures(const LtcTable& t) {
    const auto n = static_cast<std::uint32_t>(t.size);
    std::vector<Texture2D> tex(2);
    for (auto& x : tex) {
        x.width = x.height = n;
        x.rgba.assign(static_cast<std::size_t>(n) * n * 4, 0.0f);
    }
    for (int j = 0; j < t.size; ++j) {
        for (int i = 0; i < t.size; ++i) {
            const LtcCell& c = t.at(i, j);
            const std::size_t k = 4 * (static_cast<std::size_t>(j) * n + i);
            float* m = tex[0].rgba.data() + k;
            const double alpha = ltc_matrix_scale(t, i);
            m[0] = static_cast<float>(c.a * alpha);
            m[1] = static_cast<float>(c.b * alpha);
            m[2] = static_cast<float>(c.c * alpha);
            m[3] = static_cast<float>(c.d);
            // Sphere proxy: cos omega = 2 u - 1, sin^2 sigma = w; I / sin^2 sigma, whose
            // limit at sigma = 0 is max(cos omega, 0).
            const double u = static_cast<double>(i) / (t.size - 1);
            const double w = static_cast<double>(j) / (t.size - 1);
            const double cos_omega = 2 * u - 1;
            const double s =
                w > 0 ? sphere_horizon_form_factor(cos_omega, std::sqrt(w)) / w
                      : std::max(cos_omega, 0.0);
            float* a = tex[1].rgba.data() + k;
            a[0] = static_cast<float>(c.amp_f0);
            a[1] = static_cast<float>(c.amp_one);
            a[2] = static_cast<float>(c.kappa);
            a[3] = static_cast<float>(s);
        }
    }
    return tex;
}

}  // namespace arealight
