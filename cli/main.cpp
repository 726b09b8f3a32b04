// arealight command line (CONTRACT.md section 4). Thin: parse, configure, call
// the library, map the outcome to an exit code.
//
// Exit codes: 0 success, 1 bad input (malformed case file, unknown variant),
// 2 usage error, 3 runtime or device failure (write failure, no Vulkan device).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <thread>

#include "arealight/atomic_file.hpp"
#include "arealight/benchmark.hpp"
#include "arealight/case_io.hpp"
#include "arealight/compiler.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/generator.hpp"
#include "arealight/machine_code.hpp"
#include "arealight/reference.hpp"
#include "arealight/report.hpp"
#include "arealight/score.hpp"
#include "compile.hpp"
#include "fit_ltc.hpp"
#include "generate.hpp"
#include "generate_scene.hpp"
#include "gpu_cost.hpp"
#include "gpu_family.hpp"
#include "print_diagnostic.hpp"
#include "replot.hpp"
#include "progress.hpp"
#include "quality.hpp"
#include "render.hpp"
#include "summary.hpp"

namespace {

using arealight::cli::ProgressPrinter;

enum Exit { kOk = 0, kBadInput = 1, kUsage = 2, kRuntime = 3 };

using arealight::cli::print_diagnostic;

int run_reference(const std::string& cases_path, const std::string& out_path, double rel_tol,
                  unsigned threads, bool table) {
    auto cases = arealight::read_cases(cases_path, print_diagnostic);
    if (!cases) return kBadInput;
    arealight::ReferenceOptions opt;
    opt.rel_tol = rel_tol;
    opt.threads = threads;
    ProgressPrinter progress("reference", "cases");
    const auto start = std::chrono::steady_clock::now();
    const auto results = arealight::reference_all(
        *cases, opt, [&](std::size_t d, std::size_t t) { progress(d, t); });
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!arealight::write_results(out_path, results, print_diagnostic)) return kRuntime;
    if (table) fmt::print("{}", arealight::cli::results_table(results));
    fmt::print("{}", arealight::cli::results_summary(results, seconds));
    return kOk;
}

int run_variants() {
    for (const auto& v : arealight::enumerate_variants()) {
        fmt::print("{}\n", arealight::canonical_name(v));
    }
    return kOk;
}

int run_eval(const std::string& cases_path, const std::string& variant_name,
             const std::string& backend, const std::string& device, const std::string& lang,
             const std::string& out_path) {
    auto variant = arealight::parse_variant(variant_name, print_diagnostic);
    if (!variant) return kBadInput;
    auto cases = arealight::read_cases(cases_path, print_diagnostic);
    if (!cases) return kBadInput;
    arealight::EvalOptions opt;
    opt.backend = backend == "cpu" ? arealight::Backend::Cpu : arealight::Backend::Vulkan;
    opt.device = device;
    opt.language = lang == "hlsl" ? arealight::Language::Hlsl : arealight::Language::Glsl;
    if (opt.language == arealight::Language::Hlsl && opt.backend != arealight::Backend::Vulkan) {
        print_diagnostic({arealight::Severity::Error, "", 0,
                          "eval: --lang hlsl runs the HLSL kernel on Vulkan: give --backend vulkan"});
        return kUsage;
    }
    if (!arealight::language_supports(opt.language, *variant)) {
        print_diagnostic({arealight::Severity::Error, "", 0,
                          "eval: the HLSL library is fp32 only, and " +
                              arealight::canonical_name(*variant) + " computes at " +
                              arealight::to_string(arealight::effective_precision(*variant))});
        return kBadInput;
    }
    auto evaluator = arealight::Evaluator::create(opt, print_diagnostic);
    if (!evaluator) return kRuntime;
    arealight::EvalStats stats;
    auto results = evaluator->run(*variant, *cases, print_diagnostic, &stats);
    if (!results) return kRuntime;
    if (!arealight::write_results(out_path, *results, print_diagnostic)) return kRuntime;
    fmt::print(stderr, "eval: {} cases on {}, {} not applicable to {}\n", stats.evaluated, backend,
               stats.skipped, arealight::canonical_name(*variant));
    return kOk;
}

int run_compare(const std::string& ref_path, const std::string& out_path, double floor) {
    auto ref = arealight::read_results(ref_path, print_diagnostic);
    auto out = arealight::read_results(out_path, print_diagnostic);
    if (!ref || !out) return kBadInput;
    fmt::print("{} ({}) against {}\n", out_path, out->variant, ref_path);
    fmt::print("{}", arealight::format_scores(arealight::score_results(*ref, *out, floor)));
    return kOk;
}

