// arealight-cases/1 reader with full validation, arealight-results/1 writer.
#include "arealight/case_io.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "arealight/atomic_file.hpp"

namespace arealight {
namespace {

using json = nlohmann::json;

// Coordinates beyond this would overflow the products the shaders form.
constexpr double kMaxCoordinate = 1e15;

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

// Collects "FILE: case 'ID': field 'FIELD': reason" messages for one file.
class Reporter {
  public:
    Reporter(std::string file, const DiagnosticConsumer& diag)
        : file_(std::move(file)), diag_(diag) {}
    void error(const std::string& where, const std::string& field, const std::string& reason) {
        ++errors_;
        std::string msg = file_ + ": ";
        if (!where.empty()) msg += where + ": ";
        if (!field.empty()) msg += "field '" + field + "': ";
        msg += reason;
        if (diag_) diag_({Severity::Error, file_, 0, msg});
    }
    int errors() const { return errors_; }

  private:
    std::string file_;
    const DiagnosticConsumer& diag_;
    int errors_ = 0;
};

// Reads and checks the fields of one case; every problem is reported.
class CaseReader {
  public:
    CaseReader(Reporter& rep, std::string where, const ValidationTolerances& tol)
        : rep_(rep), where_(std::move(where)), tol_(tol) {}

    bool number(const json& obj, const std::string& key, const std::string& path, double& out) {
        auto it = obj.find(key);
        if (it == obj.end()) return fail(path, "missing");
        if (!it->is_number()) return fail(path, "must be a number");
        out = it->get<double>();
        if (!std::isfinite(out) || std::abs(out) > kMaxCoordinate)
            return fail(
                path, fmt::format("must be finite and at most {:g} in magnitude", kMaxCoordinate));
        return true;
    }

    bool vec3(const json& v, const std::string& path, Vec3& out) {
        if (!v.is_array() || v.size() != 3) return fail(path, "must be an array of 3 numbers");
        for (int k = 0; k < 3; ++k) {
            if (!v[k].is_number()) return fail(path, "must be an array of 3 numbers");
            out[k] = v[k].get<double>();
            if (!std::isfinite(out[k]) || std::abs(out[k]) > kMaxCoordinate)
                return fail(path, "components must be finite and at most 1e15 in magnitude");
        }
        return true;
    }

    bool vec3_field(const json& obj, const std::string& key, const std::string& path, Vec3& out) {
        auto it = obj.find(key);
        if (it == obj.end()) return fail(path, "missing");
        return vec3(*it, path, out);
    }

    bool nonzero(const Vec3& v, const std::string& path) {
        return norm(v) > 0.0 ? true : fail(path, "must have non-zero length");
    }

    bool fail(const std::string& path, const std::string& reason) {
        rep_.error(where_, path, reason);
        ok_ = false;
        return false;
    }
    bool ok() const { return ok_; }

    void read_polygon(const json& L, Light& light) {
        auto it = L.find("vertices");
        if (it == L.end()) {
            fail("light.vertices", "missing");
            return;
        }
        if (!it->is_array()) {
            fail("light.vertices", "must be an array of points");
            return;
        }
        if (it->size() < 3 || it->size() > 8) {
            fail("light.vertices",
                 fmt::format("has {} vertices; a polygon needs 3 to 8", it->size()));
            return;
        }
        for (std::size_t i = 0; i < it->size(); ++i) {
            Vec3 x;
            if (!vec3((*it)[i], fmt::format("light.vertices[{}]", i), x)) return;
            light.vertices.push_back(x);
        }
        check_polygon(light.vertices);
    }

