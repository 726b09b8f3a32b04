// Error against cost for every variant matching a pattern, measured side by side in
// one run: SPIR-V and lavapipe x86-64 instruction counts, median time per case as a
// ratio to the point-light baseline of the same distribution and shape, and error
// against the oracle (arealight reference) per quantity. As a sweep, the same for
// every case overridden along one axis in turn: the distribution's parameter
// (exponent N or roughness alpha) or the view angle.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "arealight/case.hpp"
#include "arealight/diagnostics.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/gpu_cost.hpp"
#include "arealight/results.hpp"
#include "arealight/score.hpp"
#include "arealight/variant.hpp"

namespace arealight {

// What a sweep overrides in every case: nothing (a report), the material
// parameter of the case's distribution, or the view direction.
enum class SweepAxis { None, Param, View };

const char* to_string(SweepAxis a);  // "none", "param", "view"
// "param" or "view"; nullopt for anything else (a report is not a sweep axis).
std::optional<SweepAxis> parse_sweep_axis(const std::string& s);

// The swept material parameter of one distribution: the case field it overrides,
// the symbol tables and plots name it by, the values a sweep takes by default
// (log-spaced), and the range CONTRACT.md section 2 accepts.
struct SweepParameter {
    Distribution dist;
    std::string field;   // "exponent" (phong, blinn) or "alpha" (beckmann, ggx)
    std::string symbol;  // "N" or "α"
    std::vector<double> values;
    double min = 0, max = 0;
};

// One row per distribution, in Distribution order.
const std::vector<SweepParameter>& sweep_parameters();
const SweepParameter& sweep_parameter(Distribution d);

// cos θ_v of the view sweep, from the normal to grazing.
const std::vector<double>& view_sweep_cosines();

// The case with its axis set to `value`. Param: the material's exponent or alpha
// (sweep_parameter of its distribution). View: v replaced by the unit vector at
// cos θ_v = value from n, in the plane of n and v, on v's side of n (any side when
// v is parallel to n). None: the case unchanged.
Case sweep_case(const Case& c, SweepAxis axis, double value);

// The quantity beside specular that a variant's error is judged on: "moment"
// (phong) or "ndf" (microfacet distributions).
const char* second_quantity(const Variant& v);

// The point-light variant a variant's time is divided by: same distribution and
// light, method=point, the same sided and verts where that variant exists, else
// the family's default shape.
Variant baseline_of(const Variant& v);

struct ReportOptions {
    std::string pattern;               // variant_matches pattern; empty: every variant
    SweepAxis axis = SweepAxis::None;  // None: a report
    // The axis values to sweep; empty: the axis's table (Param: sweep_parameter of
    // the variants' one distribution; View: view_sweep_cosines()).
    std::vector<double> values;
    int repeats = 7;                 // timed dispatches per variant (median)
    double dispatch_seconds = 0.02;  // cases are repeated until a dispatch lasts about this
    double floor = 1e-3;             // of the relative error (shared/tools/score metric)
    unsigned threads = 1;            // oracle threads
    // MESA_SHADER_CACHE_DIR of this process (PrivateShaderCache); empty: no
    // x86-64 counts.
    std::string shader_cache_dir;
    // Oracle values by case id, when already computed for these cases (report only;
    // a sweep computes its own).
    std::optional<ResultSet> reference;
    // RADV's figures per variant (gpu_cost.hpp); nullopt: none. Where RADV cannot be
    // used the rows go without, after one warning.
    std::optional<GpuCostOptions> gpu = GpuCostOptions{};
};

struct ReportRow {
    Variant variant;
    std::string name;       // canonical
    std::string baseline;   // the point variant its time is divided by
    double value = 0;       // sweep: the axis value of this row; 0 in a report
    std::size_t cases = 0;  // cases it applies to
    std::size_t spirv_instructions = 0, x86_instructions = 0;
    // Tables the variant samples (bytes uploaded) and image reads in its SPIR-V (per
    // shading point: no read sits in a loop).
    std::size_t table_bytes = 0, texture_fetches = 0;
    double ns_per_case = 0;  // median over repeats
    double ratio = 0;        // ns_per_case / the baseline's, same run
    // The GPU cost of the variant's kernel (ratio_to_point against the same baseline);
    // absent without RADV.
    std::optional<GpuCost> gpu;
    std::vector<QuantityScore> scores;
    // The error the plot and the Pareto front use: the larger relL2 of specular and
    // second_quantity (moment or ndf); diffuse is exact in every method but point,
    // whose larger error shows.
    double error() const;
    // On the error-cost front of its distribution, shape and value; the cost is the
    // GPU cost's ratio to the point light when every row has one, else the time ratio.
    bool pareto = false;
    // What `generate --scene` would pick by this report's rows at the default quality
    // (CONTRACT.md 7): per value, distribution and light, among the rows of the default
    // shape (sided=any, verts=8) that are not fp64, the cheapest (the front's cost) whose
    // error() is at most kDefaultMaxError, or the most accurate when none is.
    bool recommended = false;
};

struct Report {
    std::string pattern;
    std::vector<std::string> case_files;
    std::string device;
    SweepAxis axis = SweepAxis::None;
    // A sweep's axis: the JSON key of a row's value ("exponent", "alpha",
    // "cos_theta_v"), its symbol in tables ("N", "α", "cos θ_v") and the plots'
    // axis label.
    std::string parameter, symbol, axis_label;
    // What measured the rows' gpu objects ("RADV NAVI21, Mesa 22.3.6"); empty: nothing.
    std::string gpu_device;
    std::vector<ReportRow> rows;  // enumerate_variants order; per value in a sweep
    // Whether every row has a GPU cost with a ratio to its point light: the cost axis
    // of the front and of report.svg.
    bool by_gpu_cost() const;
    double seconds = 0;           // wall time of the whole run
    bool sweep() const { return axis != SweepAxis::None; }
};

// Sets each row's `pareto`: no other row of the same value, distribution and shape (so
// the same cases) is at most as costly and at most as wrong, and better in one. Cost:
// the GPU cost's ratio to the point light when every row has one, else the time ratio.
void mark_pareto(std::vector<ReportRow>& rows);
// Sets each row's `recommended` (above).
void mark_recommended(std::vector<ReportRow>& rows);

// Phase name ("reference", "compile", "gpu cost", "time"), done, total.
using PhaseProgress = std::function<void(const std::string&, std::size_t, std::size_t)>;

// nullopt, with a diagnostic, when the pattern matches nothing, a Param sweep's
// variants span several distributions, a variant fails to build or run, or no
// case applies to a variant.
std::optional<Report> run_report(Evaluator& ev, const CaseSet& cases, const ReportOptions& opt,
                                 const DiagnosticConsumer& diag,
                                 const PhaseProgress& progress = {});

std::string report_json(const Report& r);
// A report back from report_json's text (`file` names it in diagnostics), with each row's
// pareto and recommended marked again by today's rules: what `arealight replot` draws
// the markdown and pictures from, without measuring again. nullopt, with a diagnostic
// naming the file, the row and the field, on a malformed document.
std::optional<Report> read_report_json(const std::string& text, const std::string& file,
                                       const DiagnosticConsumer& diag);
std::string report_markdown(const Report& r);
// The pictures, as (file name, SVG text): for a report, error (log) against cost
// ratio to the point light (log), one point per variant, coloured by method, the
// Pareto front drawn (report.svg: the GPU cost when by_gpu_cost(), else lavapipe
// time), the same against lavapipe time (report_time.svg, only with the GPU cost),
// and error against x86-64 instruction count (report_x86.svg); for a sweep, time ratio
// and error against the axis value, one line per variant (sweep_time.svg,
// sweep_error.svg).
std::vector<std::pair<std::string, std::string>> report_pictures(const Report& r);

}  // namespace arealight