int run_bench(const std::string& cases_path, const std::vector<std::string>& names,
              const std::vector<double>& exponents, const std::string& backend,
              std::size_t min_cases, int repeats, const std::string& gpu_family,
              const std::string& gpu_cache) {
    arealight::BenchOptions opt;
    opt.gpu->family = gpu_family;
    opt.gpu->cache_dir = gpu_cache;
    for (const auto& name : names) {
        auto v = arealight::parse_variant(name, print_diagnostic);
        if (!v) return kBadInput;
        opt.variants.push_back(*v);
    }
    auto cases = arealight::read_cases(cases_path, print_diagnostic);
    if (!cases) return kBadInput;
    opt.exponents = exponents;
    opt.min_cases = min_cases;
    opt.repeats = repeats;
    // Before any Vulkan call: Mesa reads its cache location once per process.
    // Declared before the evaluator, so that it outlives every Vulkan object.
    std::optional<arealight::PrivateShaderCache> cache;
    if (backend == "vulkan") opt.shader_cache_dir = cache.emplace().path();
    arealight::EvalOptions eo;
    eo.backend = backend == "cpu" ? arealight::Backend::Cpu : arealight::Backend::Vulkan;
    auto ev = arealight::Evaluator::create(eo, print_diagnostic);
    if (!ev) return kRuntime;
    ProgressPrinter progress("bench", "timed runs");
    auto rows = arealight::benchmark(*ev, *cases, opt, print_diagnostic,
                                     [&](std::size_t d, std::size_t t) { progress(d, t); });
    if (!rows) return kRuntime;
    fmt::print("{}", arealight::format_bench(*rows));
    return kOk;
}

// Reads and concatenates case files; ids must be unique across them.
std::optional<arealight::CaseSet> read_case_files(const std::vector<std::string>& paths) {
    arealight::CaseSet all;
    std::map<std::string, std::string> seen;  // id -> file
    for (const auto& path : paths) {
        auto set = arealight::read_cases(path, print_diagnostic);
        if (!set) return std::nullopt;
        for (auto& c : set->cases) {
            auto [it, fresh] = seen.emplace(c.id, path);
            if (!fresh) {
                print_diagnostic(
                    {arealight::Severity::Error, path, 0,
                     fmt::format("{}: case '{}': id already used in {}", path, c.id, it->second)});
                return std::nullopt;
            }
            all.cases.push_back(std::move(c));
        }
    }
    return all;
}

struct ReportArgs {
    std::vector<std::string> cases, refs;
    std::string pattern, out_dir;
    std::string axis = "param";             // sweep: param or view
    std::vector<double> values, exponents;  // sweep: --value, --exponent
    int repeats = 7;
    double dispatch_ms = 20;
    unsigned threads = 1;
    std::string gpu_family = arealight::GpuCostOptions{}.family;
    std::string gpu_cache;
};

