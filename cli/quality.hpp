// `arealight quality`: the measured data scene selection ranks by (data/quality/
// measured.json, arealight-quality/1) from report JSON files. Its options are in
// cli/main.cpp, which calls run_quality.
#pragma once

#include <string>
#include <vector>

#include "arealight/gpu_cost.hpp"

namespace arealight::cli {

struct QualityArgs {
    std::vector<std::string> reports;
    std::string out;
    std::string gpu_family = GpuCostOptions{}.family;
    std::string gpu_cache;  // --gpu-cache / AREALIGHT_GPU_CACHE
};

// 0 ok, 3 a report unreadable or the output not written (usage errors are CLI11's, 2).
int run_quality(const QualityArgs& args);

}  // namespace arealight::cli