    // Planar within tol.coplanar_rel of the diameter, no repeated or collinear
    // consecutive vertices, and convex (every turn has the sign of the Newell normal).
    void check_polygon(const std::vector<Vec3>& V) {
        const std::size_t n = V.size();
        double diameter = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                diameter = std::max(diameter, norm(sub(V[i], V[j])));
        for (std::size_t i = 0; i < n; ++i) {
            if (norm(sub(V[(i + 1) % n], V[i])) <= 1e-12 * diameter) {
                fail(fmt::format("light.vertices[{}]", (i + 1) % n),
                     fmt::format("repeats vertex {}", i));
                return;
            }
        }
        Vec3 newell{};
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 c = cross(V[i], V[(i + 1) % n]);
            for (int k = 0; k < 3; ++k) newell[k] += c[k];
        }
        const double nl = norm(newell);
        if (!(nl > 0.0)) {
            fail("light.vertices", "polygon has zero area");
            return;
        }
        const Vec3 N = {newell[0] / nl, newell[1] / nl, newell[2] / nl};
        Vec3 centroid{};
        for (const auto& x : V)
            for (int k = 0; k < 3; ++k) centroid[k] += x[k] / n;
        for (std::size_t i = 0; i < n; ++i) {
            const double d = std::abs(dot(N, sub(V[i], centroid)));
            if (d > tol_.coplanar_rel * diameter) {
                fail(fmt::format("light.vertices[{}]", i),
                     fmt::format("is {:.3g} off the polygon's plane (more than {:g} of its size): "
                                 "not coplanar",
                                 d, tol_.coplanar_rel));
                return;
            }
        }
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 a = sub(V[i], V[(i + n - 1) % n]), b = sub(V[(i + 1) % n], V[i]);
            const double turn = dot(cross(a, b), N) / (norm(a) * norm(b));
            if (std::abs(turn) <= tol_.collinear_rel) {
                fail(fmt::format("light.vertices[{}]", i), "is collinear with its neighbours");
                return;
            }
            if (turn < 0.0) {
                fail(fmt::format("light.vertices[{}]", i), "makes the polygon non-convex");
                return;
            }
        }
    }

    bool orthogonal(const Vec3& a, const Vec3& b) {
        return std::abs(dot(a, b)) <= 1e-6 * norm(a) * norm(b);
    }

    void read_light(const json& c, Light& light) {
        auto it = c.find("light");
        if (it == c.end()) {
            fail("light", "missing");
            return;
        }
        if (!it->is_object()) {
            fail("light", "must be an object");
            return;
        }
        const json& L = *it;
        auto t = L.find("type");
        if (t == L.end() || !t->is_string()) {
            fail("light.type", t == L.end() ? "missing" : "must be a string");
            return;
        }
        const std::string type = t->get<std::string>();
        if (auto ts = L.find("two_sided"); ts != L.end()) {
            if (!ts->is_boolean())
                fail("light.two_sided", "must be true or false");
            else
                light.two_sided = ts->get<bool>();
        }
        if (type == "polygon") {
            light.type = LightType::Polygon;
            read_polygon(L, light);
        } else if (type == "disk") {
            light.type = LightType::Disk;
            if (vec3_field(L, "center", "light.center", light.center) &&
                vec3_field(L, "u", "light.u", light.u) && vec3_field(L, "v", "light.v", light.v) &&
                nonzero(light.u, "light.u") && nonzero(light.v, "light.v") &&
                !orthogonal(light.u, light.v)) {
                fail("light.v", "must be orthogonal to light.u");
            }
        } else if (type == "sphere") {
            light.type = LightType::Sphere;
            if (vec3_field(L, "center", "light.center", light.center) &&
                number(L, "radius", "light.radius", light.radius) && !(light.radius > 0.0)) {
                fail("light.radius", "must be positive");
            }
        } else if (type == "ellipsoid") {
            light.type = LightType::Ellipsoid;
            if (!vec3_field(L, "center", "light.center", light.center)) return;
            auto a = L.find("axes");
            if (a == L.end()) {
                fail("light.axes", "missing");
                return;
            }
            if (!a->is_array() || a->size() != 3) {
                fail("light.axes", "must be an array of exactly 3 vectors");
                return;
            }
            for (int i = 0; i < 3; ++i) {
                const std::string path = fmt::format("light.axes[{}]", i);
                if (!vec3((*a)[i], path, light.axes[i]) || !nonzero(light.axes[i], path)) return;
            }
            for (int i = 0; i < 3; ++i) {
                for (int j = i + 1; j < 3; ++j) {
                    if (!orthogonal(light.axes[i], light.axes[j])) {
                        fail(fmt::format("light.axes[{}]", j),
                             fmt::format("must be orthogonal to light.axes[{}]", i));
                        return;
                    }
                }
            }
        } else {
            fail("light.type",
                 "unknown type '" + type + "' (expected polygon, disk, sphere or ellipsoid)");
        }
    }

