// Scenes on the command line (CONTRACT.md 7): `arealight scene-variants --scene FILE`
// prints the variants a scene's library is made of, one name per line, with why each
// was chosen on stderr. `generate --scene` will call into this file once the library
// generator is on main. Hooked into cli/main.cpp like cli/fit_ltc.hpp.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace arealight::cli {

struct SceneVariantsArgs {
    std::string scene;
};

CLI::App* add_scene_variants_command(CLI::App& app, SceneVariantsArgs& args);

// 0 ok, 1 a malformed scene or nothing to select for it.
int run_scene_variants(const SceneVariantsArgs& args);

}  // namespace arealight::cli
