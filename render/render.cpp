#include "arealight/render.hpp"

#include <fmt/format.h>

#include <chrono>
#include <map>
#include <utility>

#include "arealight/raycast.hpp"

namespace arealight {
namespace {

struct Shading {
    std::size_t pixel;
    int light;
    int object;
};

void error(const DiagnosticConsumer& diag, const std::string& msg) {
    if (diag) diag({Severity::Error, "", 0, msg});
}

std::string describe(const Light& L) {
    if (L.type != LightType::Polygon) return to_string(L.type);
    return fmt::format("{}-sided polygon of {} vertices", L.two_sided ? "two" : "one",
                       L.vertices.size());
}

}  // namespace

std::optional<SelectedVariant> render_variant(const Scene& scene, LightType light,
                                              Distribution dist, const QualityData& measured,
                                              const DiagnosticConsumer& diag) {
    // The pair's part of the scene: its selection depends on nothing else (the lights of
    // its type, the scene's quality), and the other pairs' problems, e.g. those a
    // --variant covers, are not this one's.
    Scene part;
    part.quality = scene.quality;
    for (const auto& l : scene.lights)
        if (l.type == light) part.lights.push_back(l);
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        if (scene.materials[i].distribution != dist) continue;
        part.materials.push_back(scene.materials[i]);
        part.material_quality.push_back(i < scene.material_quality.size()
                                            ? scene.material_quality[i]
                                            : std::nullopt);
    }
    auto selected = select_variants(part, measured, diag);
    if (!selected) return std::nullopt;
    if (selected->size() != 1) {
        error(diag, fmt::format("render: the selection for light={}, dist={} gave {} variants",
                                to_string(light), to_string(dist), selected->size()));
        return std::nullopt;
    }
    const SelectedVariant& v = selected->front();
    if (diag)
        diag({Severity::Note, "", 0,
              fmt::format("{}: the scene's selection, {}", canonical_name(v.variant), v.why)});
    return v;
}

std::optional<LinearImage> render(const RenderScene& scene, const RenderOptions& opt,
                                  Evaluator* evaluator, const DiagnosticConsumer& diag,
                                  const ProgressConsumer& progress, RenderStats* stats) {
    RenderStats st;
    LinearImage img;
    img.width = opt.width;
    img.height = opt.height;
    img.rgb.assign(static_cast<std::size_t>(opt.width) * opt.height * 3, 0.0f);
    const auto hits = cast_camera_rays(scene, opt.width, opt.height);

    // One batch per (light type, distribution): that is one variant's cases.
    using Key = std::pair<LightType, Distribution>;
    std::map<Key, std::pair<CaseSet, std::vector<Shading>>> batches;
    for (std::size_t px = 0; px < hits.size(); ++px) {
        const PixelHit& h = hits[px];
        if (h.kind == PixelHit::Kind::Light) {
            const float e = static_cast<float>(scene.intensities[h.light]);
            for (int k = 0; k < 3; ++k) img.rgb[px * 3 + k] = e;
        }
        if (h.kind != PixelHit::Kind::Surface) continue;
        const Material& m = scene.materials[scene.objects[h.object].material];
        for (std::size_t l = 0; l < scene.lights.size(); ++l) {
            const Light& L = scene.lights[l];
            Case c;
            c.id = fmt::format("pixel {} light {}", px, l);
            c.p = h.p;
            c.n = h.n;
            c.v = h.v;
            c.light = L;
            c.material = m;
            auto& b = batches[{L.type, m.distribution}];
            b.first.cases.push_back(std::move(c));
            b.second.push_back({px, static_cast<int>(l), h.object});
        }
    }

    auto accumulate = [&](const std::vector<Shading>& where, const std::vector<CaseResult>& res) {
        for (std::size_t i = 0; i < where.size(); ++i) {
            const Shading& s = where[i];
            const Vec3& albedo = scene.objects[s.object].albedo;
            const double e = scene.intensities[s.light];
            const double d = res[i].diffuse.value_or(0), sp = res[i].specular.value_or(0);
            for (int k = 0; k < 3; ++k)
                img.rgb[s.pixel * 3 + k] += static_cast<float>(e * (albedo[k] * d + sp));
        }
        st.cases += where.size();
    };

    if (opt.reference) {
        // One pool over every case, so that the threads stay busy to the end.
        CaseSet all;
        std::vector<Shading> where;
        for (auto& [key, b] : batches) {
            all.cases.insert(all.cases.end(), b.first.cases.begin(), b.first.cases.end());
            where.insert(where.end(), b.second.begin(), b.second.end());
        }
        const auto start = std::chrono::steady_clock::now();
        const ResultSet res = reference_all(all, opt.reference_options, progress);
        st.shading_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        for (const auto& r : res.results)
            if (r.converged && !*r.converged) ++st.unconverged;
        accumulate(where, res.results);
        st.variants.push_back("oracle");
    } else {
        if (!evaluator) {
            error(diag, "render: no evaluator given for a non-reference render");
            return std::nullopt;
        }
        for (auto& [key, b] : batches) {
            std::optional<Variant> v;
            for (const auto& given : opt.variants)
                if (given.light == key.first && given.dist == key.second) v = given;
            if (!v) {
                auto s = render_variant(scene, key.first, key.second,
                                        opt.quality ? *opt.quality : shipped_quality(), diag);
                if (!s) return std::nullopt;
                v = s->variant;
            }
            for (std::size_t i = 0; i < b.first.cases.size(); ++i) {
                if (case_applies(*v, b.first.cases[i])) continue;
                const int l = b.second[i].light;
                error(diag, fmt::format("variant {} does not apply to light {} (a {})",
                                        canonical_name(*v), l, describe(scene.lights[l])));
                return std::nullopt;
            }
            EvalStats es;
            auto res = evaluator->run(*v, b.first, diag, &es);
            if (!res) return std::nullopt;
            if (res->results.size() != b.second.size()) {
                error(diag, fmt::format("render: {} returned {} results for {} cases",
                                        canonical_name(*v), res->results.size(), b.second.size()));
                return std::nullopt;
            }
            st.shading_seconds += es.seconds;
            st.variants.push_back(canonical_name(*v));
            accumulate(b.second, res->results);
        }
    }
    if (stats) *stats = st;
    return img;
}

}  // namespace arealight
