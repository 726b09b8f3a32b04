#include "eval.hpp"

#include <fmt/format.h>

#include "arealight/case_io.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/generator.hpp"
#include "arealight/score.hpp"
#include "exit_code.hpp"
#include "print_diagnostic.hpp"

namespace arealight::cli {

int run_variants() {
    for (const auto& v : enumerate_variants()) fmt::print("{}\n", canonical_name(v));
    return kOk;
}

int run_eval(const EvalArgs& a) {
    auto variant = parse_variant(a.variant, print_diagnostic);
    if (!variant) return kBadInput;
    auto cases = read_cases(a.cases, print_diagnostic);
    if (!cases) return kBadInput;
    EvalOptions opt;
    opt.backend = a.backend == "cpu" ? Backend::Cpu : Backend::Vulkan;
    opt.device = a.device;
    opt.language = a.lang == "hlsl" ? Language::Hlsl : Language::Glsl;
    if (opt.language == Language::Hlsl && opt.backend != Backend::Vulkan) {
        print_diagnostic(
            {Severity::Error, "", 0,
             "eval: --lang hlsl runs the HLSL kernel on Vulkan: give --backend vulkan"});
        return kUsage;
    }
    if (!language_supports(opt.language, *variant)) {
        print_diagnostic({Severity::Error, "", 0,
                          "eval: the HLSL library is fp32 only, and " + canonical_name(*variant) +
                              " computes at " + to_string(effective_precision(*variant))});
        return kBadInput;
    }
    auto evaluator = Evaluator::create(opt, print_diagnostic);
    if (!evaluator) return kRuntime;
    EvalStats stats;
    auto results = evaluator->run(*variant, *cases, print_diagnostic, &stats);
    if (!results) return kRuntime;
    if (!write_results(a.out, *results, print_diagnostic)) return kRuntime;
    fmt::print(stderr, "eval: {} cases on {}, {} not applicable to {}\n", stats.evaluated,
               a.backend, stats.skipped, canonical_name(*variant));
    return kOk;
}

int run_compare(const CompareArgs& a) {
    auto ref = read_results(a.ref, print_diagnostic);
    auto out = read_results(a.out, print_diagnostic);
    if (!ref || !out) return kBadInput;
    fmt::print("{} ({}) against {}\n", a.out, out->variant, a.ref);
    fmt::print("{}", format_scores(score_results(*ref, *out, a.floor)));
    return kOk;
}

}  // namespace arealight::cli
