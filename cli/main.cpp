// arealight command line (CONTRACT.md section 4): every subcommand's options and help,
// parsing, and the call of the subcommand's run function (cli/<subcommand>.cpp), which calls
// the library. The one file that includes CLI11: version 2.1 is header-only, and each file
// that included it took 5.5 s to compile at -O1 and 7.4 s under ASan.
//
// Exit codes: 0 success, 1 bad input (malformed case file, unknown variant),
// 2 usage error, 3 runtime or device failure (write failure, no Vulkan device).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <string>
#include <thread>
#include <vector>

#include "arealight/gpu_cost.hpp"
#include "bench.hpp"
#include "compile.hpp"
#include "eval.hpp"
#include "exit_code.hpp"
#include "fit_ltc.hpp"
#include "generate.hpp"
#include "generate_scene.hpp"
#include "gpu_cost.hpp"
#include "print_diagnostic.hpp"
#include "quality.hpp"
#include "reference.hpp"
#include "render.hpp"
#include "replot.hpp"
#include "report.hpp"

namespace arealight::cli {

namespace {

// The GPU cost's options, which report, sweep, bench, quality and gpu-cost share:
// `--gpu-family`, the RADV chip it is compiled for, checked against the names the driver
// knows before it ever sees one (an unknown name aborts it); `--gpu-cache DIR` (or
// AREALIGHT_GPU_CACHE), GpuCostOptions::cache_dir, created when missing.
void add_gpu_options(CLI::App* cmd, std::string& family, std::string& cache_dir) {
    std::string names;
    for (const auto& f : radv_families()) names += (names.empty() ? "" : " ") + f;
    cmd->add_option("--gpu-family", family,
                    "RADV chip family the GPU cost is compiled for (RADV_FORCE_FAMILY, null "
                    "device): " +
                        names)
        ->check(CLI::Validator(
            [](std::string& s) {
                return is_radv_family(s) ? std::string() : "'" + s + "' is not a RADV chip family";
            },
            "FAMILY"))
        ->capture_default_str();
    cmd->add_option("--gpu-cache", cache_dir,
                    "folder that keeps RADV's statistics per module, so that a module "
                    "compiled once (in any run) is not compiled again; default: none")
        ->envname("AREALIGHT_GPU_CACHE");
}

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
    add_gpu_options(cmd, a.gpu_family, a.gpu_cache);
}

CLI::App* add_compile_command(CLI::App& app, CompileArgs& args) {
    auto* cmd = app.add_subcommand(
        "compile",
        "Compile a GLSL or HLSL shader that may #include arealight libraries to validated, "
        "optimized SPIR-V (Vulkan 1.1, SPIR-V 1.3 unless --target-env says otherwise). GLSL's "
        "stage comes from the extension (.vert .tesc .tese .geom .frag .comp); a .hlsl file "
        "is HLSL (glslang's HLSL front end, then SPIRV-Tools' legalization), its stage from "
        "the extension before .hlsl (x.frag.hlsl) or --stage, its entry function -E. "
        "#include \"name\" is searched beside the including file, then in each -I folder; "
        "no #extension line is needed. Nothing is written on error");
    cmd->add_option("shader", args.shader, "GLSL or HLSL (.hlsl) source file")->required();
    cmd->add_option("-o,--out", args.out, "SPIR-V file to write")->required();
    cmd->add_option("-I,--include-dir", args.include_dirs, "include folder (repeatable, in order)");
    cmd->add_option("--stage", args.stage, "stage when the extension does not say it")
        ->check(CLI::IsMember({"vert", "tesc", "tese", "geom", "frag", "comp"}));
    cmd->add_option("--depfile", args.depfile,
                    "also write a Makefile rule: OUT depends on SHADER and every included file "
                    "(CMake's DEPFILE, ninja's depfile)");
    cmd->add_option("-E,--entry", args.entry,
                    "HLSL: the entry function (default main); the module's entry point is "
                    "named main");
    cmd->add_option("--target-env", args.target_env,
                    "Vulkan version the SPIR-V is for: vulkan1.0 (SPIR-V 1.0), vulkan1.1 (1.3, "
                    "the default), vulkan1.2 (1.5), vulkan1.3 (1.6)")
        ->check(CLI::IsMember({"vulkan1.0", "vulkan1.1", "vulkan1.2", "vulkan1.3"}));
    cmd->add_flag("--no-opt", args.no_opt, "skip the SPIRV-Tools performance passes");
    return cmd;
}

CLI::App* add_fit_ltc_command(CLI::App& app, FitLtcArgs& args) {
    auto* cmd = app.add_subcommand(
        "fit-ltc",
        "Fit a distribution's linearly transformed cosines table (data/ltc/ltc_DIST.txt): "
        "Nelder-Mead per (roughness, view) cell, each from its neighbour's solution");
    cmd->add_option("--dist", args.dist, "phong, blinn, beckmann or ggx")
        ->required()
        ->check(CLI::IsMember({"phong", "blinn", "beckmann", "ggx"}));
    cmd->add_option("--size", args.size, "cells per axis")
        ->check(CLI::Range(2, 1024))
        ->capture_default_str();
    cmd->add_option("--threads", args.threads,
                    "worker threads (0: all cores); the table does not depend on it")
        ->check(CLI::Range(0u, 256u))
        ->capture_default_str();
    cmd->add_option("--out", args.out, "table file to write")->required();
    return cmd;
}

CLI::App* add_generate_command(CLI::App& app, GenerateArgs& args) {
    auto* cmd = app.add_subcommand(
        "generate",
        "Write a variant's validation kernel (GLSL and/or SPIR-V; GLSL on stdout when no file "
        "is given), or with --library the includable shading library of CONTRACT.md 5");
    auto* variant = cmd->add_option("--variant", args.variants,
                                    "variant name (repeatable with --library: one per light "
                                    "type and distribution)");
    cmd->add_option("--scene", args.scene,
                    "with --library: the variants an arealight-scene/1 file needs (CONTRACT.md "
                    "7), each the cheapest that meets its quality by the measured data built in")
        ->excludes(variant);
    cmd->add_option("--glsl", args.glsl, "kernel GLSL file to write (one variant)");
    cmd->add_option("--hlsl", args.hlsl,
                    "the HLSL validation kernel to write (one fp32 variant): the HLSL library "
                    "around templates/library/kernel.hlsl");
    cmd->add_option("--spv", args.spv, "kernel SPIR-V file to write (one variant)");
    cmd->add_option("--library", args.library,
                    "write the shading library (GLSL or, with --lang hlsl, HLSL to #include, "
                    "CONTRACT.md 5) here");
    cmd->add_option("--lang", args.lang,
                    "the library's language: glsl (4.50; also GLSL ES 3.10) or hlsl (Shader "
                    "Model 6 syntax, fp32 variants)")
        ->check(CLI::IsMember({"glsl", "hlsl"}))
        ->capture_default_str();
    cmd->add_option("--tables", args.tables,
                    "with --library: write the tables its samplers read, and tables.json, "
                    "into this folder");
    cmd->add_flag("--no-opt", args.no_opt, "skip the SPIRV-Tools performance passes");
    return cmd;
}

CLI::App* add_scene_variants_command(CLI::App& app, SceneVariantsArgs& args) {
    auto* cmd = app.add_subcommand(
        "scene-variants",
        "List the variants a scene (arealight-scene/1) needs: one per light type and "
        "distribution, the cheapest meeting its quality by the measured data built in "
        "(data/quality/measured.json), specialised to its sidedness and largest polygon");
    cmd->add_option("--scene", args.scene, "scene file")->required();
    return cmd;
}

CLI::App* add_gpu_cost_command(CLI::App& app, GpuCostArgs& args) {
    auto* cmd = app.add_subcommand(
        "gpu-cost",
        "Print the GPU cost (RADV/ACO on a null device, CONTRACT.md 4) of variants' kernels "
        "as `generate --spv` writes them, with their ratio to the point light, or of SPIR-V "
        "files: one JSON line each");
    cmd->add_option("--variant", args.variants, "variant name (repeatable)");
    cmd->add_option("--spv", args.spv, "SPIR-V compute module (repeatable)")
        ->check(CLI::ExistingFile);
    add_gpu_options(cmd, args.gpu_family, args.gpu_cache);
    return cmd;
}

CLI::App* add_quality_command(CLI::App& app, QualityArgs& args) {
    auto* cmd = app.add_subcommand(
        "quality",
        "Collect the measured error and cost of every variant in report JSON files into the "
        "quality data scene selection ranks by (arealight-quality/1; a variant in several "
        "reports takes the last one's row)");
    cmd->add_option("--report", args.reports, "report.json of `arealight report` (repeatable)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--out", args.out, "quality file to write (data/quality/measured.json)")
        ->required();
    add_gpu_options(cmd, args.gpu_family, args.gpu_cache);
    return cmd;
}

CLI::App* add_render_command(CLI::App& app, RenderArgs& a) {
    auto* cmd = app.add_subcommand(
        "render",
        "Render a scene (arealight-scene/1 plus camera and objects, see examples/scene.json) "
        "through the shading library: one camera ray per pixel, then every visible point and "
        "light a case, each variant's cases in one batch. Pixel = sum over lights of "
        "intensity * (albedo * diffuse + specular); no shadows. The PNG is exposure * radiance "
        "clamped to [0, 1], sRGB-encoded. With --compare, prints the image's error against a "
        "linear reference (luminance: relL2, and median / p95 / max of "
        "|Y - Y_ref| / max(Y_ref, floor)) and writes that per-pixel error in false colour "
        "(viridis, log scale 1e-4 .. 1, colour bar with decade labels below the picture)");
    cmd->add_option("--scene", a.scene, "scene file")->required();
    cmd->add_option("--out", a.out, "PNG file to write")->required();
    auto* variant = cmd->add_option(
        "--variant", a.variants,
        "variant for the lights and materials of its dist and light (repeatable, one per "
        "pair); default: the scene's selection, as 'arealight generate --scene' makes it "
        "(quality.method, quality.max_error, default 0.02, by the measured data built in)");
    cmd->add_flag("--reference", a.reference,
                  "shade with the oracle (arealight reference) instead of a variant")
        ->excludes(variant);
    cmd->add_option("--size", a.size, "image width and height in pixels")
        ->expected(2)
        ->check(CLI::Range(1, 8192))
        ->capture_default_str();
    cmd->add_option("--backend", a.backend, "cpu (the CPU mirror) or vulkan (the SPIR-V)")
        ->check(CLI::IsMember({"cpu", "vulkan"}))
        ->capture_default_str();
    cmd->add_option("--device", a.device, "Vulkan device name substring (default: first)");
    cmd->add_option("--exposure", a.exposure, "radiance multiplier before the sRGB encoding")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--linear", a.linear,
                    "also write the linear radiance: a colour PFM (little-endian float RGB, "
                    "rows bottom to top)");
    cmd->add_option("--compare", a.compare,
                    "linear reference (a PFM from --linear, e.g. of a --reference render) to "
                    "measure the error against");
    cmd->add_option("--diff", a.diff,
                    "error image to write with --compare (default: OUT with _diff before .png)");
    cmd->add_option("--floor", a.floor, "luminance floor of the relative error")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--tolerance", a.tolerance, "--reference: the oracle's relative accuracy")
        ->check(CLI::Range(1e-14, 1e-1))
        ->capture_default_str();
    cmd->add_option("--threads", a.threads, "--reference: worker threads (0: every core)")
        ->check(CLI::Range(0u, 256u))
        ->capture_default_str();
    return cmd;
}

