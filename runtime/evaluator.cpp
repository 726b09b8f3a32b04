#include "arealight/evaluator.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <exception>
#include <map>

#include "arealight/compiler.hpp"
#include "arealight/cpu_mirror.hpp"
#include "arealight/generator.hpp"
#include "arealight/spirv_cache.hpp"
#include "arealight/vulkan_runner.hpp"

namespace arealight {
namespace {

}  // namespace

const char* to_string(Backend b) {
    return b == Backend::Cpu ? "cpu" : "vulkan";
}

bool has_second_quantity(const Variant& v) {
    const VariantFamily* family = find_family(v);
    return family && family->second_quantity;
}

bool case_applies(const Variant& v, const Case& c) {
    if (c.material.distribution != v.dist || c.light.type != v.light) return false;
    if (v.light == LightType::Polygon && static_cast<int>(c.light.vertices.size()) > v.verts)
        return false;
    if (v.sided == Sided::One && c.light.two_sided) return false;
    if (v.sided == Sided::Two && !c.light.two_sided) return false;
    return true;
}

std::vector<float> pack_cases(const std::vector<const Case*>& cases) {
    std::vector<float> out(cases.size() * kFloatsPerCase, 0.0f);
    auto put = [](const Vec3& a, float* dst) {
        for (int k = 0; k < 3; ++k) dst[k] = static_cast<float>(a[k]);
    };
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const Case& c = *cases[i];
        float* o = &out[i * kFloatsPerCase];
        // The values as given, rounded to fp32, as a renderer holds them: the library
        // function does every per-point step itself (CONTRACT.md 5).
        put(c.p, o);
        put(c.n, o + 4);
        put(c.v, o + 8);
        const Material& m = c.material;
        const bool exponent =
            m.distribution == Distribution::Phong || m.distribution == Distribution::Blinn;
        o[12] = static_cast<float>(exponent ? m.exponent : m.alpha);
        // Schlick f0 (CONTRACT.md 2); 1 when the case has none, which makes F = 1 exactly.
        o[13] = static_cast<float>(m.f0);
        o[14] = c.light.two_sided ? 1.0f : 0.0f;
        // The light's slots (templates/library/kernel.glsl): a polygon's vertices, or a curved
        // light's centre and then its vectors.
        float* slots = o + 16;
        const Light& l = c.light;
        switch (l.type) {
            case LightType::Polygon:
                o[15] = static_cast<float>(l.vertices.size());
                for (std::size_t k = 0; k < l.vertices.size() && k < 8; ++k)
                    put(l.vertices[k], slots + 4 * k);
                break;
            case LightType::Disk:
                put(l.center, slots);
                put(l.u, slots + 4);
                put(l.v, slots + 8);
                break;
            case LightType::Sphere:
                put(l.center, slots);
                slots[4] = static_cast<float>(l.radius);
                break;
            case LightType::Ellipsoid:
                put(l.center, slots);
                for (int k = 0; k < 3; ++k) put(l.axes[k], slots + 4 + 4 * k);
                break;
        }
    }
    return out;
}

namespace {

// `diag` with every message prefixed (the variant a compiler message is about).
DiagnosticConsumer prefixed_consumer(std::string prefix, const DiagnosticConsumer& diag) {
    return [prefix = std::move(prefix), &diag](const Diagnostic& d) {
        if (!diag) return;
        Diagnostic p = d;
        p.message = prefix + d.message;
        diag(p);
    };
}

}  // namespace

std::optional<std::vector<uint32_t>> build_spirv(const Variant& v, bool optimize,
                                                 const DiagnosticConsumer& diag,
                                                 KernelOutputs outputs) {
    return build_spirv(v, generate_source(v, Language::Glsl, outputs), optimize, diag);
}

std::optional<std::vector<uint32_t>> generated_kernel_spirv(const Variant& v,
                                                            const DiagnosticConsumer& diag,
                                                            bool optimize) {
    return build_spirv(v, optimize, diag, KernelOutputs::All);
}

std::optional<std::vector<uint32_t>> build_spirv(const Variant& v, const std::string& glsl,
                                                 bool optimize, const DiagnosticConsumer& diag) {
    const std::string name = canonical_name(v);
    const DiagnosticConsumer prefixed = prefixed_consumer("variant " + name + ": ", diag);
    CompileOptions opt;
    opt.optimize = optimize;
    return compile_shader(glsl, name + ".comp", opt, prefixed);
}

namespace {

// False, with the diagnostic, for a variant the HLSL library does not hold.
bool hlsl_supports(const Variant& v, const DiagnosticConsumer& diag) {
    if (language_supports(Language::Hlsl, v)) return true;
    prefixed_consumer("variant " + canonical_name(v) + " (HLSL): ", diag)(
        {Severity::Error, "", 0,
         "the HLSL library is fp32 only: this variant computes at " +
             std::string(to_string(effective_precision(v)))});
    return false;
}

// The HLSL kernel text (generate_hlsl_kernel) of an fp32 variant through glslang's HLSL
// front end, legalized and optionally optimized.
std::optional<std::vector<uint32_t>> compile_hlsl_kernel(const Variant& v, const std::string& hlsl,
                                                         bool optimize,
                                                         const DiagnosticConsumer& diag) {
    const std::string name = canonical_name(v);
    const DiagnosticConsumer prefixed = prefixed_consumer("variant " + name + " (HLSL): ", diag);
    CompileOptions opt;
    opt.optimize = optimize;
    opt.language = SourceLanguage::Hlsl;
    return compile_shader(hlsl, name + ".comp.hlsl", opt, prefixed);
}

}  // namespace