// The options report and sweep share.
void add_measure_options(CLI::App* cmd, ReportArgs& a) {
    cmd->add_option("--cases", a.cases, "arealight-cases/1 file (repeatable)")->required();
    cmd->add_option("--variants", a.pattern, "variant pattern, e.g. dist=phong,light=polygon")
        ->required();
    cmd->add_option("--out", a.out_dir, "folder to write into (created)")->required();
    cmd->add_option("--repeat", a.repeats, "timed dispatches per variant (median)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    cmd->add_option("--dispatch-ms", a.dispatch_ms, "target length of a timed dispatch")
        ->check(CLI::Range(1.0, 10000.0))
        ->capture_default_str();
    cmd->add_option("--threads", a.threads, "oracle threads")
        ->check(CLI::Range(1u, 256u))
        ->capture_default_str();
    arealight::cli::add_gpu_family_option(cmd, a.gpu_family);
    arealight::cli::add_gpu_cache_option(cmd, a.gpu_cache);
}

// report and sweep: measure, then write every file (nothing is written on failure).
int run_report(const ReportArgs& a, bool sweep) {
    auto cases = read_case_files(a.cases);
    if (!cases) return kBadInput;
    std::vector<arealight::Variant> matching;
    for (const auto& v : arealight::enumerate_variants())
        if (arealight::variant_matches(v, a.pattern)) matching.push_back(v);
    if (matching.empty()) {
        print_diagnostic(
            {arealight::Severity::Error, "", 0,
             fmt::format("no variant matches '{}' (arealight variants lists them)", a.pattern)});
        return kBadInput;
    }
    arealight::ReportOptions opt;
    opt.pattern = a.pattern;
    opt.repeats = a.repeats;
    opt.dispatch_seconds = a.dispatch_ms * 1e-3;
    opt.threads = a.threads;
    opt.gpu->family = a.gpu_family;
    opt.gpu->cache_dir = a.gpu_cache;
    if (sweep) {
        auto bad = [&](const std::string& m) {
            print_diagnostic({arealight::Severity::Error, "", 0, "sweep: " + m});
            return kBadInput;
        };
        const auto axis = arealight::parse_sweep_axis(a.axis);
        if (!axis) return bad(fmt::format("--axis '{}': expected param or view", a.axis));
        opt.axis = *axis;
        std::set<arealight::Distribution> dists;
        for (const auto& v : matching) dists.insert(v.dist);
        std::string names;
        for (auto d : dists)
            names += std::string(names.empty() ? "" : ", ") + arealight::to_string(d);
        // The range a value must lie in, and what it is called.
        double lo = 0, hi = 1;
        std::string what = "cos θ_v";
        if (opt.axis == arealight::SweepAxis::Param) {
            if (dists.size() > 1)
                return bad(fmt::format(
                    "--axis param: the variants matching '{}' span several distributions ({}), "
                    "whose parameters differ; add dist=... to the pattern, or sweep --axis view",
                    a.pattern, names));
            const auto& p = arealight::sweep_parameter(*dists.begin());
            lo = p.min;
            hi = p.max;
            what = p.field;
            if (!a.exponents.empty() && p.field != "exponent")
                return bad(
                    fmt::format("--exponent: {} has no exponent; its parameter is {} (--value)",
                                names, p.field));
        } else if (!a.exponents.empty()) {
            return bad("--exponent sweeps the exponent: it needs --axis param");
        }
        opt.values = a.values;
        opt.values.insert(opt.values.end(), a.exponents.begin(), a.exponents.end());
        for (double x : opt.values) {
            const bool ok =
                opt.axis == arealight::SweepAxis::View ? x > 0 && x <= 1 : x >= lo && x <= hi;
            if (!ok || !std::isfinite(x))
                return bad(fmt::format("value {:g}: {} must lie in {}{:g}, {:g}]", x, what,
                                       opt.axis == arealight::SweepAxis::View ? "(" : "[", lo, hi));
        }
    }
    if (!a.refs.empty()) {
        arealight::ResultSet ref;
        for (const auto& path : a.refs) {
            auto r = arealight::read_results(path, print_diagnostic);
            if (!r) return kBadInput;
            ref.results.insert(ref.results.end(), r->results.begin(), r->results.end());
        }
        // Every case a matching variant will run needs its oracle value.
        std::set<std::string> have;
        for (const auto& r : ref.results) have.insert(r.id);
        for (const auto& c : cases->cases) {
            const bool used = std::any_of(
                matching.begin(), matching.end(),
                [&](const arealight::Variant& v) { return arealight::case_applies(v, c); });
            if (used && !have.count(c.id)) {
                print_diagnostic({arealight::Severity::Error, "", 0,
                                  fmt::format("case '{}' has no value in the --ref files", c.id)});
                return kBadInput;
            }
        }
        opt.reference = ref;
    }
    // Before any Vulkan call: Mesa reads its cache location once per process.
    // Declared before the evaluator, so that it outlives every Vulkan object.
    arealight::PrivateShaderCache cache;
    opt.shader_cache_dir = cache.path();
    arealight::EvalOptions eo;
    auto ev = arealight::Evaluator::create(eo, print_diagnostic);
    if (!ev) return kRuntime;
    std::map<std::string, std::unique_ptr<ProgressPrinter>> printers;
    auto progress = [&](const std::string& phase, std::size_t done, std::size_t total) {
        auto& p = printers[phase];
        // compile and time count variants; the oracle phases ("reference ...") cases.
        if (!p)
            p = std::make_unique<ProgressPrinter>(
                phase, phase.rfind("reference", 0) == 0 ? "cases" : "variants");
        (*p)(done, total);
    };
    auto report = arealight::run_report(*ev, *cases, opt, print_diagnostic, progress);
    if (!report) return kRuntime;
    report->case_files = a.cases;
    report->device = ev->device_name();
    const std::string stem = sweep ? "sweep" : "report";
    std::vector<std::pair<std::string, std::string>> files = {
        {stem + ".json", arealight::report_json(*report)},
        {stem + ".md", arealight::report_markdown(*report)}};
    for (auto& pic : arealight::report_pictures(*report)) files.push_back(std::move(pic));
    std::error_code ec;
    std::filesystem::create_directories(a.out_dir, ec);
    for (const auto& [name, text] : files) {
        if (!arealight::write_file_atomic(a.out_dir + "/" + name, text, print_diagnostic))
            return kRuntime;
    }
    fmt::print(stderr, "{}: {} rows in {:.0f} s; wrote", stem, report->rows.size(),
               report->seconds);
    for (const auto& f : files) fmt::print(stderr, " {}/{}", a.out_dir, f.first);
    fmt::print(stderr, "\n");
    return kOk;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "arealight: analytic area-light shading, generated as GLSL/SPIR-V and checked "
        "against an independent oracle"};
    app.require_subcommand(1);
    app.footer("Exit codes: 0 ok, 1 bad input, 2 usage, 3 runtime/device failure.");

    auto* variants = app.add_subcommand("variants", "List every valid variant name, one per line");

    std::string cases_path, out_path, variant, backend = "vulkan", device, eval_lang = "glsl";
    auto* eval = app.add_subcommand("eval", "Run one shader variant on every case it applies to");
    eval->add_option("--cases", cases_path, "arealight-cases/1 file")->required();
    eval->add_option("--variant", variant,
                     "variant name, e.g. dist=phong,method=exact,light=polygon")
        ->required();
    eval->add_option("--backend", backend, "cpu (the CPU mirror) or vulkan (the SPIR-V)")
        ->check(CLI::IsMember({"cpu", "vulkan"}))
        ->capture_default_str();
    eval->add_option("--device", device, "Vulkan device name substring (default: first device)");
    eval->add_option("--lang", eval_lang,
                     "vulkan: run the kernel around the GLSL library or the HLSL one (fp32 "
                     "variants; glslang's HLSL front end)")
        ->check(CLI::IsMember({"glsl", "hlsl"}))
        ->capture_default_str();
    eval->add_option("--out", out_path, "arealight-results/1 file to write")->required();

    arealight::cli::GenerateArgs generate_args;
    auto* generate = arealight::cli::add_generate_command(app, generate_args);

    double rel_tol = 1e-10;
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    auto* reference = app.add_subcommand(
        "reference", "Compute the oracle values (adaptive cubature) of every case");
    reference->add_option("--cases", cases_path, "arealight-cases/1 file")->required();
    reference->add_option("--out", out_path, "arealight-results/1 file to write")->required();
    reference->add_option("--tolerance", rel_tol, "requested relative accuracy")
        ->check(CLI::Range(1e-14, 1e-2))
        ->capture_default_str();
    reference->add_option("--threads", threads, "worker threads")
        ->check(CLI::Range(1u, 256u))
        ->capture_default_str();
    bool table = false;
    reference->add_flag("--table", table, "print every case's values on stdout");

    std::string ref_path;
    double floor = 1e-3;
    auto* compare = app.add_subcommand(
        "compare", "Error table of a results file against a reference (shared/tools/score metric)");
    compare->add_option("--ref", ref_path, "reference results file")->required();
    compare->add_option("--out", out_path, "results file to judge")->required();
    compare->add_option("--floor", floor, "absolute floor of the relative error")
        ->capture_default_str();

    std::vector<std::string> bench_variants;
    std::vector<double> exponents;
    std::size_t min_cases = 1 << 16;
    int repeats = 9;
    auto* bench = app.add_subcommand(
        "bench", "Time variants side by side (median of interleaved repeats, ratio to the first)");
    bench->add_option("--cases", cases_path, "arealight-cases/1 file")->required();
    bench
        ->add_option("--variant", bench_variants, "variant (repeatable); the first is the baseline")
        ->required();
    bench->add_option("--exponent", exponents, "override the exponent of every case (repeatable)");
    bench->add_option("--backend", backend, "cpu or vulkan")
        ->check(CLI::IsMember({"cpu", "vulkan"}))
        ->capture_default_str();
    bench->add_option("--min-cases", min_cases, "cases per dispatch (repeating the file)")
        ->capture_default_str();
    bench->add_option("--repeat", repeats, "timed runs per variant")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    std::string bench_gpu_family = arealight::GpuCostOptions{}.family;
    arealight::cli::add_gpu_family_option(bench, bench_gpu_family);
    std::string bench_gpu_cache;
    arealight::cli::add_gpu_cache_option(bench, bench_gpu_cache);

    ReportArgs rep, swp;
    rep.threads = swp.threads = threads;
    auto* report = app.add_subcommand(
        "report",
        "Error against cost of every variant matching a pattern (Phong and microfacet: blinn, "
        "beckmann, ggx): SPIR-V and lavapipe x86-64 instruction counts, time ratio to the "
        "point light of the same distribution and shape (dist=<same>,method=point, same "
        "sided/verts where that variant exists, else the family's default shape), error "
        "against the oracle per quantity: diffuse, specular, and moment (phong) or ndf "
        "(microfacet); the plots' error is the larger relL2 of specular and moment or ndf; "
        "and the GPU cost (RADV/ACO on a null device, CONTRACT.md 4) with its ratio to the "
        "point light, the cost of the front and report.svg where RADV is available. Writes "
        "report.json, report.md, report.svg, report_time.svg (with the GPU cost), "
        "report_x86.svg");
    add_measure_options(report, rep);
    report->add_option("--ref", rep.refs,
                       "oracle results of the cases (repeatable); default: computed here");
    auto* sweep = app.add_subcommand(
        "sweep",
        "Cost and error against one axis, every case overridden along it in turn, the oracle "
        "recomputed per value, for the variants matching a pattern. --axis param (default): "
        "the distribution's parameter: exponent N for phong and blinn (10^0, 10^0.5, ..., "
        "10^5), alpha for beckmann and ggx (0.001, 0.002, 0.005, ..., 0.5, 1); the variants "
        "must share one distribution (else exit 1). --axis view: each case's v rotated in the "
        "plane of n and v to cos(theta_v) = 1, 0.9, 0.7, 0.5, 0.3, 0.2, 0.1, 0.05, 0.02, 0.01 "
        "(normal to grazing); any distributions. Time is the ratio to the point light of the "
        "same distribution and shape; error the larger relL2 of specular and moment (phong) or "
        "ndf (microfacet). Writes sweep.json, sweep.md, sweep_time.svg, sweep_error.svg, the x "
        "axis named by the axis");
    add_measure_options(sweep, swp);
    sweep
        ->add_option("--axis", swp.axis,
                     "param (exponent or alpha of the variants' distribution) or view "
                     "(cos theta_v); another value is exit 1")
        ->capture_default_str();
    sweep->add_option("--value", swp.values,
                      "values to sweep (repeatable; default the axis's table above): exponent "
                      "in [1, 100000], alpha in [0.001, 1], cos theta_v in (0, 1]");
    sweep
        ->add_option("--exponent", swp.exponents,
                     "exponents to sweep, as --value (repeatable; --axis param on phong or "
                     "blinn only)")
        ->check(CLI::Range(1.0, 100000.0));
    arealight::cli::ReplotArgs replot_args;
    auto* replot = arealight::cli::add_replot_command(app, replot_args);
    arealight::cli::FitLtcArgs fit_args;
    auto* fit_ltc = arealight::cli::add_fit_ltc_command(app, fit_args);
    arealight::cli::QualityArgs quality_args;
    auto* quality = arealight::cli::add_quality_command(app, quality_args);
    arealight::cli::SceneVariantsArgs scene_args;
    auto* scene_variants = arealight::cli::add_scene_variants_command(app, scene_args);
    arealight::cli::RenderArgs render_args;
    auto* render = arealight::cli::add_render_command(app, render_args);
    arealight::cli::GpuCostArgs gpu_cost_args;
    auto* gpu_cost = arealight::cli::add_gpu_cost_command(app, gpu_cost_args);
    arealight::cli::CompileArgs compile_args;
    auto* compile = arealight::cli::add_compile_command(app, compile_args);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return kUsage;
    }

    if (variants->parsed()) return run_variants();
    if (report->parsed()) return run_report(rep, false);
    if (sweep->parsed()) return run_report(swp, true);
    if (replot->parsed()) return arealight::cli::run_replot(replot_args);
    if (eval->parsed()) return run_eval(cases_path, variant, backend, device, eval_lang, out_path);
    if (generate->parsed()) return arealight::cli::run_generate(generate_args, print_diagnostic);
    if (bench->parsed())
        return run_bench(cases_path, bench_variants, exponents, backend, min_cases, repeats,
                         bench_gpu_family, bench_gpu_cache);
    if (compare->parsed()) return run_compare(ref_path, out_path, floor);
    if (reference->parsed()) return run_reference(cases_path, out_path, rel_tol, threads, table);
    if (fit_ltc->parsed()) return arealight::cli::run_fit_ltc(fit_args);
    if (quality->parsed()) return arealight::cli::run_quality(quality_args);
    if (scene_variants->parsed()) return arealight::cli::run_scene_variants(scene_args);
    if (render->parsed()) return arealight::cli::run_render(render_args);
    if (compile->parsed()) return arealight::cli::run_compile(compile_args);
    if (gpu_cost->parsed()) return arealight::cli::run_gpu_cost(gpu_cost_args);
    return kUsage;
}
