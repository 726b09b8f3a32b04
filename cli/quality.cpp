#include "quality.hpp"

#include <chrono>

#include "arealight/atomic_file.hpp"
#include "arealight/quality.hpp"
#include "arealight/variant.hpp"
#include "exit_code.hpp"
#include "print_diagnostic.hpp"
#include "progress.hpp"

namespace arealight::cli {

int run_quality(const QualityArgs& args) {
    auto data = quality_from_reports(args.reports, print_diagnostic);
    if (!data) return kRuntime;
    // A report older than a change to the variant keys may name what no longer exists:
    // selection could never choose it, so it does not ship.
    std::vector<MeasuredVariant> kept;
    for (auto& m : data->variants) {
        if (parse_variant(m.variant, {}))
            kept.push_back(std::move(m));
        else
            print_diagnostic(
                {Severity::Warning, m.report, 0,
                 m.report + ": '" + m.variant + "' is not a variant of this arealight; left out"});
    }
    data->variants = std::move(kept);
    // The GPU cost is deterministic and needs no lavapipe run: measured here from each
    // variant itself, so that it follows the current templates and --gpu-family. Without
    // RADV the reports' own gpu objects stay.
    const auto t0 = std::chrono::steady_clock::now();
    GpuCostOptions gopt;
    gopt.family = args.gpu_family;
    gopt.cache_dir = args.gpu_cache;
    std::size_t measured = 0;
    if (auto meter = GpuCostMeter::create(gopt, print_diagnostic)) {
        ProgressPrinter progress("gpu cost", "variants");
        for (auto& m : data->variants) {
            const auto v = parse_variant(m.variant, {});
            m.gpu = meter->measure(*v, print_diagnostic);
            if (!m.gpu) return kRuntime;
            progress(++measured, data->variants.size());
        }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!write_file_atomic(args.out, format_quality(*data), print_diagnostic)) return kRuntime;
    std::fprintf(stderr,
                 "quality: %zu variants from %zu reports (GPU cost of %zu in %.0f s); wrote %s\n",
                 data->variants.size(), data->reports.size(), measured, seconds, args.out.c_str());
    return kOk;
}

}  // namespace arealight::cli
