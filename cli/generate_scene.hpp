// Scenes on the command line (CONTRACT.md 7): `arealight scene-variants --scene FILE`
// prints the variants a scene's library is made of, one name per line, with why each
// was chosen on stderr (`generate --scene`, in cli/generate.cpp, writes their library).
// Its options are in cli/main.cpp, which calls run_scene_variants.
#pragma once

#include <string>

namespace arealight::cli {

struct SceneVariantsArgs {
    std::string scene;
};

// 0 ok, 1 a malformed scene or nothing to select for it.
int run_scene_variants(const SceneVariantsArgs& args);

}  // namespace arealight::cli
