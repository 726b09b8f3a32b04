// Lights at the ends of every range, for the no-bad-value and nothing-seen checks of
// the shading tests: every light type and distribution, lights tiny (1e-6 of their
// distance) to huge (1e3), along r and straddling the horizon; p 1e-7 from a disk's or
// a quad's plane (its foot inside and outside the light) and 1e-6 outside a sphere;
// N 1 and 1e5, alpha 1e-3 and 1; views along n, grazing (n.v 1e-6) and from below
// (n.v = -0.2). `dark` holds the cases that must give exactly 0: p on a light's plane,
// behind a one-sided light (a quad facing away, a disk and a quad behind p), inside a
// sphere or an ellipsoid. A variant runs on the cases of its own light type.
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "arealight/case.hpp"
#include "microfacet_cases.hpp"
#include "test_support.hpp"

namespace arealight::test {

inline void extreme_lights(CaseSet& set, CaseSet& dark) {
    const glm::dvec3 n(0, 0, 1);
    for (Distribution d : {Distribution::Phong, Distribution::Blinn, Distribution::Beckmann,
                           Distribution::Ggx}) {
        const bool exponent = d == Distribution::Phong || d == Distribution::Blinn;
        for (double param : exponent ? std::vector<double>{1.0, 1e5} : std::vector<double>{1e-3, 1.0}) {
            for (double nv : {1.0, 0.3, 1e-6, -0.2}) {
                const double sv = std::sqrt(std::max(0.0, 1 - nv * nv));
                const glm::dvec3 v(sv, 0, nv);
                const glm::dvec3 r = glm::normalize(2 * nv * n - v + glm::dvec3(0, 0, 1e-9));
                for (const glm::dvec3& dir :
                     {glm::normalize(r + glm::dvec3(0, 0, 0.3)),
                      glm::normalize(glm::dvec3(r.x, r.y, 0.0) + glm::dvec3(0, 0, 1e-3))}) {
                    const glm::dvec3 t1 = glm::normalize(glm::cross(
                        dir, std::abs(dir.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
                    const glm::dvec3 t2 = glm::cross(dir, t1);
                    auto add = [&](CaseSet& to, LightType type, const glm::dvec3& center) -> Case& {
                        Case c;
                        c.id = "x" + std::to_string(set.cases.size() + dark.cases.size());
                        c.n = a3(n);
                        c.v = a3(v);
                        set_param(c, d, param);
                        c.light.type = type;
                        c.light.center = a3(center);
                        to.cases.push_back(c);
                        return to.cases.back();
                    };
                    auto quad = [&](Case& c, const glm::dvec3& centre, double size, bool facing) {
                        for (int k = 0; k < 4; ++k) {
                            const double a = (facing ? -1.0 : 1.0) * kPi_ / 2 * k;
                            c.light.vertices.push_back(
                                a3(centre + size * (std::cos(a) * t1 + std::sin(a) * t2)));
                        }
                    };
                    for (double size : {1e-6, 0.5, 1e3}) {
                        quad(add(set, LightType::Polygon, 2.0 * dir), 2.0 * dir, 2.0 * size, true);
                        Case& disk = add(set, LightType::Disk, 2.0 * dir);
                        disk.light.u = a3(2.0 * size * t1);
                        disk.light.v = a3(-2.0 * size * t2);
                        if (size > 1.0) continue;
                        add(set, LightType::Sphere, 2.0 * dir).light.radius = 2.0 * size;
                        add(set, LightType::Ellipsoid, 2.0 * dir).light.axes = {
                            a3(2.0 * size * t1), a3(0.5 * size * t2), a3(1.5 * size * dir)};
                    }
                    for (double off : {0.0, 3.0}) {
                        for (double h : {1e-7, 0.0, -1.0}) {
                            const glm::dvec3 c0 = h * dir + off * t1;
                            Case& disk = add(h > 0.0 ? set : dark, LightType::Disk, c0);
                            disk.light.u = a3(2.0 * t1);
                            disk.light.v = a3(-2.0 * t2);
                            quad(add(h > 0.0 ? set : dark, LightType::Polygon, c0), c0, 2.0, true);
                        }
                    }
                    // A one-sided quad facing away.
                    quad(add(dark, LightType::Polygon, 2.0 * dir), 2.0 * dir, 0.5, false);
                    add(set, LightType::Sphere, dir).light.radius = 1.0 - 1e-6;
                    add(dark, LightType::Sphere, dir).light.radius = 1.5;
                    add(dark, LightType::Ellipsoid, dir).light.axes = {
                        a3(glm::dvec3(1.5, 0, 0)), a3(glm::dvec3(0, 1.2, 0)),
                        a3(glm::dvec3(0, 0, 2.0))};
                }
            }
        }
    }
}

}  // namespace arealight::test
