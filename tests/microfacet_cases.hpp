// Seeded random microfacet polygon cases shared by the microfacet shading tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace arealight::test {

constexpr double kPi_ = 3.14159265358979323846;

// Random convex polygons around the mirror direction of views from normal to
// grazing (n.v down to 0.02), some crossing the horizon, some large; parameters
// log-uniform over the contract's range (alpha in [1e-3, 1], N in [1, 1e5]); a
// third two-sided, a third with Schlick f0. A random rigid motion on each. Case ids
// are the prefix and the index.
inline CaseSet random_microfacet_polygons(std::uint64_t seed, int count, Distribution d,
                                          const std::string& prefix) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    CaseSet set;
    for (int i = 0; i < count; ++i) {
        glm::dvec3 n(0, 0, 1);
        const double nv = 0.02 + 0.98 * U(rng), ph = 2 * kPi_ * U(rng);
        const double sv = std::sqrt(1 - nv * nv);
        glm::dvec3 v(sv * std::cos(ph), sv * std::sin(ph), nv);
        glm::dvec3 r = 2 * nv * n - v;
        glm::dvec3 dir =
            glm::normalize(r + 0.8 * glm::dvec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.4));
        glm::dvec3 t1 = glm::normalize(glm::cross(dir, glm::dvec3(0.3, 0.5, 0.8)));
        glm::dvec3 t2 = glm::cross(dir, t1);
        const int k = 3 + static_cast<int>(U(rng) * 6);
        const double dist = 1 + 4 * U(rng), rad = (0.05 + 1.5 * U(rng)) * dist * 0.5;
        std::vector<glm::dvec3> verts;
        for (int j = 0; j < k; ++j) {
            const double a = -2 * kPi_ * (j + 0.7 * U(rng)) / k;  // clockwise about dir
            verts.push_back(dist * dir + rad * (std::cos(a) * t1 + std::sin(a) * t2));
        }
        const double p = d == Distribution::Blinn ? std::exp(std::log(1e5) * U(rng))
                                                  : std::exp(std::log(1e-3) * U(rng));
        Case c = polygon_case(prefix + std::to_string(i), verts, n, v, d, p, i % 3 == 0);
        if (i % 3 == 0 && U(rng) < 0.5)
            std::reverse(c.light.vertices.begin(), c.light.vertices.end());
        if (i % 3 == 1) {
            c.material.f0 = U(rng);
            c.material.has_f0 = true;
        }
        set.cases.push_back(transformed(
            c, random_rotation(rng), glm::dvec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5) * 10.0));
    }
    return set;
}

// Large polygons that hold the whole lobe, the case where the specular factor W (G2, h.v,
// 1/n.v) varies most across the D-weighted half vectors: a regular k-gon (k 4 to 8) about the
// mirror direction r, tilted off it by up to 0.3 rad, 1 to 3 away, its circumradius 1.5 to
// 3 times that (lit to the horizon where it crosses it); n.v uniform in [nv_lo, nv_hi], alpha
// in [alpha_lo, alpha_hi] log-uniform (blinn: N = 2 / alpha^2 - 2), f0 on every other case.
inline CaseSet lobe_filling_microfacet_polygons(std::uint64_t seed, int count, Distribution d,
                                                double nv_lo = 0.15, double nv_hi = 0.9,
                                                double alpha_lo = 0.15, double alpha_hi = 0.6) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    CaseSet set;
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 n(0, 0, 1);
        const double nv = nv_lo + (nv_hi - nv_lo) * U(rng), sv = std::sqrt(1 - nv * nv);
        const glm::dvec3 v(sv, 0, nv), r = 2 * nv * n - v;
        const glm::dvec3 dir = glm::normalize(
            r + 0.3 * glm::dvec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5));
        const glm::dvec3 t1 = glm::normalize(glm::cross(dir, glm::dvec3(0.3, 0.5, 0.8)));
        const glm::dvec3 t2 = glm::cross(dir, t1);
        const int k = 4 + static_cast<int>(U(rng) * 5);
        const double dist = 1 + 2 * U(rng), rad = (1.5 + 1.5 * U(rng)) * dist;
        std::vector<glm::dvec3> verts;
        for (int j = 0; j < k; ++j) {
            const double a = -2 * kPi_ * j / k;  // clockwise about dir
            verts.push_back(dist * dir + rad * (std::cos(a) * t1 + std::sin(a) * t2));
        }
        const double alpha = alpha_lo * std::exp(std::log(alpha_hi / alpha_lo) * U(rng));
        const double p = d == Distribution::Blinn ? 2 / (alpha * alpha) - 2 : alpha;
        Case c = polygon_case("filling-" + std::to_string(i), verts, n, v, d, p);
        if (i % 2 == 1) {
            c.material.f0 = U(rng);
            c.material.has_f0 = true;
        }
        set.cases.push_back(c);
    }
    return set;
}

