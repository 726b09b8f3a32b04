#include "generate.hpp"

#include <fmt/format.h>

#include "arealight/atomic_file.hpp"
#include "arealight/compiler.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/generator.hpp"
#include "arealight/library_tables.hpp"
#include "arealight/scene_select.hpp"
#include "exit_code.hpp"

namespace arealight::cli {
namespace {

// Each function's comment line of measured error and cost, from the data built in
// (data/quality/measured.json, made from the reports by `arealight quality`).
LibraryOptions measured_comments(const std::vector<Variant>& variants) {
    LibraryOptions opt;
    for (const auto& v : variants) {
        const std::string name = canonical_name(v);
        const MeasuredVariant* m = shipped_quality().find(name);
        // A variant specialised to sidedness or polygon size computes the same values as
        // its general form on the lights it accepts: quote that one's measurement.
        Variant general = v;
        general.sided = Variant{}.sided;
        general.verts = Variant{}.verts;
        std::string as;
        if (!m && is_valid(general)) {
            m = shipped_quality().find(canonical_name(general));
            as = fmt::format(" for {}", canonical_name(general));
        }
        if (!m) continue;
        std::string errors;
        for (const auto& [quantity, value] : m->rel_l2)
            errors += fmt::format("{}{} {:.2g}", errors.empty() ? "" : ", ", quantity, value);
        opt.measured[name] = fmt::format(
            "Measured{} ({}, {} cases, relL2): {}. Cost on lavapipe: {} x86-64 instructions, "
            "{:.2g}x the point light's time.",
            as, m->report, m->cases, errors, m->x86_instructions, m->ratio_to_point);
    }
    return opt;
}

// The library of `variants`, checked by compiling it into each variant's kernel's
// stage (a written library is a library that compiles), then written.
int write_library(const std::vector<Variant>& variants, const GenerateArgs& args,
                  const DiagnosticConsumer& diag) {
    const Language lang = args.lang == "hlsl" ? Language::Hlsl : Language::Glsl;
    for (const auto& v : variants) {
        if (language_supports(lang, v)) continue;
        if (diag)
            diag({Severity::Error, "", 0,
                  fmt::format("generate: the HLSL library is fp32 only, and {} computes at {} "
                              "(name precision=fp32 where the family offers it)",
                              canonical_name(v), to_string(effective_precision(v)))});
        return kBadInput;
    }
    auto text = generate_library(variants, lang, measured_comments(variants), diag);
    if (!text) return kBadInput;
    for (const auto& v : variants) {
        const bool built = lang == Language::Hlsl ? build_hlsl_spirv(v, true, diag).has_value()
                                                  : build_spirv(v, true, diag).has_value();
        if (!built) return kRuntime;
    }
    if (!args.tables.empty() && !write_library_tables(variants, args.tables, diag)) return kRuntime;
    if (!write_file_atomic(args.library, *text, diag)) return kRuntime;
    return kOk;
}

}  // namespace

int run_generate(const GenerateArgs& args, const DiagnosticConsumer& diag) {
    auto usage = [&](const std::string& message) {
        if (diag) diag({Severity::Error, "", 0, "generate: " + message});
        return kUsage;
    };
    if (!args.scene.empty() && args.library.empty()) return usage("--scene needs --library");
    if (args.scene.empty() && args.variants.empty()) return usage("--variant or --scene is required");
    if (args.library.empty() && args.variants.size() != 1)
        return usage("one --variant, or --library for several");
    if (!args.library.empty() && (!args.glsl.empty() || !args.spv.empty() || !args.hlsl.empty()))
        return usage("--library writes a library; --glsl, --hlsl and --spv a single variant's "
                     "kernel");
    if (args.library.empty() && args.lang != "glsl")
        return usage("--lang chooses the library's language (with --library); a variant's "
                     "HLSL kernel is --hlsl FILE");
    if (args.library.empty() && !args.tables.empty()) return usage("--tables needs --library");
    std::vector<Variant> variants;
    if (!args.scene.empty()) {
        const auto scene = read_scene(args.scene, diag);
        if (!scene) return kBadInput;
        const auto selected = select_variants(*scene, shipped_quality(), diag);
        if (!selected) return kBadInput;
        for (const auto& s : *selected) {
            if (diag)
                diag({Severity::Note, "", 0,
                      fmt::format("{}: {}", canonical_name(s.variant), s.why)});
            variants.push_back(s.variant);
        }
    }
    for (const auto& name : args.variants) {
        auto v = parse_variant(name, diag);
        if (!v) return kBadInput;
        variants.push_back(*v);
    }
    if (!args.library.empty()) return write_library(variants, args, diag);

    const Variant& v = variants.front();
    const std::string glsl = generate_source(v, Language::Glsl);
    // Compile even when only GLSL is asked for: a written shader is a valid shader.
    auto spirv = generated_kernel_spirv(v, diag, !args.no_opt);
    if (!spirv) return kRuntime;
    if (args.glsl.empty() && args.spv.empty() && args.hlsl.empty()) fmt::print("{}", glsl);
    if (!args.glsl.empty() && !write_file_atomic(args.glsl, glsl, diag)) return kRuntime;
    if (!args.hlsl.empty()) {
        if (!language_supports(Language::Hlsl, v)) {
            if (diag)
                diag({Severity::Error, "", 0,
                      fmt::format("generate: the HLSL library is fp32 only, and {} computes at {}",
                                  canonical_name(v), to_string(effective_precision(v)))});
            return kBadInput;
        }
        if (!build_hlsl_spirv(v, !args.no_opt, diag, KernelOutputs::All)) return kRuntime;
        if (!write_file_atomic(args.hlsl, generate_hlsl_kernel(v, KernelOutputs::All), diag))
            return kRuntime;
    }
    if (!args.spv.empty()) {
        const std::string bytes(reinterpret_cast<const char*>(spirv->data()),
                                spirv->size() * sizeof(uint32_t));
        if (!write_file_atomic(args.spv, bytes, diag)) return kRuntime;
    }
    return kOk;
}

}  // namespace arealight::cli
