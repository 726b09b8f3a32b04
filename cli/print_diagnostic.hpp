// How the scene and quality subcommands print library diagnostics on stderr.
#pragma once

#include <cstdio>

#include "arealight/diagnostics.hpp"

namespace arealight::cli {

inline void print_scene_diagnostic(const Diagnostic& d) {
    std::fprintf(stderr, "arealight: %s: %s\n", to_string(d.severity), d.message.c_str());
}

}  // namespace arealight::cli