CLI::App* add_replot_command(CLI::App& app, ReplotArgs& args) {
    auto* cmd = app.add_subcommand(
        "replot",
        "Draw a report's or sweep's markdown and pictures again from its JSON (DIR/report.json "
        "or DIR/sweep.json), with today's plots and marks (Pareto front, recommended "
        "variant), without measuring again; the JSON is rewritten with the marks");
    cmd->add_option("dirs", args.dirs, "folders that arealight report or sweep wrote")->required();
    return cmd;
}

CLI::App* add_eval_command(CLI::App& app, EvalArgs& a) {
    auto* cmd = app.add_subcommand("eval", "Run one shader variant on every case it applies to");
    cmd->add_option("--cases", a.cases, "arealight-cases/1 file")->required();
    cmd->add_option("--variant", a.variant,
                    "variant name, e.g. dist=phong,method=exact,light=polygon")
        ->required();
    cmd->add_option("--backend", a.backend, "cpu (the CPU mirror) or vulkan (the SPIR-V)")
        ->check(CLI::IsMember({"cpu", "vulkan"}))
        ->capture_default_str();
    cmd->add_option("--device", a.device, "Vulkan device name substring (default: first device)");
    cmd->add_option("--lang", a.lang,
                    "vulkan: run the kernel around the GLSL library or the HLSL one (fp32 "
                    "variants; glslang's HLSL front end)")
        ->check(CLI::IsMember({"glsl", "hlsl"}))
        ->capture_default_str();
    cmd->add_option("--out", a.out, "arealight-results/1 file to write")->required();
    return cmd;
}

