// `arealight generate`: a variant's validation kernel (GLSL and/or SPIR-V), or the
// shading library of CONTRACT.md 5 for one or more variants (--library), with the
// tables it samples (--tables). Its options are in cli/main.cpp, which calls run_generate.
#pragma once

#include <string>
#include <vector>

#include "arealight/diagnostics.hpp"

namespace arealight::cli {

struct GenerateArgs {
    std::vector<std::string> variants;
    std::string scene;  // instead of variants: the scene's selection
    std::string glsl, hlsl, spv, library, tables;
    std::string lang = "glsl";  // the library's language
    bool no_opt = false;
};

// Exit codes as cli/main.cpp: 0 ok, 1 bad input (unknown variant, two variants of one
// light and distribution), 2 usage, 3 compile or write failure.
int run_generate(const GenerateArgs& args, const DiagnosticConsumer& diag);

}  // namespace arealight::cli
