#include "generate_scene.hpp"

#include <cstdio>

#include "arealight/scene_select.hpp"
#include "exit_code.hpp"
#include "print_diagnostic.hpp"

namespace arealight::cli {

int run_scene_variants(const SceneVariantsArgs& args) {
    const auto scene = read_scene(args.scene, print_diagnostic);
    if (!scene) return kBadInput;
    const auto selected = select_variants(*scene, shipped_quality(), print_diagnostic);
    if (!selected) return kBadInput;
    for (const auto& s : *selected) {
        std::printf("%s\n", canonical_name(s.variant).c_str());
        std::fprintf(stderr, "arealight: note: %s: %s\n", canonical_name(s.variant).c_str(),
                     s.why.c_str());
    }
    return kOk;
}

}  // namespace arealight::cli
