// Helpers shared by the tests: case construction, rigid motions, tolerances.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <random>
#include <string>
#include <vector>

#include "arealight/case.hpp"

namespace arealight::test {

inline glm::dvec3 g(const Vec3& a) {
    return {a[0], a[1], a[2]};
}
inline Vec3 a3(const glm::dvec3& v) {
    return {v.x, v.y, v.z};
}

// The acceptance bar of every exact method (issues 4 and 13): p95 and max of the
// relative error against the oracle (floor 1e-3) over diffuse, specular and moment
// or ndf. What is left at fp64 is the fp32 rounding of the uploaded case.
constexpr double kExactP95Tol = 1e-5;
constexpr double kExactMaxTol = 1e-4;

// |x - ref| / max(|ref|, floor): the metric of shared/tools/score.
inline double rel_err(double x, double ref, double floor = 1e-3) {
    return std::abs(x - ref) / std::max(std::abs(ref), floor);
}

inline Case polygon_case(const std::string& id, std::vector<glm::dvec3> verts, glm::dvec3 n,
                         glm::dvec3 v, Distribution d, double param, bool two_sided = false) {
    Case c;
    c.id = id;
    c.p = {0, 0, 0};
    c.n = a3(n);
    c.v = a3(v);
    c.light.type = LightType::Polygon;
    for (auto& x : verts) c.light.vertices.push_back(a3(x));
    c.light.two_sided = two_sided;
    c.material.distribution = d;
    (d == Distribution::Phong || d == Distribution::Blinn ? c.material.exponent
                                                          : c.material.alpha) = param;
    return c;
}

// The material's distribution and its parameter (exponent or alpha).
inline void set_param(Case& c, Distribution d, double param) {
    c.material.distribution = d;
    (d == Distribution::Phong || d == Distribution::Blinn ? c.material.exponent
                                                          : c.material.alpha) = param;
}

// Uniformly distributed rotation (normalized Gaussian quaternion).
inline glm::dmat3 random_rotation(std::mt19937_64& rng) {
    std::normal_distribution<double> N(0.0, 1.0);
    double w = N(rng), x = N(rng), y = N(rng), z = N(rng);
    const double s = 1.0 / std::sqrt(w * w + x * x + y * y + z * z);
    w *= s, x *= s, y *= s, z *= s;
    return glm::transpose(
        glm::dmat3(1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                   2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                   2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)));
}

// Applies x -> R x + t to every point and R to every direction of the case.
inline Case transformed(const Case& c, const glm::dmat3& R, const glm::dvec3& t) {
    Case o = c;
    auto P = [&](const Vec3& x) { return a3(R * g(x) + t); };
    auto D = [&](const Vec3& x) { return a3(R * g(x)); };
    o.p = P(c.p);
    o.n = D(c.n);
    o.v = D(c.v);
    for (auto& x : o.light.vertices) x = P(x);
    o.light.center = P(c.light.center);
    o.light.u = D(c.light.u);
    o.light.v = D(c.light.v);
    for (auto& a : o.light.axes) a = D(a);
    return o;
}

// For each polygon case, a disk, a sphere and an ellipsoid light of about its size
// and place (seeded): the disk in the polygon's plane, facing the same way, with
// random orthogonal semi-axes of 0.4 to 1 times the polygon's radius; the sphere
// and the ellipsoid centred there too, sized so that p stays outside.
inline CaseSet curved_cases_like(const CaseSet& polygons, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    CaseSet out;
    for (const Case& c : polygons.cases) {
        const auto& vs = c.light.vertices;
        glm::dvec3 centre(0.0);
        for (const auto& x : vs) centre += g(x);
        centre /= static_cast<double>(vs.size());
        double radius = 0.0;
        for (const auto& x : vs) radius = std::max(radius, glm::length(g(x) - centre));
        const glm::dvec3 normal =
            glm::normalize(glm::cross(g(vs[1]) - g(vs[0]), g(vs[2]) - g(vs[0])));
        glm::dvec3 t = glm::cross(normal, glm::dvec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5));
        t = glm::normalize(t);
        const glm::dvec3 b = glm::cross(normal, t);
        const double ru = radius * (0.4 + 0.6 * U(rng)), rv = radius * (0.4 + 0.6 * U(rng));
        const double dist = glm::length(centre - g(c.p));
        Case disk = c;
        disk.id += "-disk";
        disk.light = Light{};
        disk.light.type = LightType::Disk;
        disk.light.center = a3(centre);
        disk.light.u = a3(ru * t);
        disk.light.v = a3(rv * b);
        disk.light.two_sided = c.light.two_sided;
        Case sphere = disk;
        sphere.id = c.id + "-sphere";
        sphere.light.type = LightType::Sphere;
        sphere.light.radius = std::min(ru, 0.8 * dist);
        Case ellipsoid = disk;
        ellipsoid.id = c.id + "-ellipsoid";
        ellipsoid.light.type = LightType::Ellipsoid;
        const double scale = std::min(1.0, 0.8 * dist / std::max({ru, rv, radius}));
        ellipsoid.light.axes = {a3(scale * ru * t), a3(scale * rv * b),
                                a3(scale * radius * (0.2 + 0.8 * U(rng)) * normal)};
        out.cases.insert(out.cases.end(), {disk, sphere, ellipsoid});
    }
    return out;
}

}  // namespace arealight::test
