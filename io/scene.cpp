// arealight-scene/1 reader: the top level here, every light and material field through the
// schema case files use too (shading_schema.hpp), so the two formats cannot drift apart.
#include "arealight/scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "json_fields.hpp"
#include "shading_schema.hpp"

namespace arealight {
namespace {

using json = nlohmann::json;
using io_detail::Reporter;

constexpr const char* kFormat = "arealight-scene/1";

// The array under `key`: nullptr after an error when it is missing, not an array or empty
// (a scene without lights or materials would generate nothing, which is never meant).
const json* nonempty_array(const json& doc, const char* key, const char* what, Reporter& rep) {
    auto it = doc.find(key);
    if (it == doc.end()) {
        rep.error("", key, "missing");
        return nullptr;
    }
    if (!it->is_array()) {
        rep.error("", key, fmt::format("must be an array of {}", what));
        return nullptr;
    }
    if (it->empty()) {
        rep.error("", key, fmt::format("must list at least one of the scene's {}", what));
        return nullptr;
    }
    return &*it;
}

// An optional boolean field of a quality object.
void read_flag(const json& q, const char* key, const std::string& where, const std::string& field,
               std::optional<bool>& out, Reporter& rep) {
    auto f = q.find(key);
    if (f == q.end()) return;
    if (!f->is_boolean())
        rep.error(where, field + key, "must be true or false");
    else
        out = f->get<bool>();
}

// A quality object (the scene's or a material's): `where` names its owner in messages
// ("" for the scene, "material N"), `field` its path ("quality.").
SceneQuality read_quality_object(const json& q, const std::string& where, Reporter& rep) {
    const std::string field = "quality.";
    io_detail::check_fields(rep, where, field, q,
                            {"max_error", "method", "precision", "tables", "patented", "exclude"});
    SceneQuality out;
    if (auto e = q.find("max_error"); e != q.end()) {
        if (!e->is_number())
            rep.error(where, field + "max_error", "must be a number");
        else if (const double x = e->get<double>(); !(x > 0.0 && std::isfinite(x)))
            rep.error(where, field + "max_error", fmt::format("{:g} is not a positive number", x));
        else
            out.max_error = x;
    }
    if (auto m = q.find("method"); m != q.end()) {
        if (!m->is_string() || m->get<std::string>().empty())
            rep.error(where, field + "method", "must be a method name (a non-empty string)");
        else
            out.method = m->get<std::string>();
    }
    if (auto p = q.find("precision"); p != q.end()) {
        const std::string s = p->is_string() ? p->get<std::string>() : "";
        if (s == "fp32" || s == "fp64")
            out.fp64 = s == "fp64";
        else
            rep.error(where, field + "precision", "must be \"fp32\" or \"fp64\"");
    }
    read_flag(q, "tables", where, field, out.tables, rep);
    read_flag(q, "patented", where, field, out.patented, rep);
    if (auto x = q.find("exclude"); x != q.end()) {
        bool ok = x->is_array();
        if (ok)
            for (const auto& name : *x) ok = ok && name.is_string() && !name.get<std::string>().empty();
        if (!ok)
            rep.error(where, field + "exclude", "must be an array of method names");
        else
            for (const auto& name : *x) out.exclude.push_back(name.get<std::string>());
    }
    return out;
}

void read_quality(const json& doc, const std::string& where, std::optional<SceneQuality>& out,
                  Reporter& rep) {
    auto q = doc.find("quality");
    if (q == doc.end()) return;
    if (!q->is_object()) {
        rep.error(where, "quality", "must be an object");
        return;
    }
    out = read_quality_object(*q, where, rep);
}

}  // namespace

std::optional<Scene> parse_scene(const std::string& text, const std::string& name,
                                 const DiagnosticConsumer& diag, const ValidationTolerances& tol) {
    auto parsed = io_detail::parse_json(text, name, diag);
    if (!parsed) return std::nullopt;
    const json& doc = *parsed;
    Reporter rep(name, diag);
    if (!io_detail::check_format(doc, kFormat, rep)) return std::nullopt;
    // camera and objects are arealight render's (io/render_scene.cpp checks them).
    io_detail::check_fields(rep, "", "", doc,
                            {"format", "lights", "materials", "quality", "camera", "objects"});
    Scene scene;
    if (const json* lights = nonempty_array(doc, "lights", "lights", rep)) {
        for (std::size_t i = 0; i < lights->size(); ++i) {
            const std::string where = fmt::format("light {}", i);
            Light light;
            if ((*lights)[i].is_object())
                io_detail::read_light_object(rep, where, "", (*lights)[i], tol, light,
                                             {"intensity"});
            else
                rep.error(where, "", "must be an object");
            scene.lights.push_back(std::move(light));
        }
    }
    if (const json* materials = nonempty_array(doc, "materials", "materials", rep)) {
        for (std::size_t i = 0; i < materials->size(); ++i) {
            const std::string where = fmt::format("material {}", i);
            Material material;
            std::optional<SceneQuality> quality;
            if ((*materials)[i].is_object()) {
                io_detail::read_material_object(rep, where, "", (*materials)[i], material,
                                                {"quality"});
                read_quality((*materials)[i], where, quality, rep);
            } else {
                rep.error(where, "", "must be an object");
            }
            scene.materials.push_back(material);
            scene.material_quality.push_back(std::move(quality));
        }
    }
    std::optional<SceneQuality> quality;
    read_quality(doc, "", quality, rep);
    if (quality) scene.quality = std::move(*quality);
    if (rep.errors() > 0) return std::nullopt;
    return scene;
}

SceneQuality effective_quality(const Scene& scene, Distribution dist, std::string* conflict) {
    SceneQuality out = scene.quality;
    // Fields some material of `dist` sets, combined strictest first.
    SceneQuality own;
    std::optional<std::size_t> method_from;
    for (std::size_t i = 0; i < scene.materials.size() && i < scene.material_quality.size();
         ++i) {
        const auto& q = scene.material_quality[i];
        if (scene.materials[i].distribution != dist || !q) continue;
        if (q->max_error) own.max_error = std::min(own.max_error.value_or(*q->max_error), *q->max_error);
        auto strict = [](std::optional<bool>& into, const std::optional<bool>& x) {
            if (x) into = into.value_or(true) && *x;
        };
        strict(own.fp64, q->fp64);
        strict(own.tables, q->tables);
        strict(own.patented, q->patented);
        for (const auto& m : q->exclude)
            if (std::find(own.exclude.begin(), own.exclude.end(), m) == own.exclude.end())
                own.exclude.push_back(m);
        if (q->method) {
            if (own.method && *own.method != *q->method) {
                if (conflict)
                    *conflict = fmt::format(
                        "materials {} and {} (both {}) ask for quality.method '{}' and '{}'",
                        *method_from, i, to_string(dist), *own.method, *q->method);
                return scene.quality;
            }
            own.method = q->method;
            method_from = i;
        }
    }
    if (own.max_error) out.max_error = own.max_error;
    if (own.method) out.method = own.method;
    if (own.fp64) out.fp64 = own.fp64;
    if (own.tables) out.tables = own.tables;
    if (own.patented) out.patented = own.patented;
    for (const auto& m : own.exclude)
        if (std::find(out.exclude.begin(), out.exclude.end(), m) == out.exclude.end())
            out.exclude.push_back(m);
    return out;
}

std::optional<Scene> read_scene(const std::string& path, const DiagnosticConsumer& diag,
                                const ValidationTolerances& tol) {
    auto text = io_detail::read_text(path, diag);
    if (!text) return std::nullopt;
    return parse_scene(*text, path, diag, tol);
}

}  // namespace arealight
