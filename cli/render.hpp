// `arealight render`: a scene's picture through the shading library (or the oracle), as
// a PNG, optionally its linear radiance (PFM) and its error against a linear reference.
// Its options are in cli/main.cpp, which calls run_render.
#pragma once

#include <string>
#include <vector>

namespace arealight::cli {

struct RenderArgs {
    std::string scene, out, linear, compare, diff, backend = "vulkan", device;
    std::vector<std::string> variants;
    std::vector<int> size = {320, 240};
    bool reference = false;
    double exposure = 1.0, floor = 1e-3, tolerance = 1e-4;
    unsigned threads = 0;  // 0: hardware concurrency
};

// Exit codes as cli/main.cpp: 0 ok, 1 bad input, 3 runtime or write failure.
int run_render(const RenderArgs& args);

}  // namespace arealight::cli
