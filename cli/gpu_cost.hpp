// `arealight gpu-cost`: the `gpu` object (gpu_cost.hpp) of variants or of SPIR-V files,
// one JSON line each, for checking a figure against shared/tools/radvstats by hand.
#pragma once

#include <string>
#include <vector>

#include "arealight/gpu_cost.hpp"

namespace arealight::cli {

struct GpuCostArgs {
    std::vector<std::string> variants, spv;
    std::string gpu_family = GpuCostOptions{}.family;
    std::string gpu_cache;  // --gpu-cache / AREALIGHT_GPU_CACHE
};

// 0 ok, 1 an unknown variant or unreadable file, 2 neither --variant nor --spv, 3 RADV
// missing or a module it fails on.
int run_gpu_cost(const GpuCostArgs& args);

}  // namespace arealight::cli