std::optional<std::vector<uint32_t>> build_hlsl_spirv(const Variant& v, bool optimize,
                                                      const DiagnosticConsumer& diag,
                                                      KernelOutputs outputs) {
    if (!hlsl_supports(v, diag)) return std::nullopt;
    return compile_hlsl_kernel(v, generate_hlsl_kernel(v, outputs), optimize, diag);
}

struct Evaluator::Impl {
    EvalOptions opt;
    std::unique_ptr<VulkanRunner> runner;
    // By canonical name and kernel outputs.
    std::map<std::pair<std::string, KernelOutputs>, std::vector<uint32_t>> spirv;
};

Evaluator::Evaluator(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Evaluator::~Evaluator() = default;

std::string Evaluator::device_name() const {
    return impl_->runner ? impl_->runner->device_name() : "cpu mirror";
}

std::unique_ptr<Evaluator> Evaluator::create(const EvalOptions& opt,
                                             const DiagnosticConsumer& diag) {
    auto impl = std::make_unique<Impl>();
    impl->opt = opt;
    if (opt.backend == Backend::Vulkan) {
        impl->runner = VulkanRunner::create(opt.device, diag);
        if (!impl->runner) return nullptr;
    }
    return std::unique_ptr<Evaluator>(new Evaluator(std::move(impl)));
}

bool Evaluator::run_packed(const Variant& v, const std::vector<float>& packed, std::size_t count,
                           std::vector<float>& results, const DiagnosticConsumer& diag,
                           double* seconds, KernelOutputs outputs) {
    const std::string name = canonical_name(v);
    // The tables the variant samples, bound the same way on both backends.
    const auto found = variant_textures(v, diag);
    if (!found) return false;
    const std::vector<const Texture2D*>& textures = *found;
    if (impl_->opt.backend == Backend::Cpu) {
        const MirrorEntry* entry = find_mirror_entry(name);
        if (!entry) {
            if (diag) diag({Severity::Error, "", 0, "variant " + name + " has no CPU mirror"});
            return false;
        }
        if (entry->samplers != textures.size()) {
            if (diag)
                diag({Severity::Error, "", 0,
                      "variant " + name + ": its CPU mirror samples " +
                          std::to_string(entry->samplers) + " textures but " +
                          std::to_string(textures.size()) +
                          " were found for it (a stale mirror build?)"});
            return false;
        }
        std::vector<float> out(count * kFloatsPerResult);
        const auto t0 = std::chrono::steady_clock::now();
        entry->run(packed.data(), out.data(), count, textures.data(), textures.size(),
                   outputs == KernelOutputs::All);
        if (seconds)
            *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        results.swap(out);
        return true;
    }
    const auto key = std::make_pair(name, outputs);
    auto it = impl_->spirv.find(key);
    if (it == impl_->spirv.end()) {
        // The kernel's text, compiled or read from the cache folder by that text.
        const bool hlsl = impl_->opt.language == Language::Hlsl;
        const bool optimize = impl_->opt.optimize;
        if (hlsl && !hlsl_supports(v, diag)) return false;
        const std::string source = hlsl ? generate_hlsl_kernel(v, outputs)
                                        : generate_source(v, Language::Glsl, outputs);
        auto words = cached_compile(
            impl_->opt.spirv_cache,
            fmt::format("{} kernel, optimize {}, {}", hlsl ? "hlsl" : "glsl", optimize,
                        compiler_versions()),
            source, [&] {
                return hlsl ? compile_hlsl_kernel(v, source, optimize, diag)
                            : build_spirv(v, source, optimize, diag);
            });
        if (!words) return false;
        it = impl_->spirv.emplace(key, std::move(*words)).first;
    }
    return impl_->runner->run(it->second, packed.data(), packed.size() * sizeof(float), count,
                              results, kFloatsPerResult, diag, seconds, textures);
}

std::optional<ResultSet> Evaluator::run(const Variant& v, const CaseSet& cases,
                                        const DiagnosticConsumer& diag, EvalStats* stats) {
    std::vector<const Case*> todo;
    for (const auto& c : cases.cases)
        if (case_applies(v, c)) todo.push_back(&c);
    const auto packed = pack_cases(todo);
    std::vector<float> raw;
    double seconds = 0.0;
    const bool second = has_second_quantity(v);
    if (!run_packed(v, packed, todo.size(), raw, diag, &seconds,
                    second ? KernelOutputs::All : KernelOutputs::Shading))
        return std::nullopt;
    ResultSet out;
    out.variant = canonical_name(v);
    out.backend = to_string(impl_->opt.backend);
    const bool phong = v.dist == Distribution::Phong;
    for (std::size_t i = 0; i < todo.size(); ++i) {
        CaseResult r;
        r.id = todo[i]->id;
        const float* x = &raw[i * kFloatsPerResult];
        r.diffuse = x[0];
        r.specular = x[1];
        if (second) (phong ? r.moment : r.ndf) = x[2];
        out.results.push_back(std::move(r));
    }
    if (stats) {
        stats->evaluated = todo.size();
        stats->skipped = cases.cases.size() - todo.size();
        stats->seconds = seconds;
    }
    return out;
}

}  // namespace arealight
