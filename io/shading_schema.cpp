// The light and material schema of CONTRACT 3 (shading_schema.hpp): types, ranges,
// planarity, convexity and orientation of polygons, disk and ellipsoid axes.
#include "shading_schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

namespace arealight {
namespace {

using json = nlohmann::json;

// Coordinates beyond this would overflow the products the shaders and the oracle form.
constexpr double kMaxCoordinate = 1e15;
constexpr double kPi = 3.14159265358979323846;

// The spacing of fp32 values at magnitude x: what rounding a coordinate of that size to
// fp32 can move it by, twice over.
double fp32_ulp(double x) {
    x = std::abs(x);
    if (!(x >= static_cast<double>(FLT_MIN))) return std::ldexp(1.0, -149);
    return std::ldexp(1.0, std::ilogb(x) - 23);
}

double max_abs(const Vec3& a) {
    return std::max({std::abs(a[0]), std::abs(a[1]), std::abs(a[2])});
}

Vec3 sub(const Vec3& a, const Vec3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double norm(const Vec3& a) {
    return std::sqrt(dot(a, a));
}

using io_detail::Reporter;

// Reads and checks the fields of a light or a material. Independent fields are all checked,
// so one pass reports every problem; a check that needs an earlier value runs only when it
// was valid.
class ShadingReader {
  public:
    // light_prefix, material_prefix: what the fields of a light and a material are named
    // after ("light.vertices" in a case, "vertices" in a scene's list of lights).
    ShadingReader(Reporter& rep, std::string where, const ValidationTolerances& tol,
                  std::string light_prefix, std::string material_prefix)
        : rep_(rep),
          where_(std::move(where)),
          tol_(tol),
          light_(std::move(light_prefix)),
          material_(std::move(material_prefix)) {}

    bool fail(const std::string& path, const std::string& reason) {
        rep_.error(where_, path, reason);
        return false;
    }

    bool number(const json& obj, const char* key, const std::string& path, double& out) {
        auto it = obj.find(key);
        if (it == obj.end()) return fail(path, "missing");
        if (!it->is_number()) return fail(path, "must be a number");
        out = it->get<double>();
        if (!(std::abs(out) <= kMaxCoordinate))
            return fail(path, fmt::format("{:g} is not finite or larger than {:g} in magnitude",
                                          out, kMaxCoordinate));
        return true;
    }

    bool text(const json& obj, const char* key, const std::string& path, std::string& out) {
        auto it = obj.find(key);
        if (it == obj.end()) return fail(path, "missing");
        if (!it->is_string()) return fail(path, "must be a string");
        out = it->get<std::string>();
        return true;
    }

    bool vec3(const json& v, const std::string& path, Vec3& out) {
        if (!v.is_array() || v.size() != 3) return fail(path, "must be an array of 3 numbers");
        for (std::size_t k = 0; k < 3; ++k) {
            if (!v[k].is_number()) return fail(path, "must be an array of 3 numbers");
            out[k] = v[k].get<double>();
            if (!(std::abs(out[k]) <= kMaxCoordinate))
                return fail(path,
                            fmt::format("component {} is {:g}: not finite or larger than {:g} "
                                        "in magnitude",
                                        k, out[k], kMaxCoordinate));
        }
        return true;
    }

    bool vec3_field(const json& obj, const char* key, const std::string& path, Vec3& out) {
        auto it = obj.find(key);
        if (it == obj.end()) return fail(path, "missing");
        return vec3(*it, path, out);
    }

    bool nonzero(const Vec3& v, const std::string& path) {
        return norm(v) > 0.0 || fail(path, "must have non-zero length");
    }

    // A direction: present, 3 finite numbers, and normalizable.
    bool direction(const json& obj, const char* key, const std::string& path, Vec3& out) {
        return vec3_field(obj, key, path, out) && nonzero(out, path);
    }

    void read_polygon(const json& L, Light& light) {
        auto it = L.find("vertices");
        if (it == L.end()) {
            fail(light_ + "vertices", "missing");
            return;
        }
        if (!it->is_array()) {
            fail(light_ + "vertices", "must be an array of points");
            return;
        }
        if (it->size() < 3 || it->size() > 8) {
            fail(light_ + "vertices",
                 fmt::format("has {} vertices; a polygon needs 3 to 8", it->size()));
            return;
        }
        bool ok = true;
        for (std::size_t i = 0; i < it->size(); ++i) {
            Vec3 x{};
            ok = vec3((*it)[i], light_ + fmt::format("vertices[{}]", i), x) && ok;
            light.vertices.push_back(x);
        }
        if (ok) check_polygon(light.vertices);
    }

    // Whether two edges that share no vertex cross, seen along the polygon's normal (the
    // largest cross product of two vertices about the centroid: a symmetric bowtie has no
    // Newell area); then an error naming them. A convex outline never crosses itself.
    bool crosses_itself(const std::vector<Vec3>& V, const Vec3& centroid) {
        const std::size_t n = V.size();
        if (n < 4) return false;
        Vec3 axis{};
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j) {
                const Vec3 c = cross(sub(V[i], centroid), sub(V[j], centroid));
                if (dot(c, c) > dot(axis, axis)) axis = c;
            }
        if (!(norm(axis) > 0.0)) return false;  // collinear: the zero-area check says so
        // Drop the axis's largest component: the other two span the plane's projection.
        int drop = 0;
        for (int k = 1; k < 3; ++k)
            if (std::abs(axis[k]) > std::abs(axis[drop])) drop = k;
        const int ux = drop == 0 ? 1 : 0, uy = drop == 2 ? 1 : 2;
        auto orient = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
            const double s = (b[ux] - a[ux]) * (c[uy] - a[uy]) - (b[uy] - a[uy]) * (c[ux] - a[ux]);
            return (s > 0.0) - (s < 0.0);
        };
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 2; j < n; ++j) {
                if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
                const Vec3 &a = V[i], &b = V[(i + 1) % n], &c = V[j], &d = V[(j + 1) % n];
                const int o1 = orient(a, b, c), o2 = orient(a, b, d);
                const int o3 = orient(c, d, a), o4 = orient(c, d, b);
                if (o1 * o2 < 0 && o3 * o4 < 0) {
                    fail(light_ + "vertices",
                         fmt::format("edges {}-{} and {}-{} cross: the polygon is "
                                     "self-intersecting (not convex)",
                                     i, (i + 1) % n, j, (j + 1) % n));
                    return true;
                }
            }
        return false;
    }

