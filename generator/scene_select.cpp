// Scene-driven variant selection: which (light, distribution) pairs occur, which method
// meets the scene's quality at the least measured cost, and the sided and verts keys the
// scene allows. Every choice is a variant enumerate_variants() lists: methods come from
// parse_variant, specialisations only take values the family row offers.
#include "arealight/scene_select.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
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

// Whether the quality lets the variant be chosen (CONTRACT.md 7): fp64 only where the
// scene allows it, tables and the patented peak functions unless it refuses them, and
// never an excluded method; `why` says which rule refused it.
bool allowed(const Variant& v, const SceneQuality& q, std::string* why = nullptr) {
    auto refuse = [&](std::string reason) {
        if (why) *why = std::move(reason);
        return false;
    };
    if (effective_precision(v) == Precision::Fp64 && !q.fp64.value_or(false))
        return refuse("it computes in fp64 (quality.precision is fp32 unless the scene says fp64)");
    if (!variant_samplers(v).empty() && !q.tables.value_or(true))
        return refuse("it samples tables (quality.tables is false)");
    if (is_peak_method(v.method) && !q.patented.value_or(true))
        return refuse("it is a patented peak-function method (quality.patented is false)");
    if (std::find(q.exclude.begin(), q.exclude.end(), to_string(v.method)) != q.exclude.end())
        return refuse(fmt::format("quality.exclude names {}", to_string(v.method)));
    return true;
}

// The measured rows of one pair (and method) that the quality allows, each with its
// parsed variant. Rows measured at another sided or verts ran on a subset of the cases and
// are not comparable.
std::vector<std::pair<Variant, const MeasuredVariant*>> candidates(
    const QualityData& measured, LightType light, Distribution dist,
    const std::optional<Method>& method, const SceneQuality& q) {
    std::vector<std::pair<Variant, const MeasuredVariant*>> out;
    const Variant defaults;
    for (const auto& m : measured.variants) {
        auto v = parse_variant(m.variant, {});
        if (!v || v->light != light || v->dist != dist) continue;
        if (method && v->method != *method) continue;
        if (v->sided != defaults.sided || v->verts != defaults.verts) continue;
        if (!allowed(*v, q)) continue;
        out.emplace_back(*v, &m);
    }
    return out;
}

// What a row costs, in the order rows are ranked: the GPU cost (CONTRACT.md 4) where the
// row has one (rows without rank after those with), then the x86-64 count.
std::tuple<int, double, std::size_t> cost_of(const MeasuredVariant& m) {
    if (m.gpu) return {0, static_cast<double>(m.gpu->cost), m.x86_instructions};
    return {1, 0.0, m.x86_instructions};
}

std::string measured_text(const MeasuredVariant& m) {
    if (m.gpu)
        return fmt::format("measured error {:.4g} at GPU cost {} cycles per wave, {:.3g}x its "
                           "point light ({} {}; {})",
                           m.error(), m.gpu->cost, m.gpu->ratio_to_point, m.gpu->family,
                           m.gpu->mesa, m.report);
    return fmt::format("measured error {:.4g} at {} x86 instructions, no GPU figures ({})",
                       m.error(), m.x86_instructions, m.report);
}

std::optional<Method> checked_method(const std::string& name, const char* field,
                                     const DiagnosticConsumer& diag) {
    if (auto m = method_named(name)) return m;
    std::vector<std::string> names;
    for (const auto& f : variant_families())
        if (std::find(names.begin(), names.end(), to_string(f.method)) == names.end())
            names.push_back(to_string(f.method));
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    emit(diag, Severity::Error,
         fmt::format("{}: no variant has method '{}' (methods: {})", field, name, list));
    return std::nullopt;
}

