// Error against cost for every variant matching a pattern, measured side by side in
// one run: SPIR-V and lavapipe x86-64 instruction counts, median time per case as a
// ratio to the point-light baseline of the same shape, and error against the oracle
// (arealight reference) per quantity. With exponents given it is a sweep: the same
// for every case's exponent overridden by each N in turn (cost and error against N).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "arealight/case.hpp"
#include "arealight/diagnostics.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/results.hpp"
#include "arealight/score.hpp"
#include "arealight/variant.hpp"

namespace arealight {

struct ReportOptions {
    std::string pattern;             // variant_matches pattern; empty: every variant
    std::vector<double> exponents;   // sweep: override every case's exponent; empty: keep
    int repeats = 7;                 // timed dispatches per variant (median)
    double dispatch_seconds = 0.02;  // cases are repeated until a dispatch lasts about this
    double floor = 1e-3;             // of the relative error (shared/tools/score metric)
    unsigned threads = 1;            // oracle threads
    // MESA_SHADER_CACHE_DIR of this process (use_private_shader_cache); empty: no
    // x86-64 counts.
    std::string shader_cache_dir;
    // Oracle values by case id, when already computed for these cases and exponents
    // (report only; a sweep computes its own).
    std::optional<ResultSet> reference;
};

struct ReportRow {
    Variant variant;
    std::string name;       // canonical
    std::string baseline;   // the point variant its time is divided by
    double exponent = 0;    // sweep: the N of this row; 0: each case's own
    std::size_t cases = 0;  // cases it applies to
    std::size_t spirv_instructions = 0, x86_instructions = 0;
    double ns_per_case = 0;  // median over repeats
    double ratio = 0;        // ns_per_case / the baseline's, same run
    std::vector<QuantityScore> scores;
    // The error the plot and the Pareto front use: the larger relL2 of specular and
    // moment (diffuse is exact in every method but point, whose larger error shows).
    double error() const;
    bool pareto = false;  // on the error-cost front of its exponent
};

struct Report {
    std::string pattern;
    std::vector<std::string> case_files;
    std::string device;
    std::vector<ReportRow> rows;  // enumerate_variants order; per exponent in a sweep
    double seconds = 0;           // wall time of the whole run
};

// Phase name ("reference", "compile", "time"), done, total.
using PhaseProgress = std::function<void(const std::string&, std::size_t, std::size_t)>;

// nullopt, with a diagnostic, when the pattern matches nothing, a variant fails
// to build or run, or no case applies to a variant.
std::optional<Report> run_report(Evaluator& ev, const CaseSet& cases, const ReportOptions& opt,
                                 const DiagnosticConsumer& diag,
                                 const PhaseProgress& progress = {});

std::string report_json(const Report& r);
std::string report_markdown(const Report& r);
// The pictures, as (file name, SVG text): for a report, error (log) against time
// ratio to the point light (log), one point per variant, coloured by method, the
// Pareto front drawn (report.svg), and error against x86-64 instruction count
// (report_x86.svg); for a sweep, time ratio and error against N,
// one line per variant (sweep_time.svg, sweep_error.svg).
std::vector<std::pair<std::string, std::string>> report_pictures(const Report& r);

}  // namespace arealight
