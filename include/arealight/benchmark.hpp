// Side-by-side timing of variants on one case set: medians over interleaved
// repeats, each variant against a baseline measured in the same run.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "arealight/evaluator.hpp"
#include "arealight/gpu_cost.hpp"

namespace arealight {

struct BenchOptions {
    std::vector<Variant> variants;    // the first is the baseline
    std::vector<double> exponents;    // overrides the cases' exponent; empty keeps them
    std::size_t min_cases = 1 << 16;  // cases are repeated up to this count per dispatch
    int repeats = 9;
    // When set, SPIR-V and lavapipe x86-64 instruction counts are taken; the folder
    // must be MESA_SHADER_CACHE_DIR (see PrivateShaderCache).
    std::string shader_cache_dir;
    // RADV's figures per variant (gpu_cost.hpp); nullopt: none. Without RADV the rows
    // go without, after one warning.
    std::optional<GpuCostOptions> gpu = GpuCostOptions{};
};

struct BenchRow {
    std::string variant;
    double exponent = 0;                 // 0 when the cases kept their own
    std::size_t cases = 0;               // cases per dispatch
    double median_ns_per_case = 0;       // backend time (Vulkan: submit + wait)
    double ratio = 0;                    // median / baseline median at the same exponent
    std::size_t spirv_instructions = 0;  // after optimization; 0 when not counted
    std::size_t x86_instructions = 0;    // lavapipe's JIT code; 0 when not counted
    // The variant's GPU cost, ratio_to_point against its point light (baseline_of), not
    // against the first variant; absent without RADV.
    std::optional<GpuCost> gpu;
};

// nullopt (with a diagnostic) when a variant fails to build or run.
std::optional<std::vector<BenchRow>> benchmark(Evaluator& ev, const CaseSet& cases,
                                               const BenchOptions& opt,
                                               const DiagnosticConsumer& diag,
                                               const ProgressConsumer& progress = {});

std::string format_bench(const std::vector<BenchRow>& rows);

}  // namespace arealight
