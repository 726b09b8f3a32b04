// The renderer's scene reader: lights, materials and quality through the core scene
// reader (parse_scene, CONTRACT 7), so that they are validated exactly as a case's fields
// are; camera, objects and each light's intensity here, in the same message format.
#include "arealight/render_scene.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "arealight/read_file.hpp"
#include "json_fields.hpp"
#include "shading_schema.hpp"

namespace arealight {
namespace {

using json = nlohmann::json;

// Larger coordinates would overflow the products a ray cast forms.
constexpr double kMaxCoordinate = 1e15;

class SceneReader {
  public:
    SceneReader(std::string file, const DiagnosticConsumer& diag) : rep_(std::move(file), diag) {}

    bool fail(const std::string& where, const std::string& field, const std::string& reason) {
        rep_.error(where, field, reason);
        return false;
    }
    int errors() const { return rep_.errors(); }

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
        io_detail::check_fields(rep_, "camera", "", c, {"eye", "target", "up", "fov_deg"});
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
            io_detail::check_fields(rep_, where, "", o,
                                    {"type", "point", "normal", "material", "albedo"});
            vec3(o, "point", where, out.point);
            nonzero(o, "normal", where, out.normal);
        } else if (*t == "sphere") {
            out.type = ObjectType::Sphere;
            io_detail::check_fields(rep_, where, "", o,
                                    {"type", "center", "radius", "material", "albedo"});
            vec3(o, "center", where, out.center);
            if (number(o, "radius", where, out.radius) && !(out.radius > 0))
                fail(where, "radius", fmt::format("{:g} is not positive", out.radius));
        } else if (*t == "box") {
            out.type = ObjectType::Box;
            io_detail::check_fields(rep_, where, "", o, {"type", "min", "max", "material", "albedo"});
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
                 fmt::format("{} is not an index into materials (0 to {})", io_detail::describe(*m),
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

    // Each light's optional uniform radiance; its CONTRACT 3 fields are parse_scene's.
    void read_intensities(const json& doc, RenderScene& scene) {
        auto lights = doc.find("lights");
        if (lights == doc.end() || !lights->is_array()) return;
        for (std::size_t i = 0; i < lights->size(); ++i) {
            double intensity = 1.0;
            const json& L = (*lights)[i];
            const std::string where = fmt::format("light {}", i);
            if (L.is_object() && L.find("intensity") != L.end() &&
                number(L, "intensity", where, intensity) && !(intensity >= 0))
                fail(where, "intensity", fmt::format("{:g} is negative", intensity));
            scene.intensities.push_back(intensity);
        }
    }

    const json* array(const json& doc, const char* key) {
        auto it = doc.find(key);
        if (it == doc.end() || !it->is_array()) {
            fail("", key, it == doc.end() ? "missing" : "must be an array");
            return nullptr;
        }
        return &*it;
    }

  private:
    io_detail::Reporter rep_;
};

}  // namespace

std::optional<RenderScene> parse_render_scene(const std::string& text, const std::string& name,
                                              const DiagnosticConsumer& diag) {
    auto core = parse_scene(text, name, diag);
    // parse_scene has said what is wrong with a file that is no scene at all.
    const json doc = json::parse(text, nullptr, false);
    if (!doc.is_object()) return std::nullopt;
    auto f = doc.find("format");
    if (f == doc.end() || *f != "arealight-scene/1") return std::nullopt;
    RenderScene scene;
    if (core) static_cast<Scene&>(scene) = std::move(*core);
    SceneReader r(name, diag);
    r.read_intensities(doc, scene);
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
    if (!core || r.errors() > 0) return std::nullopt;
    return scene;
}

std::optional<RenderScene> read_render_scene(const std::string& path,
                                             const DiagnosticConsumer& diag) {
    auto text = read_file(path, diag);
    if (!text) return std::nullopt;
    return parse_render_scene(*text, path, diag);
}

}  // namespace arealight
