#include "arealight/evaluator.hpp"

#include <chrono>
#include <cmath>
#include <exception>
#include <map>

#include "arealight/compiler.hpp"
#include "arealight/cpu_mirror.hpp"
#include "arealight/generator.hpp"
#include "arealight/vulkan_runner.hpp"

namespace arealight {
namespace {

Vec3 sub(const Vec3& a, const Vec3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double norm(const Vec3& a) {
    return std::sqrt(dot(a, a));
}
Vec3 scale(const Vec3& a, double s) {
    return {a[0] * s, a[1] * s, a[2] * s};
}

// Orthonormal x, y completing the unit z (Duff et al. 2017, branch-free).
void orthonormal_basis(const Vec3& z, Vec3& x, Vec3& y) {
    const double s = std::copysign(1.0, z[2]);
    const double a = -1.0 / (s + z[2]);
    const double b = z[0] * z[1] * a;
    x = {1.0 + s * z[0] * z[0] * a, s * b, -s * z[0]};
    y = {b, s + z[1] * z[1] * a, -z[1]};
}

Vec3 light_centre(const Light& L) {
    if (L.type != LightType::Polygon) return L.center;
    Vec3 c{};
    for (const auto& x : L.vertices)
        for (int k = 0; k < 3; ++k) c[k] += x[k] / L.vertices.size();
    return c;
}

}  // namespace

const char* to_string(Backend b) {
    return b == Backend::Cpu ? "cpu" : "vulkan";
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
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const Case& c = *cases[i];
        float* o = &out[i * kFloatsPerCase];
        // Directions and solid angles are invariant under rotations and scalings
        // about p: put the light's centre at distance 1 on +z.
        const Vec3 centre = light_centre(c.light);
        const Vec3 rel = sub(centre, c.p);
        double dist = norm(rel);
        if (!(dist > 0.0) || !std::isfinite(dist)) dist = 1.0;
        const Vec3 z = scale(rel, 1.0 / dist);
        Vec3 x, y;
        orthonormal_basis(z, x, y);
        auto frame = [&](const Vec3& a, float* dst) {
            dst[0] = static_cast<float>(dot(a, x));
            dst[1] = static_cast<float>(dot(a, y));
            dst[2] = static_cast<float>(dot(a, z));
        };
        const Vec3 n = scale(c.n, 1.0 / norm(c.n)), v = scale(c.v, 1.0 / norm(c.v));
        const double nv = dot(n, v);
        const Vec3 r = {2 * nv * n[0] - v[0], 2 * nv * n[1] - v[1], 2 * nv * n[2] - v[2]};
        frame(n, o);
        frame(v, o + 4);
        frame(scale(r, 1.0 / norm(r)), o + 8);
        const Material& m = c.material;
        const bool exponent =
            m.distribution == Distribution::Phong || m.distribution == Distribution::Blinn;
        o[12] = static_cast<float>(exponent ? m.exponent : m.alpha);
        o[13] = c.light.two_sided ? 1.0f : 0.0f;
        o[14] = static_cast<float>(c.light.vertices.size());
        // Schlick f0 (CONTRACT.md 2); 1 when the case has none, which makes F = 1 exactly.
        o[15] = static_cast<float>(m.f0);
        frame(scale(rel, 1.0 / dist), o + 16);
        // Offsets from the centre are formed in double, so small distant polygons
        // keep the relative precision of their edges.
        for (std::size_t k = 0; k < c.light.vertices.size() && k < 8; ++k) {
            frame(scale(sub(c.light.vertices[k], centre), 1.0 / dist), o + 20 + 4 * k);
        }
    }
    return out;
}

std::optional<std::vector<uint32_t>> build_spirv(const Variant& v, bool optimize,
                                                 const DiagnosticConsumer& diag) {
    return build_spirv(v, generate_source(v, Language::Glsl), optimize, diag);
}

std::optional<std::vector<uint32_t>> build_spirv(const Variant& v, const std::string& glsl,
                                                 bool optimize, const DiagnosticConsumer& diag) {
    const std::string name = canonical_name(v);
    auto prefixed = [&](const Diagnostic& d) {
        if (!diag) return;
        Diagnostic p = d;
        p.message = "variant " + name + ": " + d.message;
        diag(p);
    };
    CompileOptions opt;
    opt.optimize = optimize;
    return compile_glsl(glsl, name + ".comp", opt, prefixed);
}

struct Evaluator::Impl {
    EvalOptions opt;
    std::unique_ptr<VulkanRunner> runner;
    std::map<std::string, std::vector<uint32_t>> spirv;  // by canonical name
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
                           double* seconds) {
    const std::string name = canonical_name(v);
    // The tables the variant samples, bound the same way on both backends.
    std::vector<const Texture2D*> textures;
    try {
        textures = variant_textures(v);
    } catch (const std::exception& e) {
        if (diag) diag({Severity::Error, "", 0, e.what()});
        return false;
    }
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
        entry->run(packed.data(), out.data(), count, textures.data(), textures.size());
        if (seconds)
            *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        results.swap(out);
        return true;
    }
    auto it = impl_->spirv.find(name);
    if (it == impl_->spirv.end()) {
        auto words = build_spirv(v, impl_->opt.optimize, diag);
        if (!words) return false;
        it = impl_->spirv.emplace(name, std::move(*words)).first;
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
    if (!run_packed(v, packed, todo.size(), raw, diag, &seconds)) return std::nullopt;
    ResultSet out;
    out.variant = canonical_name(v);
    out.backend = to_string(impl_->opt.backend);
    const bool phong = v.dist == Distribution::Phong;
    const VariantFamily* family = find_family(v);
    const bool second = family && family->second_quantity;
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
