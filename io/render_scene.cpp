// The renderer's scene reader: camera and objects here; lights and materials through the
// case reader (parse_cases), so that they are validated exactly as CONTRACT 3 fields are.
//
// Stand-in until the core scene reader (read_scene, CONTRACT 7) lands: each light and
// each material is wrapped into a synthetic case and its messages renamed from
// "case 'light 1': field 'light.vertices'" to "light 1: field 'vertices'".
#include "arealight/render_scene.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "arealight/case_io.hpp"
#include "arealight/read_file.hpp"

namespace arealight {
namespace {

using json = nlohmann::json;

// Larger coordinates would overflow the products a ray cast forms.
constexpr double kMaxCoordinate = 1e15;

class SceneReader {
  public:
    SceneReader(std::string file, const DiagnosticConsumer& diag)
        : file_(std::move(file)), diag_(diag) {}

    bool fail(const std::string& where, const std::string& field, const std::string& reason) {
        ++errors_;
        std::string msg = file_ + ": ";
        if (!where.empty()) msg += where + ": ";
        if (!field.empty()) msg += "field '" + field + "': ";
        if (diag_) diag_({Severity::Error, file_, 0, msg + reason});
        return false;
    }
    int errors() const { return errors_; }

    bool number(const json& obj, const char* key, const std::string& where, double& out) {
        auto it = obj.find(key);
        if (it == obj.end()) return fail(where, key, "missing");
        if (!it->is_number()) return fail(where, key, "must be a number");
        out = it->get<double>();
        if (!(std::abs(out) <= kMaxCoordinate))
            return fail(where, key,
                        fmt::format("{:g} is not finite or larger than {:g} in magnitude", out,
                                    kMaxCoordinate));
        return true;
    }

    bool vec3(const json& obj, const char* key, const std::string& where, Vec3& out) {
        auto it = obj.find(key);
        if (it == obj.end()) return fail(where, key, "missing");
        if (!it->is_array() || it->size() != 3) return fail(where, key, "must be an array of 3 numbers");
        for (std::size_t k = 0; k < 3; ++k) {
            const json& x = (*it)[k];
            if (!x.is_number()) return fail(where, key, "must be an array of 3 numbers");
            out[k] = x.get<double>();
            if (!(std::abs(out[k]) <= kMaxCoordinate))
                return fail(where, key,
                            fmt::format("component {} is {:g}: not finite or larger than {:g} in "
                                        "magnitude",
                                        k, out[k], kMaxCoordinate));
        }
        return true;
    }

    bool nonzero(const json& obj, const char* key, const std::string& where, Vec3& out) {
        if (!vec3(obj, key, where, out)) return false;
        if (out[0] == 0 && out[1] == 0 && out[2] == 0)
            return fail(where, key, "must have non-zero length");
        return true;
    }

    void read_camera(const json& doc, Camera& cam) {
        auto it = doc.find("camera");
        if (it == doc.end() || !it->is_object()) {
            fail("", "camera", it == doc.end() ? "missing" : "must be an object");
            return;
        }
        const json& c = *it;
        const bool eye = vec3(c, "eye", "camera", cam.eye);
        const bool target = vec3(c, "target", "camera", cam.target);
        const bool up = nonzero(c, "up", "camera", cam.up);
        if (number(c, "fov_deg", "camera", cam.fov_deg) &&
            !(cam.fov_deg > 0 && cam.fov_deg < 180))
            fail("camera", "fov_deg", fmt::format("{:g} is outside (0, 180)", cam.fov_deg));
        if (!eye || !target) return;
        const Vec3 d = {cam.target[0] - cam.eye[0], cam.target[1] - cam.eye[1],
                        cam.target[2] - cam.eye[2]};
        const double dl = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (!(dl > 0)) {
            fail("camera", "target", "equals eye: the camera looks nowhere");
            return;
        }
        if (!up) return;
        const Vec3& u = cam.up;
        const Vec3 x = {d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2],
                        d[0] * u[1] - d[1] * u[0]};
        const double ul = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        // Beyond this the image's horizontal axis is ill-defined.
        if (std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) <= 1e-6 * dl * ul)
            fail("camera", "up", "is parallel to the viewing direction (target - eye)");
    }

    void read_object(const json& o, const std::string& where, std::size_t materials,
                     SceneObject& out) {
        if (!o.is_object()) {
            fail(where, "", "must be an object");
            return;
        }
        auto t = o.find("type");
        if (t == o.end() || !t->is_string()) {
            fail(where, "type", t == o.end() ? "missing" : "must be a string");
        } else if (*t == "plane") {
            out.type = ObjectType::Plane;
            vec3(o, "point", where, out.point);
            nonzero(o, "normal", where, out.normal);
        } else if (*t == "sphere") {
            out.type = ObjectType::Sphere;
            vec3(o, "center", where, out.center);
            if (number(o, "radius", where, out.radius) && !(out.radius > 0))
                fail(where, "radius", fmt::format("{:g} is not positive", out.radius));
        } else if (*t == "box") {
            out.type = ObjectType::Box;
            if (vec3(o, "min", where, out.min) && vec3(o, "max", where, out.max)) {
                for (int k = 0; k < 3; ++k) {
                    if (!(out.min[k] < out.max[k])) {
                        fail(where, "max",
                             fmt::format("component {} is {:g}, not above min's {:g}", k,
                                         out.max[k], out.min[k]));
                        break;
                    }
                }
            }
        } else {
            fail(where, "type",
                 fmt::format("is {}, expected \"plane\", \"sphere\" or \"box\"", t->dump()));
        }
        auto m = o.find("material");
        if (m == o.end()) {
            fail(where, "material", "missing");
        } else if (!m->is_number_integer() || m->get<long long>() < 0 ||
                   m->get<long long>() >= static_cast<long long>(materials)) {
            fail(where, "material",
                 fmt::format("{} is not an index into materials (0 to {})", m->dump(),
                             static_cast<long long>(materials) - 1));
        } else {
            out.material = m->get<int>();
        }
        if (vec3(o, "albedo", where, out.albedo)) {
            for (int k = 0; k < 3; ++k)
                if (!(out.albedo[k] >= 0 && out.albedo[k] <= 1)) {
                    fail(where, "albedo",
                         fmt::format("component {} is {:g}, outside [0, 1]", k, out.albedo[k]));
                    break;
                }
        }
    }

