// `arealight variants`, `eval` and `compare`: the variant names, one variant over a case file
// (the CPU mirror or the SPIR-V on Vulkan), and a results file scored against a reference.
// Their options are in cli/main.cpp, which calls these.
#pragma once

#include <string>

namespace arealight::cli {

struct EvalArgs {
    std::string cases, variant, out;
    std::string backend = "vulkan";  // cpu or vulkan
    std::string device;              // Vulkan device name substring; empty: the first
    std::string lang = "glsl";       // glsl or hlsl (Vulkan only)
};

struct CompareArgs {
    std::string ref, out;
    double floor = 1e-3;
};

// Exit codes as cli/main.cpp: 0 ok.
int run_variants();

// Exit codes as cli/main.cpp: 0 ok, 1 bad input (unknown variant, malformed cases, an fp64
// variant in HLSL), 2 usage (HLSL on the CPU), 3 no device or a write failure.
int run_eval(const EvalArgs& args);

// Exit codes as cli/main.cpp: 0 ok, 1 an unreadable or malformed results file.
int run_compare(const CompareArgs& args);

}  // namespace arealight::cli
