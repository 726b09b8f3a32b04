#include "reference.hpp"

#include <fmt/format.h>

#include <chrono>

#include "arealight/case_io.hpp"
#include "arealight/reference.hpp"
#include "exit_code.hpp"
#include "print_diagnostic.hpp"
#include "progress.hpp"
#include "summary.hpp"

namespace arealight::cli {

int run_reference(const ReferenceArgs& a) {
    auto cases = read_cases(a.cases, print_diagnostic);
    if (!cases) return kBadInput;
    ReferenceOptions opt;
    opt.rel_tol = a.rel_tol;
    opt.threads = a.threads;
    ProgressPrinter progress("reference", "cases");
    const auto start = std::chrono::steady_clock::now();
    const auto results =
        reference_all(*cases, opt, [&](std::size_t d, std::size_t t) { progress(d, t); });
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!write_results(a.out, results, print_diagnostic)) return kRuntime;
    if (a.table) fmt::print("{}", results_table(results));
    fmt::print("{}", results_summary(results, seconds));
    return kOk;
}

}  // namespace arealight::cli