    // The lights' and materials' CONTRACT 3 fields, each wrapped in a case that is valid
    // but for it, so that the case reader's messages point at that one item.
    void read_lights_and_materials(const json& doc, RenderScene& scene) {
        const json* lights = array(doc, "lights");
        const json* materials = array(doc, "materials");
        if (!lights || !materials) return;
        const json some_light = {{"type", "polygon"},
                                 {"vertices", {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}}};
        const json some_material = {{"distribution", "phong"}, {"exponent", 1}};
        json cases = json::array();
        auto wrap = [&](const std::string& id, const json& light, const json& material) {
            cases.push_back({{"id", id},
                             {"p", {0, 0, 0}},
                             {"n", {0, 0, 1}},
                             {"v", {0, 0, 1}},
                             {"light", light},
                             {"material", material}});
        };
        for (std::size_t i = 0; i < lights->size(); ++i)
            wrap(fmt::format("light {}", i), (*lights)[i], some_material);
        for (std::size_t i = 0; i < materials->size(); ++i)
            wrap(fmt::format("material {}", i), some_light, (*materials)[i]);
        const json wrapped = {{"format", "arealight-cases/1"}, {"cases", cases}};
        auto renamed = [&](const Diagnostic& d) {
            ++errors_;
            if (!diag_) return;
            Diagnostic r = d;
            for (const char* kind : {"light", "material"}) {
                const std::string from = fmt::format("case '{} ", kind);
                const auto at = r.message.find(from);
                if (at == std::string::npos) continue;
                r.message.replace(at, from.size(), std::string(kind) + " ");
                const auto quote = r.message.find("': field '", at);
                if (quote != std::string::npos) r.message.erase(quote, 1);
                const std::string prefix = fmt::format("field '{}.", kind);
                const auto field = r.message.find(prefix, at);
                if (field != std::string::npos)
                    r.message.replace(field, prefix.size(), "field '");
            }
            diag_(r);
        };
        auto set = parse_cases(wrapped.dump(), file_, renamed);
        if (!set) return;
        for (std::size_t i = 0; i < lights->size(); ++i) {
            scene.lights.push_back(set->cases[i].light);
            double intensity = 1.0;
            const json& L = (*lights)[i];
            if (L.find("intensity") != L.end() &&
                number(L, "intensity", fmt::format("light {}", i), intensity) &&
                !(intensity >= 0))
                fail(fmt::format("light {}", i), "intensity",
                     fmt::format("{:g} is negative", intensity));
            scene.intensities.push_back(intensity);
        }
        for (std::size_t i = 0; i < materials->size(); ++i)
            scene.materials.push_back(set->cases[lights->size() + i].material);
    }

    const json* array(const json& doc, const char* key) {
        auto it = doc.find(key);
        if (it == doc.end() || !it->is_array()) {
            fail("", key, it == doc.end() ? "missing" : "must be an array");
            return nullptr;
        }
        return &*it;
    }

    void read_method(const json& doc, RenderScene& scene) {
        auto q = doc.find("quality");
        if (q == doc.end() || !q->is_object()) return;
        auto m = q->find("method");
        if (m == q->end()) return;
        if (!m->is_string())
            fail("quality", "method", "must be a string");
        else
            scene.method = m->get<std::string>();
    }

  private:
    std::string file_;
    const DiagnosticConsumer& diag_;
    int errors_ = 0;
};

}  // namespace

std::optional<RenderScene> parse_render_scene(const std::string& text, const std::string& name,
                                              const DiagnosticConsumer& diag) {
    SceneReader r(name, diag);
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::exception& e) {
        r.fail("", "", std::string("invalid JSON: ") + e.what());
        return std::nullopt;
    }
    if (!doc.is_object()) {
        r.fail("", "format", "the file must be a JSON object");
        return std::nullopt;
    }
    auto f = doc.find("format");
    if (f == doc.end() || *f != "arealight-scene/1") {
        r.fail("", "format",
               f == doc.end() ? "missing (expected \"arealight-scene/1\")"
                              : "is " + f->dump() + ", expected \"arealight-scene/1\"");
        return std::nullopt;
    }
    RenderScene scene;
    r.read_lights_and_materials(doc, scene);
    r.read_method(doc, scene);
    r.read_camera(doc, scene.camera);
    // Indices are checked against the file's list even when an item of it is invalid, so
    // that one bad material does not make every object's index look wrong too.
    auto m = doc.find("materials");
    const std::size_t materials = m != doc.end() && m->is_array() ? m->size() : 0;
    if (const json* objects = r.array(doc, "objects")) {
        for (std::size_t i = 0; i < objects->size(); ++i) {
            SceneObject o;
            r.read_object((*objects)[i], fmt::format("object {}", i), materials, o);
            scene.objects.push_back(o);
        }
    }
    if (r.errors() > 0) return std::nullopt;
    return scene;
}

std::optional<RenderScene> read_render_scene(const std::string& path,
                                             const DiagnosticConsumer& diag) {
    auto text = read_file(path, diag);
    if (!text) return std::nullopt;
    return parse_render_scene(*text, path, diag);
}

}  // namespace arealight
