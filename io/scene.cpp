// arealight-scene/1 reader: the top level here, every light and material field through the
// case reader's own checks (case_fields.hpp), so the two formats cannot drift apart.
#include "arealight/scene.hpp"

#include <fmt/format.h>

#include <cmath>

#include "case_fields.hpp"

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

void read_quality(const json& doc, Scene& scene, Reporter& rep) {
    auto q = doc.find("quality");
    if (q == doc.end()) return;
    if (!q->is_object()) {
        rep.error("", "quality", "must be an object");
        return;
    }
    if (auto e = q->find("max_error"); e != q->end()) {
        if (!e->is_number())
            rep.error("", "quality.max_error", "must be a number");
        else if (const double x = e->get<double>(); !(x > 0.0 && std::isfinite(x)))
            rep.error("", "quality.max_error", fmt::format("{:g} is not a positive number", x));
        else
            scene.max_error = x;
    }
    if (auto m = q->find("method"); m != q->end()) {
        if (!m->is_string() || m->get<std::string>().empty())
            rep.error("", "quality.method", "must be a method name (a non-empty string)");
        else
            scene.method = m->get<std::string>();
    }
}

}  // namespace

std::optional<Scene> parse_scene(const std::string& text, const std::string& name,
                                 const DiagnosticConsumer& diag, const ValidationTolerances& tol) {
    auto parsed = io_detail::parse_json(text, name, diag);
    if (!parsed) return std::nullopt;
    const json& doc = *parsed;
    Reporter rep(name, diag);
    if (!io_detail::check_format(doc, kFormat, rep)) return std::nullopt;
    Scene scene;
    if (const json* lights = nonempty_array(doc, "lights", "lights", rep)) {
        for (std::size_t i = 0; i < lights->size(); ++i) {
            const std::string where = fmt::format("light {}", i);
            Light light;
            if ((*lights)[i].is_object())
                io_detail::read_light_object(rep, where, "", (*lights)[i], tol, light);
            else
                rep.error(where, "", "must be an object");
            scene.lights.push_back(std::move(light));
        }
    }
    if (const json* materials = nonempty_array(doc, "materials", "materials", rep)) {
        for (std::size_t i = 0; i < materials->size(); ++i) {
            const std::string where = fmt::format("material {}", i);
            Material material;
            if ((*materials)[i].is_object())
                io_detail::read_material_object(rep, where, "", (*materials)[i], material);
            else
                rep.error(where, "", "must be an object");
            scene.materials.push_back(material);
        }
    }
    read_quality(doc, scene, rep);
    if (rep.errors() > 0) return std::nullopt;
    return scene;
}

std::optional<Scene> read_scene(const std::string& path, const DiagnosticConsumer& diag,
                                const ValidationTolerances& tol) {
    auto text = io_detail::read_text(path, diag);
    if (!text) return std::nullopt;
    return parse_scene(*text, path, diag, tol);
}

}  // namespace arealight
