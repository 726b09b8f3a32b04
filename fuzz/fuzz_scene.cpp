// libFuzzer target: parse_scene (arealight-scene/1) on arbitrary bytes. Built when
// include/arealight/scene.hpp exists (fuzz/CMakeLists.txt, AREALIGHT_FUZZ_SCENE).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "accepted.hpp"
#include "arealight/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace arealight;
    const auto scene = fuzz::read_checked(data, size, [](const std::string& text, auto diag) {
        return parse_scene(text, "fuzz.scene.json", diag);
    });
    if (!scene) return 0;
    fuzz::require(!scene->lights.empty() && !scene->materials.empty(),
                  "accepted a scene without lights or materials");
    for (const Light& light : scene->lights) fuzz::check_accepted(light);
    for (const Material& m : scene->materials) fuzz::check_accepted(m);
    auto check_quality = [](const SceneQuality& q) {
        if (q.max_error)
            fuzz::require(*q.max_error > 0.0 && std::isfinite(*q.max_error),
                          "accepted a max_error that is not positive and finite");
        for (const auto& m : q.exclude) fuzz::require(!m.empty(), "accepted an empty exclude name");
    };
    check_quality(scene->quality);
    fuzz::require(scene->material_quality.size() == scene->materials.size(),
                  "material_quality is not parallel to materials");
    for (const auto& q : scene->material_quality)
        if (q) check_quality(*q);
    return 0;
}
