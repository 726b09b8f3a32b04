#include "render.hpp"

#include <fmt/format.h>

#include <chrono>
#include <set>
#include <thread>

#include "arealight/atomic_file.hpp"
#include "arealight/error_image.hpp"
#include "arealight/pfm_image.hpp"
#include "arealight/png_image.hpp"
#include "arealight/render.hpp"
#include "arealight/tone_map.hpp"
#include "exit_code.hpp"
#include "print_diagnostic.hpp"
#include "progress.hpp"

namespace arealight::cli {

namespace {

// IMAGE.png -> IMAGE_diff.png (any other name: NAME_diff.png).
std::string default_diff_path(const std::string& out) {
    const std::string ext = ".png";
    const bool png = out.size() > ext.size() && out.compare(out.size() - ext.size(), ext.size(), ext) == 0;
    return (png ? out.substr(0, out.size() - ext.size()) : out) + "_diff.png";
}

}  // namespace

int run_render(const RenderArgs& a) {
    const auto start = std::chrono::steady_clock::now();
    auto scene = read_render_scene(a.scene, print_diagnostic);
    if (!scene) return kBadInput;
    RenderOptions opt;
    opt.width = a.size[0];
    opt.height = a.size[1];
    std::set<std::pair<LightType, Distribution>> given;
    for (const auto& name : a.variants) {
        auto v = parse_variant(name, print_diagnostic);
        if (!v) return kBadInput;
        if (!given.insert({v->light, v->dist}).second) {
            print_diagnostic({Severity::Error, "", 0,
                              fmt::format("--variant {}: a variant for dist={},light={} was "
                                          "already given",
                                          name, to_string(v->dist), to_string(v->light))});
            return kBadInput;
        }
        opt.variants.push_back(*v);
    }
    // Every other pair of the scene takes its selection, chosen here rather than in the
    // rendering so that a quality no measured variant meets is bad input, as it is to
    // generate --scene, and is reported before minutes of work.
    for (const auto& l : scene->lights) {
        for (const auto& m : scene->materials) {
            if (a.reference || !given.insert({l.type, m.distribution}).second) continue;
            auto s = render_variant(*scene, l.type, m.distribution, shipped_quality(),
                                    print_diagnostic);
            if (!s) return kBadInput;
            opt.variants.push_back(s->variant);
        }
    }
    std::optional<LinearImage> ref;
    if (!a.compare.empty()) {
        ref = read_pfm(a.compare, print_diagnostic);
        if (!ref) return kBadInput;
        // Before the rendering, which may take minutes.
        if (ref->width != a.size[0] || ref->height != a.size[1]) {
            print_diagnostic({Severity::Error, a.compare, 0,
                              fmt::format("{}: is {}x{}, the rendering (--size) {}x{}", a.compare,
                                          ref->width, ref->height, a.size[0], a.size[1])});
            return kBadInput;
        }
    }
    opt.reference = a.reference;
    opt.reference_options.rel_tol = a.tolerance;
    opt.reference_options.threads =
        a.threads ? a.threads : std::max(1u, std::thread::hardware_concurrency());

    std::unique_ptr<Evaluator> evaluator;
    if (!a.reference) {
        EvalOptions eo;
        eo.backend = a.backend == "cpu" ? Backend::Cpu : Backend::Vulkan;
        eo.device = a.device;
        evaluator = Evaluator::create(eo, print_diagnostic);
        if (!evaluator) return kRuntime;
    }
    ProgressPrinter progress("render reference", "cases");
    RenderStats stats;
    auto image = render(*scene, opt, evaluator.get(), print_diagnostic,
                        [&](std::size_t d, std::size_t t) { progress(d, t); }, &stats);
    if (!image) return kRuntime;

    std::optional<ImageError> err;
    ErrorScale scale;
    scale.floor = a.floor;
    if (ref) {
        err = compare_images(*image, *ref, scale, print_diagnostic);
        if (!err) return kBadInput;
    }
    // Every output is encoded before the first is written, so that a failure to encode
    // leaves none of them behind.
    const std::string diff = a.diff.empty() ? default_diff_path(a.out) : a.diff;
    std::vector<std::pair<std::string, std::string>> files;
    auto png = encode_png(tone_map(*image, a.exposure), a.out, print_diagnostic);
    if (!png) return kRuntime;
    files.emplace_back(a.out, std::move(*png));
    if (!a.linear.empty()) files.emplace_back(a.linear, format_pfm(*image));
    if (ref) {
        auto diff_png = encode_png(error_image(*image, *ref, scale), diff, print_diagnostic);
        if (!diff_png) return kRuntime;
        files.emplace_back(diff, std::move(*diff_png));
    }
    for (const auto& [path, bytes] : files)
        if (!write_file_atomic(path, bytes, print_diagnostic)) return kRuntime;

    const double total =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fmt::print("render: {} {}x{} on {}: {} cases, shading {:.2f} s, total {:.2f} s\n", a.scene,
               opt.width, opt.height, a.reference ? "the oracle" : evaluator->device_name(),
               stats.cases, stats.shading_seconds, total);
    std::string names;
    for (const auto& v : stats.variants) names += (names.empty() ? "" : "; ") + v;
    fmt::print("variants: {}\n", names);
    if (stats.unconverged)
        fmt::print("oracle: {} cases stopped by the evaluation budget before --tolerance\n",
                   stats.unconverged);
    if (err)
        fmt::print("error: relL2 {:.3e}, median {:.3e}, p95 {:.3e}, max {:.3e} against {} "
                   "(luminance, floor {:g}); wrote {}\n",
                   err->rel_l2, err->median, err->p95, err->max, a.compare, a.floor, diff);
    if (err && err->bad)
        fmt::print("error: {} pixels are not finite (magenta in {})\n", err->bad, a.out);
    return kOk;
}

}  // namespace arealight::cli