// Grazing views, n.v exactly each of 1e-3, 1e-4 and 1e-7 (n = +z, v in the xz plane), at
// alpha 0.1, 0.3, 0.5, 0.77 and 1 (blinn: N = 2 / alpha^2 - 2, at least 1), each with a
// square light about the mirror direction r (itself 2 n.v above the horizon) raised by
// 0.02, 0.3 and 0.8 rad (the lowest one cut by the horizon), a random azimuth within
// 0.5 rad of r's, 2 to 6 away, 0.5 to 3 wide.
inline CaseSet grazing_microfacet_polygons(std::uint64_t seed, Distribution d) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    CaseSet set;
    for (double nv : {1e-3, 1e-4, 1e-7}) {
        for (double alpha : {0.1, 0.3, 0.5, 0.77, 1.0}) {
            for (double elevation : {0.02, 0.3, 0.8}) {
                const glm::dvec3 n(0, 0, 1), v(std::sqrt(1 - nv * nv), 0, nv);
                const double az = U(rng) - 0.5, dist = 2 + 4 * U(rng), half = 0.25 + 1.25 * U(rng);
                const glm::dvec3 dir(-std::cos(elevation) * std::cos(az),
                                     std::cos(elevation) * std::sin(az), std::sin(elevation));
                const glm::dvec3 t1 = glm::normalize(glm::cross(dir, n)), t2 = glm::cross(dir, t1);
                std::vector<glm::dvec3> verts;
                for (int j = 0; j < 4; ++j) {
                    const double a = -2 * kPi_ * (j + 0.5) / 4;  // clockwise about dir
                    verts.push_back(dist * dir +
                                    half * std::sqrt(2.0) * (std::cos(a) * t1 + std::sin(a) * t2));
                }
                const double p =
                    d == Distribution::Blinn ? std::max(2 / (alpha * alpha) - 2, 1.0) : alpha;
                set.cases.push_back(polygon_case("grazing-" + std::to_string(set.cases.size()),
                                                 verts, n, v, d, p));
            }
        }
    }
    return set;
}

// Extreme microfacet polygon cases: alpha 1e-3 and 1 (N 1 and 1e5), views from
// normal to grazing (n.v 1e-6) and from below (n.v = -0.2), two-sided quads tiny,
// along r and nearly filling the hemisphere, for blinn, beckmann and ggx.
inline CaseSet extreme_microfacet_polygons() {
    CaseSet set;
    int id = 0;
    for (Distribution d : {Distribution::Blinn, Distribution::Beckmann, Distribution::Ggx}) {
        const bool blinn = d == Distribution::Blinn;
        for (double p : blinn ? std::vector<double>{1.0, 1e5} : std::vector<double>{1e-3, 1.0}) {
            for (double nv : {1.0, 0.3, 1e-3, 1e-6, -0.2}) {
                glm::dvec3 n(0, 0, 1);
                const double sv = std::sqrt(std::max(0.0, 1 - nv * nv));
                glm::dvec3 v(sv, 0, nv);
                glm::dvec3 r = glm::normalize(2 * nv * n - v + glm::dvec3(0, 0, 1e-9));
                glm::dvec3 t1 = glm::normalize(glm::cross(r, glm::dvec3(0, 1, 0)));
                glm::dvec3 t2 = glm::cross(r, t1);
                for (double rad : {1e-4, 0.5, 30.0}) {
                    std::vector<glm::dvec3> quad;
                    for (int j = 0; j < 4; ++j) {
                        const double a = -kPi_ / 2 * j;
                        quad.push_back(2.0 * r + glm::dvec3(0, 0, 0.3) +
                                       rad * (std::cos(a) * t1 + std::sin(a) * t2));
                    }
                    set.cases.push_back(
                        polygon_case("x" + std::to_string(id++), quad, n, v, d, p, true));
                }
            }
        }
    }
    return set;
}

}  // namespace arealight::test
