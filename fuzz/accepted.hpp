// What the evaluators rely on once a reader accepted a light or a material (CONTRACT.md 2,
// 3), checked by the case and scene fuzz targets.
#pragma once

#include <cmath>

#include "arealight/case.hpp"
#include "fuzz_support.hpp"

namespace arealight::fuzz {

inline bool finite(const Vec3& x) {
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

inline void check_accepted(const Light& light) {
    if (light.type == LightType::Polygon) {
        require(light.vertices.size() >= 3 && light.vertices.size() <= 8,
                "accepted polygon with a vertex count outside 3..8");
        for (const Vec3& x : light.vertices) require(finite(x), "accepted non-finite vertex");
    } else {
        require(finite(light.center), "accepted non-finite centre");
    }
    if (light.type == LightType::Sphere)
        require(light.radius > 0.0 && std::isfinite(light.radius),
                "accepted sphere radius that is not positive and finite");
}

inline void check_accepted(const Material& m) {
    if (m.distribution == Distribution::Beckmann || m.distribution == Distribution::Ggx)
        require(m.alpha >= 0.001 && m.alpha <= 1.0, "accepted alpha outside [0.001, 1]");
    else
        require(m.exponent >= 1.0 && m.exponent <= 100000.0,
                "accepted exponent outside [1, 100000]");
    require(m.f0 >= 0.0 && m.f0 <= 1.0, "accepted f0 outside [0, 1]");
}

}  // namespace arealight::fuzz
