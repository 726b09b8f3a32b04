// libFuzzer target: parse_cases (arealight-cases/1) on arbitrary bytes.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "arealight/case_io.hpp"
#include "fuzz_support.hpp"

namespace {

bool finite(const arealight::Vec3& x) {
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace arealight;
    const auto set = fuzz::read_checked(data, size, [](const std::string& text, auto diag) {
        return parse_cases(text, "fuzz.cases.json", diag);
    });
    if (!set) return 0;
    // What the evaluators rely on once a file was accepted.
    for (const Case& c : set->cases) {
        fuzz::require(!c.id.empty(), "accepted case without id");
        fuzz::require(finite(c.p) && finite(c.n) && finite(c.v), "accepted non-finite p, n or v");
        if (c.light.type == LightType::Polygon) {
            fuzz::require(c.light.vertices.size() >= 3 && c.light.vertices.size() <= 8,
                          "accepted polygon with a vertex count outside 3..8");
            for (const Vec3& x : c.light.vertices)
                fuzz::require(finite(x), "accepted non-finite vertex");
        }
        if (c.light.type == LightType::Sphere)
            fuzz::require(c.light.radius > 0.0 && std::isfinite(c.light.radius),
                          "accepted sphere radius that is not positive and finite");
        const Distribution d = c.material.distribution;
        if (d == Distribution::Beckmann || d == Distribution::Ggx)
            fuzz::require(c.material.alpha >= 0.001 && c.material.alpha <= 1.0,
                          "accepted alpha outside [0.001, 1]");
        else
            fuzz::require(c.material.exponent >= 1.0 && c.material.exponent <= 100000.0,
                          "accepted exponent outside [1, 100000]");
    }
    return 0;
}