    // The geometric checks of a polygon, in dependency order; the first failure ends them,
    // since each later check is meaningless on a polygon that failed an earlier one.
    void check_polygon(const std::vector<Vec3>& V) {
        const std::size_t n = V.size();
        double diameter = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                diameter = std::max(diameter, norm(sub(V[i], V[j])));
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t next = (i + 1) % n;
            if (norm(sub(V[next], V[i])) <= 1e-12 * diameter) {
                fail(light_ + fmt::format("vertices[{}]", next),
                     fmt::format("repeats vertex {}", i));
                return;
            }
        }
        // Newell's normal about the centroid: relative to the origin it would lose the
        // polygon's own size to cancellation when the light lies far from the origin.
        Vec3 centroid{};
        for (const auto& x : V)
            for (int k = 0; k < 3; ++k) centroid[k] += x[k] / static_cast<double>(n);
        Vec3 newell{};
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 c = cross(sub(V[i], centroid), sub(V[(i + 1) % n], centroid));
            for (int k = 0; k < 3; ++k) newell[k] += c[k];
        }
        if (crosses_itself(V, centroid)) return;
        const double nl = norm(newell);
        if (!(nl > 0.0)) {
            fail(light_ + "vertices", "the polygon has zero area");
            return;
        }
        const Vec3 N = {newell[0] / nl, newell[1] / nl, newell[2] / nl};
        double largest = 0.0;
        for (const auto& x : V) largest = std::max(largest, max_abs(x));
        const double off_plane =
            tol_.coplanar_rel * diameter + tol_.fp32_ulps * fp32_ulp(largest);
        for (std::size_t i = 0; i < n; ++i) {
            const double d = std::abs(dot(N, sub(V[i], centroid)));
            if (d > off_plane) {
                fail(light_ + fmt::format("vertices[{}]", i),
                     fmt::format("is {:.3g} off the polygon's plane, more than the tolerance "
                                 "{:.3g} ({:g} of its diameter {:.3g} plus {:g} fp32 ulp at "
                                 "{:.3g}): not coplanar",
                                 d, off_plane, tol_.coplanar_rel, diameter, tol_.fp32_ulps,
                                 largest));
                return;
            }
        }
        double total_turn = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 a = sub(V[i], V[(i + n - 1) % n]), b = sub(V[(i + 1) % n], V[i]);
            const double sin_turn = dot(cross(a, b), N) / (norm(a) * norm(b));
            if (std::abs(sin_turn) <= tol_.collinear_rel) {
                fail(light_ + fmt::format("vertices[{}]", i),
                     "is collinear with its neighbours (a straight or folded-back corner)");
                return;
            }
            if (sin_turn < 0.0) {
                fail(light_ + fmt::format("vertices[{}]", i),
                     "is a reflex corner: the polygon is not convex");
                return;
            }
            total_turn += std::atan2(dot(cross(a, b), N), dot(a, b));
        }
        // Every turn having one sign still admits star polygons (a pentagram turns 4 pi);
        // a convex polygon turns exactly once around.
        if (total_turn > 3.0 * kPi) {
            fail(light_ + "vertices",
                 fmt::format("the outline winds {:.0f} times around: the polygon intersects "
                             "itself and is not convex",
                             total_turn / (2.0 * kPi)));
        }
    }

    // |a.b| within orthogonal_rel |a||b| plus what fp32 rounding of each vector's
    // components moves the product by (CONTRACT 3); else an error on `path`.
    void check_orthogonal(const Vec3& a, const Vec3& b, const std::string& path,
                          const std::string& other) {
        const double la = norm(a), lb = norm(b);
        const double tol = tol_.orthogonal_rel * la * lb +
                           tol_.fp32_ulps * (fp32_ulp(max_abs(a)) * lb + fp32_ulp(max_abs(b)) * la);
        const double d = std::abs(dot(a, b));
        if (d > tol)
            fail(path, fmt::format("must be orthogonal to {} (|{}.{}| is {:.3g}, more than the "
                                   "tolerance {:.3g})",
                                   other, other, path, d, tol));
    }

    void known(const json& obj, const std::string& prefix, io_detail::FieldNames names,
               io_detail::FieldNames extra = {}) {
        io_detail::check_fields(rep_, where_, prefix, obj, names, extra);
    }

    void read_two_sided(const json& L, Light& light) {
        if (auto ts = L.find("two_sided"); ts != L.end()) {
            if (!ts->is_boolean())
                fail(light_ + "two_sided", "must be true or false");
            else
                light.two_sided = ts->get<bool>();
        }
    }

    void read_light_fields(const json& L, Light& light, io_detail::FieldNames extra = {}) {
        std::string type;
        if (!text(L, "type", light_ + "type", type)) return;
        if (type == "polygon") {
            light.type = LightType::Polygon;
            known(L, light_, {"type", "vertices", "two_sided"}, extra);
            read_two_sided(L, light);
            read_polygon(L, light);
        } else if (type == "disk") {
            light.type = LightType::Disk;
            known(L, light_, {"type", "center", "u", "v", "two_sided"}, extra);
            read_two_sided(L, light);
            vec3_field(L, "center", light_ + "center", light.center);
            const bool u = direction(L, "u", light_ + "u", light.u);
            const bool v = direction(L, "v", light_ + "v", light.v);
            if (u && v) check_orthogonal(light.u, light.v, light_ + "v", light_ + "u");
        } else if (type == "sphere") {
            light.type = LightType::Sphere;
            known(L, light_, {"type", "center", "radius"}, extra);
            vec3_field(L, "center", light_ + "center", light.center);
            if (number(L, "radius", light_ + "radius", light.radius) && !(light.radius > 0.0))
                fail(light_ + "radius", fmt::format("{:g} is not positive", light.radius));
        } else if (type == "ellipsoid") {
            light.type = LightType::Ellipsoid;
            known(L, light_, {"type", "center", "axes"}, extra);
            vec3_field(L, "center", light_ + "center", light.center);
            read_axes(L, light);
        } else {
            fail(light_ + "type",
                 "unknown type '" + type + "' (expected polygon, disk, sphere or ellipsoid)");
        }
    }

    void read_axes(const json& L, Light& light) {
        auto a = L.find("axes");
        if (a == L.end()) {
            fail(light_ + "axes", "missing");
            return;
        }
        if (!a->is_array() || a->size() != 3) {
            fail(light_ + "axes",
                 a->is_array()
                     ? fmt::format("has {} vectors; an ellipsoid needs exactly 3", a->size())
                     : "must be an array of exactly 3 vectors");
            return;
        }
        bool ok = true;
        for (std::size_t i = 0; i < 3; ++i) {
            const std::string path = light_ + fmt::format("axes[{}]", i);
            ok = (vec3((*a)[i], path, light.axes[i]) && nonzero(light.axes[i], path)) && ok;
        }
        if (!ok) return;
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = i + 1; j < 3; ++j)
                check_orthogonal(light.axes[i], light.axes[j], light_ + fmt::format("axes[{}]", j),
                                 light_ + fmt::format("axes[{}]", i));
    }

    void read_material_fields(const json& M, Material& m, io_detail::FieldNames extra = {}) {
        std::string name;
        if (!text(M, "distribution", material_ + "distribution", name)) return;
        if (name == "phong" || name == "blinn") {
            m.distribution = name == "phong" ? Distribution::Phong : Distribution::Blinn;
            // Phong has no Fresnel factor (CONTRACT 2): f0 is no field of its.
            if (name == "phong")
                known(M, material_, {"distribution", "exponent"}, extra);
            else
                known(M, material_, {"distribution", "exponent", "f0"}, extra);
            if (number(M, "exponent", material_ + "exponent", m.exponent) &&
                !(m.exponent >= 1.0 && m.exponent <= 100000.0)) {
                fail(material_ + "exponent",
                     fmt::format("{:g} is outside [1, 100000]", m.exponent));
            }
        } else if (name == "beckmann" || name == "ggx") {
            m.distribution = name == "ggx" ? Distribution::Ggx : Distribution::Beckmann;
            known(M, material_, {"distribution", "alpha", "f0"}, extra);
            if (number(M, "alpha", material_ + "alpha", m.alpha) &&
                !(m.alpha >= 0.001 && m.alpha <= 1.0)) {
                fail(material_ + "alpha", fmt::format("{:g} is outside [0.001, 1]", m.alpha));
            }
        } else {
            fail(material_ + "distribution",
                 "unknown distribution '" + name + "' (expected phong, blinn, beckmann or ggx)");
            return;
        }
        if (m.distribution != Distribution::Phong) read_f0(M, m);
    }

    // The optional Schlick f0 of a microfacet material (CONTRACT 2): absent leaves F = 1.
    void read_f0(const json& M, Material& m) {
        if (M.find("f0") == M.end()) return;
        double f0 = 0.0;
        if (!number(M, "f0", material_ + "f0", f0)) return;
        if (!(f0 >= 0.0 && f0 <= 1.0)) {
            fail(material_ + "f0", fmt::format("{:g} is outside [0, 1]", f0));
            return;
        }
        m.f0 = f0;
        m.has_f0 = true;
    }

  private:
    Reporter& rep_;
    std::string where_;
    const ValidationTolerances& tol_;
    std::string light_, material_;
};

}  // namespace

namespace io_detail {

void read_light_object(Reporter& rep, const std::string& where, const std::string& prefix,
                       const json& light, const ValidationTolerances& tol, Light& out,
                       FieldNames extra) {
    ShadingReader(rep, where, tol, prefix, {}).read_light_fields(light, out, extra);
}

void read_material_object(Reporter& rep, const std::string& where, const std::string& prefix,
                          const json& material, Material& out, FieldNames extra) {
    const ValidationTolerances unused;
    ShadingReader(rep, where, unused, {}, prefix).read_material_fields(material, out, extra);
}

bool read_point(Reporter& rep, const std::string& where, const json& obj, const char* key,
                const std::string& field, Vec3& out) {
    const ValidationTolerances unused;
    return ShadingReader(rep, where, unused, {}, {}).vec3_field(obj, key, field, out);
}

bool read_direction(Reporter& rep, const std::string& where, const json& obj, const char* key,
                    const std::string& field, Vec3& out) {
    const ValidationTolerances unused;
    return ShadingReader(rep, where, unused, {}, {}).direction(obj, key, field, out);
}

}  // namespace io_detail
}  // namespace arealight
