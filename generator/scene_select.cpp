// Scene-driven variant selection: which (light, distribution) pairs occur, which method
// meets the scene's quality at the least measured cost, and the sided and verts keys the
// scene allows. Every choice is a variant enumerate_variants() lists: methods come from
// parse_variant, specialisations only take values the family row offers.
#include "arealight/scene_select.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <tuple>
#include <utility>

namespace arealight {
namespace {

void emit(const DiagnosticConsumer& diag, Severity s, const std::string& message) {
    if (diag) diag({s, "", 0, message});
}

std::string pair_name(LightType light, Distribution dist) {
    return fmt::format("light={}, dist={}", to_string(light), to_string(dist));
}

// What every light of one type asks of its variant.
struct LightNeeds {
    Sided sided = Sided::Any;
    std::size_t max_verts = 0;  // largest polygon; 0 for other shapes
};

LightNeeds needs_of(const Scene& scene, LightType type) {
    bool any_one = false, any_two = false;
    LightNeeds n;
    for (const auto& l : scene.lights) {
        if (l.type != type) continue;
        (l.two_sided ? any_two : any_one) = true;
        n.max_verts = std::max(n.max_verts, l.vertices.size());
    }
    n.sided = any_one && any_two ? Sided::Any : (any_two ? Sided::Two : Sided::One);
    return n;
}

// The variant with sided and verts narrowed to the scene, where its family offers it.
Variant specialise(Variant v, const LightNeeds& needs) {
    const VariantFamily* family = find_family(v);
    if (!family) return v;
    for (const auto& key : family->keys) {
        if (key.key == "sided") {
            const std::string want = to_string(needs.sided);
            if (std::find(key.values.begin(), key.values.end(), want) != key.values.end())
                v.sided = needs.sided;
        } else if (key.key == "verts") {
            int best = 0;
            for (const auto& s : key.values) {
                const int n = std::stoi(s);
                if (n >= static_cast<int>(needs.max_verts) && (best == 0 || n < best)) best = n;
            }
            if (best > 0) v.verts = best;
        }
    }
    return v;
}

bool has_family(LightType light, Distribution dist, const std::optional<Method>& method) {
    for (const auto& f : variant_families())
        if (f.light == light && f.dist == dist && (!method || f.method == *method)) return true;
    return false;
}

std::optional<Method> method_named(const std::string& name) {
    for (const auto& f : variant_families())
        if (name == to_string(f.method)) return f.method;
    return std::nullopt;
}

// The measured rows of one pair (and method), each with its parsed variant. Rows measured
// at another sided or verts ran on a subset of the cases and are not comparable.
std::vector<std::pair<Variant, const MeasuredVariant*>> candidates(
    const QualityData& measured, LightType light, Distribution dist,
    const std::optional<Method>& method) {
    std::vector<std::pair<Variant, const MeasuredVariant*>> out;
    const Variant defaults;
    for (const auto& m : measured.variants) {
        auto v = parse_variant(m.variant, {});
        if (!v || v->light != light || v->dist != dist) continue;
        if (method && v->method != *method) continue;
        if (v->sided != defaults.sided || v->verts != defaults.verts) continue;
        out.emplace_back(*v, &m);
    }
    return out;
}

std::string measured_text(const MeasuredVariant& m) {
    return fmt::format("measured error {:.4g} at {} x86 instructions ({})", m.error(),
                       m.x86_instructions, m.report);
}

}  // namespace

std::optional<std::vector<SelectedVariant>> select_variants(const Scene& scene,
                                                            const QualityData& measured,
                                                            const DiagnosticConsumer& diag) {
    std::optional<Method> method;
    if (scene.method) {
        method = method_named(*scene.method);
        if (!method) {
            std::vector<std::string> names;
            for (const auto& f : variant_families())
                if (std::find(names.begin(), names.end(), to_string(f.method)) == names.end())
                    names.push_back(to_string(f.method));
            std::string list;
            for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
            emit(diag, Severity::Error,
                 fmt::format("quality.method: no variant has method '{}' (methods: {})",
                             *scene.method, list));
            return std::nullopt;
        }
    }
    std::set<std::pair<LightType, Distribution>> pairs;
    for (const auto& l : scene.lights)
        for (const auto& m : scene.materials) pairs.emplace(l.type, m.distribution);

    const double max_error = scene.max_error.value_or(kDefaultMaxError);
    std::vector<SelectedVariant> out;
    bool ok = true;
    for (const auto& [light, dist] : pairs) {
        const std::string pair = pair_name(light, dist);
        if (!has_family(light, dist, method)) {
            emit(diag, Severity::Error,
                 method ? fmt::format("{}: no variant has method={} ('arealight variants' lists "
                                      "them)",
                                      pair, to_string(*method))
                        : fmt::format("{}: no variant implements it ('arealight variants' lists "
                                      "them)",
                                      pair));
            ok = false;
            continue;
        }
        const LightNeeds needs = needs_of(scene, light);
        if (method && !scene.max_error) {
            // Parsed rather than assembled, so that the family's own defaults apply (ltc
            // computes in fp32 where Variant's default precision is fp64).
            const auto v = parse_variant(fmt::format("dist={},method={},light={}", to_string(dist),
                                                     to_string(*method), to_string(light)),
                                         diag);
            if (!v) {
                ok = false;
                continue;
            }
            out.push_back({specialise(*v, needs), fmt::format("quality.method {}: every other key "
                                                              "at its default",
                                                              to_string(*method))});
            continue;
        }
        const auto found = candidates(measured, light, dist, method);
        if (found.empty()) {
            emit(diag, Severity::Error,
                 fmt::format("{}: no measured variant{} in the quality data (arealight quality "
                             "regenerates it from the reports)",
                             pair, method ? " of method=" + std::string(to_string(*method)) : ""));
            ok = false;
            continue;
        }
        // Cheapest meeting the bound; ties by error, then name, so the choice is stable.
        auto cheaper = [](const auto& a, const auto& b) {
            return std::make_tuple(a.second->x86_instructions, a.second->error(),
                                   a.second->variant) < std::make_tuple(b.second->x86_instructions,
                                                                        b.second->error(),
                                                                        b.second->variant);
        };
        auto more_accurate = [](const auto& a, const auto& b) {
            return std::make_tuple(a.second->error(), a.second->x86_instructions,
                                   a.second->variant) < std::make_tuple(b.second->error(),
                                                                        b.second->x86_instructions,
                                                                        b.second->variant);
        };
        const std::pair<Variant, const MeasuredVariant*>* best = nullptr;
        for (const auto& c : found)
            if (c.second->error() <= max_error && (!best || cheaper(c, *best))) best = &c;
        std::string why;
        if (best) {
            why = fmt::format("cheapest with error <= {:g}: {}", max_error,
                              measured_text(*best->second));
        } else {
            best = &*std::min_element(found.begin(), found.end(), more_accurate);
            why = fmt::format("most accurate, none meets {:g}: {}", max_error,
                              measured_text(*best->second));
            emit(diag, Severity::Warning,
                 fmt::format("{}: no measured variant meets max_error {:g}; using the most "
                             "accurate, {}, {}",
                             pair, max_error, best->second->variant, measured_text(*best->second)));
        }
        out.push_back({specialise(best->first, needs), why});
    }
    // specialise only takes offered values, so this holds unless the family table
    // constrains keys jointly; say so rather than emit a variant nobody can build.
    for (const auto& s : out) {
        if (!is_valid(s.variant)) {
            emit(diag, Severity::Error,
                 fmt::format("{}: the specialised variant is not valid (internal error)",
                             canonical_name(s.variant)));
            ok = false;
        }
    }
    if (!ok) return std::nullopt;
    return out;
}

}  // namespace arealight