CLI::App* add_reference_command(CLI::App& app, ReferenceArgs& a) {
    auto* cmd = app.add_subcommand("reference",
                                   "Compute the oracle values (adaptive cubature) of every case");
    cmd->add_option("--cases", a.cases, "arealight-cases/1 file")->required();
    cmd->add_option("--out", a.out, "arealight-results/1 file to write")->required();
    cmd->add_option("--tolerance", a.rel_tol, "requested relative accuracy")
        ->check(CLI::Range(1e-14, 1e-2))
        ->capture_default_str();
    cmd->add_option("--threads", a.threads, "worker threads")
        ->check(CLI::Range(1u, 256u))
        ->capture_default_str();
    cmd->add_flag("--table", a.table, "print every case's values on stdout");
    return cmd;
}

CLI::App* add_compare_command(CLI::App& app, CompareArgs& a) {
    auto* cmd = app.add_subcommand(
        "compare", "Error table of a results file against a reference (shared/tools/score metric)");
    cmd->add_option("--ref", a.ref, "reference results file")->required();
    cmd->add_option("--out", a.out, "results file to judge")->required();
    cmd->add_option("--floor", a.floor, "absolute floor of the relative error")
        ->capture_default_str();
    return cmd;
}

CLI::App* add_bench_command(CLI::App& app, BenchArgs& a) {
    auto* cmd = app.add_subcommand(
        "bench", "Time variants side by side (median of interleaved repeats, ratio to the first)");
    cmd->add_option("--cases", a.cases, "arealight-cases/1 file")->required();
    cmd->add_option("--variant", a.variants, "variant (repeatable); the first is the baseline")
        ->required();
    cmd->add_option("--exponent", a.exponents, "override the exponent of every case (repeatable)");
    cmd->add_option("--backend", a.backend, "cpu or vulkan")
        ->check(CLI::IsMember({"cpu", "vulkan"}))
        ->capture_default_str();
    cmd->add_option("--min-cases", a.min_cases, "cases per dispatch (repeating the file)")
        ->capture_default_str();
    cmd->add_option("--repeat", a.repeats, "timed runs per variant")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    add_gpu_options(cmd, a.gpu_family, a.gpu_cache);
    return cmd;
}