    void read_material(const json& c, Material& m) {
        auto it = c.find("material");
        if (it == c.end() || !it->is_object()) {
            fail("material", it == c.end() ? "missing" : "must be an object");
            return;
        }
        const json& M = *it;
        auto d = M.find("distribution");
        if (d == M.end() || !d->is_string()) {
            fail("material.distribution", d == M.end() ? "missing" : "must be a string");
            return;
        }
        const std::string name = d->get<std::string>();
        if (name == "phong" || name == "blinn") {
            m.distribution = name == "phong" ? Distribution::Phong : Distribution::Blinn;
            if (number(M, "exponent", "material.exponent", m.exponent) &&
                !(m.exponent >= 1.0 && m.exponent <= 100000.0)) {
                fail("material.exponent", fmt::format("{:g} is outside [1, 100000]", m.exponent));
            }
        } else if (name == "beckmann" || name == "ggx") {
            m.distribution = name == "ggx" ? Distribution::Ggx : Distribution::Beckmann;
            if (number(M, "alpha", "material.alpha", m.alpha) &&
                !(m.alpha >= 0.001 && m.alpha <= 1.0)) {
                fail("material.alpha", fmt::format("{:g} is outside [0.001, 1]", m.alpha));
            }
        } else {
            fail("material.distribution",
                 "unknown distribution '" + name + "' (expected phong, blinn, beckmann or ggx)");
        }
    }

  private:
    Reporter& rep_;
    std::string where_;
    const ValidationTolerances& tol_;
    bool ok_ = true;
};

std::string file_name_of(const std::string& path) {
    return path;
}

void put(json& j, const char* key, const std::optional<double>& v) {
    if (!v) return;
    // JSON has no NaN or infinity: a non-finite value is written as null.
    if (std::isfinite(*v))
        j[key] = *v;
    else
        j[key] = nullptr;
}

}  // namespace

std::optional<CaseSet> parse_cases(const std::string& text, const std::string& name,
                                   const DiagnosticConsumer& diag,
                                   const ValidationTolerances& tol) {
    Reporter rep(file_name_of(name), diag);
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error& e) {
        rep.error("", "", std::string("invalid JSON: ") + e.what());
        return std::nullopt;
    }
    if (!doc.is_object()) {
        rep.error("", "format", "the file must be a JSON object");
        return std::nullopt;
    }
    auto f = doc.find("format");
    if (f == doc.end() || !f->is_string() || f->get<std::string>() != "arealight-cases/1") {
        rep.error("", "format", "must be \"arealight-cases/1\"");
        return std::nullopt;
    }
    auto cs = doc.find("cases");
    if (cs == doc.end() || !cs->is_array()) {
        rep.error("", "cases", "must be an array of cases");
        return std::nullopt;
    }
    CaseSet set;
    std::set<std::string> ids;
    for (std::size_t i = 0; i < cs->size(); ++i) {
        const json& c = (*cs)[i];
        Case out;
        std::string where = fmt::format("case #{}", i);
        if (!c.is_object()) {
            rep.error(where, "", "must be an object");
            continue;
        }
        auto id = c.find("id");
        if (id == c.end() || !id->is_string() || id->get<std::string>().empty()) {
            rep.error(where, "id", id == c.end() ? "missing" : "must be a non-empty string");
        } else {
            out.id = id->get<std::string>();
            where = "case '" + out.id + "'";
            if (!ids.insert(out.id).second)
                rep.error(where, "id", "duplicates an earlier case's id");
        }
        CaseReader r(rep, where, tol);
        r.vec3_field(c, "p", "p", out.p);
        if (r.vec3_field(c, "n", "n", out.n)) r.nonzero(out.n, "n");
        if (r.vec3_field(c, "v", "v", out.v)) r.nonzero(out.v, "v");
        r.read_light(c, out.light);
        r.read_material(c, out.material);
        set.cases.push_back(std::move(out));
    }
    if (rep.errors() > 0) return std::nullopt;
    return set;
}