// The pair's variant of quality.method alone, with the reason: that method at its
// family's defaults, in fp32 where fp64 is not allowed and the family offers fp32.
std::optional<SelectedVariant> method_default(LightType light, Distribution dist, Method method,
                                              const SceneQuality& q,
                                              const DiagnosticConsumer& diag) {
    // Parsed rather than assembled, so that the family's own defaults apply (ltc computes
    // in fp32 where Variant's default precision is fp64).
    const std::string base = fmt::format("dist={},method={},light={}", to_string(dist),
                                         to_string(method), to_string(light));
    auto v = parse_variant(base, diag);
    if (!v) return std::nullopt;
    std::string why = fmt::format("quality.method {}: every other key at its default",
                                  to_string(method));
    if (effective_precision(*v) == Precision::Fp64 && !q.fp64.value_or(false)) {
        if (auto fp32 = parse_variant(base + ",precision=fp32", {})) {
            v = fp32;
            why += " but precision=fp32 (the scene does not allow fp64)";
        }
    }
    std::string refused;
    if (!allowed(*v, q, &refused)) {
        emit(diag, Severity::Error,
             fmt::format("{}: quality.method {} cannot be used: {}", pair_name(light, dist),
                         to_string(method), refused));
        return std::nullopt;
    }
    return SelectedVariant{*v, why};
}

}  // namespace

std::optional<std::vector<SelectedVariant>> select_variants(const Scene& scene,
                                                            const QualityData& measured,
                                                            const DiagnosticConsumer& diag) {
    std::set<std::pair<LightType, Distribution>> pairs;
    for (const auto& l : scene.lights)
        for (const auto& m : scene.materials) pairs.emplace(l.type, m.distribution);

    std::vector<SelectedVariant> out;
    bool ok = true;
    // Each distribution's quality, resolved and its method names checked once, so that a
    // misspelt name is one error, not one per light type; nullopt where it is unusable.
    struct Resolved {
        SceneQuality q;
        std::optional<Method> method;
    };
    std::map<Distribution, std::optional<Resolved>> resolved;
    for (const auto& m : scene.materials) {
        if (resolved.count(m.distribution)) continue;
        std::string conflict;
        Resolved r{effective_quality(scene, m.distribution, &conflict), std::nullopt};
        bool usable = conflict.empty();
        if (!usable) emit(diag, Severity::Error, conflict);
        if (usable && r.q.method) {
            r.method = checked_method(*r.q.method, "quality.method", diag);
            usable = r.method.has_value();
        }
        if (usable)
            for (const auto& name : r.q.exclude)
                if (!checked_method(name, "quality.exclude", diag)) ok = false;
        resolved[m.distribution] = usable ? std::optional<Resolved>(r) : std::nullopt;
    }
    for (const auto& [light, dist] : pairs) {
        const std::string pair = pair_name(light, dist);
        if (!resolved.at(dist)) {
            ok = false;
            continue;
        }
        const SceneQuality& q = resolved.at(dist)->q;
        const std::optional<Method>& method = resolved.at(dist)->method;
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
        if (method && !q.max_error) {
            auto chosen = method_default(light, dist, *method, q, diag);
            if (!chosen) {
                ok = false;
                continue;
            }
            chosen->variant = specialise(chosen->variant, needs);
            out.push_back(std::move(*chosen));
            continue;
        }
        const auto found = candidates(measured, light, dist, method, q);
        if (found.empty()) {
            emit(diag, Severity::Error,
                 fmt::format("{}: no measured variant{} that the scene's quality allows in the "
                             "quality data (arealight quality regenerates it from the reports)",
                             pair, method ? " of method=" + std::string(to_string(*method)) : ""));
            ok = false;
            continue;
        }
        const double max_error = q.max_error.value_or(kDefaultMaxError);
        // Cheapest meeting the bound; ties by error, then name, so the choice is stable.
        auto cheaper = [](const auto& a, const auto& b) {
            return std::make_tuple(cost_of(*a.second), a.second->error(), a.second->variant) <
                   std::make_tuple(cost_of(*b.second), b.second->error(), b.second->variant);
        };
        auto more_accurate = [](const auto& a, const auto& b) {
            return std::make_tuple(a.second->error(), cost_of(*a.second), a.second->variant) <
                   std::make_tuple(b.second->error(), cost_of(*b.second), b.second->variant);
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
            why = fmt::format("most accurate allowed, none meets {:g}: {}", max_error,
                              measured_text(*best->second));
            emit(diag, Severity::Warning,
                 fmt::format("{}: no variant the scene's quality allows meets max_error {:g}; "
                             "using the most accurate, {}, which reaches {:.4g} ({})",
                             pair, max_error, best->second->variant, best->second->error(),
                             measured_text(*best->second)));
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
