// `arealight report` and `arealight sweep`: every variant matching a pattern measured for
// error (against the oracle) and cost (GPU cost, lavapipe time, x86-64 counts), written as
// JSON, markdown and plots; a sweep along one axis (the distribution's parameter or the
// view). Their options are in cli/main.cpp, which calls run_report.
#pragma once

#include <string>
#include <vector>

#include "arealight/gpu_cost.hpp"

namespace arealight::cli {

struct ReportArgs {
    std::vector<std::string> cases, refs;
    std::string pattern, out_dir;
    std::string axis = "param";             // sweep: param or view
    std::vector<double> values, exponents;  // sweep: --value, --exponent
    int repeats = 7;
    double dispatch_ms = 20;
    unsigned threads = 1;
    std::string gpu_family = GpuCostOptions{}.family;
    std::string gpu_cache;
};

// Measures, then writes every file (nothing is written on failure). Exit codes as
// cli/main.cpp: 0 ok, 1 bad input (no matching variant, malformed cases or references, a
// sweep value out of range), 3 no device or a write failure.
int run_report(const ReportArgs& args, bool sweep);

}  // namespace arealight::cli