std::optional<CaseSet> read_cases(const std::string& path, const DiagnosticConsumer& diag,
                                  const ValidationTolerances& tol) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int err = errno;
        if (diag) diag({Severity::Error, path, 0, path + ": cannot read: " + std::strerror(err)});
        return std::nullopt;
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    return parse_cases(ss.str(), path, diag, tol);
}

std::string format_results(const ResultSet& results) {
    json doc = json::object();
    doc["format"] = "arealight-results/1";
    doc["variant"] = results.variant;
    doc["backend"] = results.backend;
    json arr = json::array();
    for (const auto& r : results.results) {
        json j = json::object();
        j["id"] = r.id;
        put(j, "diffuse", r.diffuse);
        put(j, "specular", r.specular);
        put(j, "ndf", r.ndf);
        put(j, "moment", r.moment);
        put(j, "error", r.error);
        put(j, "error_diffuse", r.error_diffuse);
        put(j, "error_ndf", r.error_ndf);
        put(j, "error_moment", r.error_moment);
        if (r.converged) j["converged"] = *r.converged;
        arr.push_back(std::move(j));
    }
    doc["results"] = std::move(arr);
    // nlohmann writes doubles with max_digits10 digits: they read back bit-exact.
    return doc.dump(1) + "\n";
}

bool write_results(const std::string& path, const ResultSet& results,
                   const DiagnosticConsumer& diag) {
    return write_file_atomic(path, format_results(results), diag);
}

std::optional<ResultSet> read_results(const std::string& path, const DiagnosticConsumer& diag) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int err = errno;
        if (diag) diag({Severity::Error, path, 0, path + ": cannot read: " + std::strerror(err)});
        return std::nullopt;
    }
    json doc;
    try {
        doc = json::parse(in);
    } catch (const json::parse_error& e) {
        if (diag) diag({Severity::Error, path, 0, path + ": invalid JSON: " + e.what()});
        return std::nullopt;
    }
    if (!doc.is_object() || doc.value("format", "") != "arealight-results/1" ||
        !doc.contains("results") || !doc["results"].is_array()) {
        if (diag)
            diag({Severity::Error, path, 0,
                  path + ": field 'format': not an arealight-results/1 file"});
        return std::nullopt;
    }
    ResultSet out;
    out.variant = doc.value("variant", "");
    out.backend = doc.value("backend", "");
    for (const auto& j : doc["results"]) {
        CaseResult r;
        r.id = j.value("id", "");
        auto get = [&](const char* key, std::optional<double>& v) {
            auto it = j.find(key);
            if (it != j.end() && it->is_number()) v = it->get<double>();
        };
        get("diffuse", r.diffuse);
        get("specular", r.specular);
        get("ndf", r.ndf);
        get("moment", r.moment);
        get("error", r.error);
        get("error_diffuse", r.error_diffuse);
        get("error_ndf", r.error_ndf);
        get("error_moment", r.error_moment);
        if (auto it = j.find("converged"); it != j.end() && it->is_boolean())
            r.converged = it->get<bool>();
        out.results.push_back(std::move(r));
    }
    return out;
}

}  // namespace arealight