CLI::App* add_report_command(CLI::App& app, ReportArgs& a) {
    auto* cmd = app.add_subcommand(
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
    add_measure_options(cmd, a);
    cmd->add_option("--ref", a.refs,
                    "oracle results of the cases (repeatable); default: computed here");
    return cmd;
}

CLI::App* add_sweep_command(CLI::App& app, ReportArgs& a) {
    auto* cmd = app.add_subcommand(
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
    add_measure_options(cmd, a);
    cmd->add_option("--axis", a.axis,
                    "param (exponent or alpha of the variants' distribution) or view "
                    "(cos theta_v); another value is exit 1")
        ->capture_default_str();
    cmd->add_option("--value", a.values,
                    "values to sweep (repeatable; default the axis's table above): exponent "
                    "in [1, 100000], alpha in [0.001, 1], cos theta_v in (0, 1]");
    cmd->add_option("--exponent", a.exponents,
                    "exponents to sweep, as --value (repeatable; --axis param on phong or "
                    "blinn only)")
        ->check(CLI::Range(1.0, 100000.0));
    return cmd;
}

}  // namespace

}  // namespace arealight::cli

int main(int argc, char** argv) {
    using namespace arealight::cli;
    CLI::App app{
        "arealight: analytic area-light shading, generated as GLSL/SPIR-V and checked "
        "against an independent oracle"};
    app.require_subcommand(1);
    app.footer("Exit codes: 0 ok, 1 bad input, 2 usage, 3 runtime/device failure.");

    // In `arealight --help`'s order.
    auto* variants = app.add_subcommand("variants", "List every valid variant name, one per line");
    EvalArgs eval_args;
    auto* eval = add_eval_command(app, eval_args);
    GenerateArgs generate_args;
    auto* generate = add_generate_command(app, generate_args);
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    ReferenceArgs reference_args;
    reference_args.threads = cores;
    auto* reference = add_reference_command(app, reference_args);
    CompareArgs compare_args;
    auto* compare = add_compare_command(app, compare_args);
    BenchArgs bench_args;
    auto* bench = add_bench_command(app, bench_args);
    ReportArgs report_args, sweep_args;
    report_args.threads = sweep_args.threads = cores;
    auto* report = add_report_command(app, report_args);
    auto* sweep = add_sweep_command(app, sweep_args);
    ReplotArgs replot_args;
    auto* replot = add_replot_command(app, replot_args);
    FitLtcArgs fit_args;
    auto* fit_ltc = add_fit_ltc_command(app, fit_args);
    QualityArgs quality_args;
    auto* quality = add_quality_command(app, quality_args);
    SceneVariantsArgs scene_args;
    auto* scene_variants = add_scene_variants_command(app, scene_args);
    RenderArgs render_args;
    auto* render = add_render_command(app, render_args);
    GpuCostArgs gpu_cost_args;
    auto* gpu_cost = add_gpu_cost_command(app, gpu_cost_args);
    CompileArgs compile_args;
    auto* compile = add_compile_command(app, compile_args);

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
    if (report->parsed()) return run_report(report_args, false);
    if (sweep->parsed()) return run_report(sweep_args, true);
    if (replot->parsed()) return run_replot(replot_args);
    if (eval->parsed()) return run_eval(eval_args);
    if (generate->parsed()) return run_generate(generate_args, print_diagnostic);
    if (bench->parsed()) return run_bench(bench_args);
    if (compare->parsed()) return run_compare(compare_args);
    if (reference->parsed()) return run_reference(reference_args);
    if (fit_ltc->parsed()) return run_fit_ltc(fit_args);
    if (quality->parsed()) return run_quality(quality_args);
    if (scene_variants->parsed()) return run_scene_variants(scene_args);
    if (render->parsed()) return run_render(render_args);
    if (compile->parsed()) return run_compile(compile_args);
    if (gpu_cost->parsed()) return run_gpu_cost(gpu_cost_args);
    return kUsage;
}
