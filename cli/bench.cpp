#include "bench.hpp"

#include <fmt/format.h>

#include <optional>

#include "arealight/benchmark.hpp"
#include "arealight/case_io.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/machine_code.hpp"
#include "exit_code.hpp"
#include "print_diagnostic.hpp"
#include "progress.hpp"

namespace arealight::cli {

int run_bench(const BenchArgs& a) {
    BenchOptions opt;
    opt.gpu->family = a.gpu_family;
    opt.gpu->cache_dir = a.gpu_cache;
    for (const auto& name : a.variants) {
        auto v = parse_variant(name, print_diagnostic);
        if (!v) return kBadInput;
        opt.variants.push_back(*v);
    }
    auto cases = read_cases(a.cases, print_diagnostic);
    if (!cases) return kBadInput;
    opt.exponents = a.exponents;
    opt.min_cases = a.min_cases;
    opt.repeats = a.repeats;
    // Before any Vulkan call: Mesa reads its cache location once per process.
    // Declared before the evaluator, so that it outlives every Vulkan object.
    std::optional<PrivateShaderCache> cache;
    if (a.backend == "vulkan") opt.shader_cache_dir = cache.emplace().path();
    EvalOptions eo;
    eo.backend = a.backend == "cpu" ? Backend::Cpu : Backend::Vulkan;
    auto ev = Evaluator::create(eo, print_diagnostic);
    if (!ev) return kRuntime;
    ProgressPrinter progress("bench", "timed runs");
    auto rows = benchmark(*ev, *cases, opt, print_diagnostic,
                          [&](std::size_t d, std::size_t t) { progress(d, t); });
    if (!rows) return kRuntime;
    fmt::print("{}", format_bench(*rows));
    return kOk;
}

}  // namespace arealight::cli
