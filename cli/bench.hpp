// `arealight bench`: variants timed side by side over a case file (medians of interleaved
// repeats, ratio to the first), with their GPU cost. Its options are in cli/main.cpp, which
// calls run_bench.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "arealight/gpu_cost.hpp"

namespace arealight::cli {

struct BenchArgs {
    std::string cases;
    std::vector<std::string> variants;  // the first is the baseline
    std::vector<double> exponents;      // override every case's exponent, in turn
    std::string backend = "vulkan";
    std::size_t min_cases = 1 << 16;
    int repeats = 9;
    std::string gpu_family = GpuCostOptions{}.family;
    std::string gpu_cache;
};

// Exit codes as cli/main.cpp: 0 ok, 1 bad input (unknown variant, malformed cases), 3 no
// device or a failed run.
int run_bench(const BenchArgs& args);

}  // namespace arealight::cli
