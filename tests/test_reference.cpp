// The oracle against closed forms derived here, Monte Carlo, and symmetries.
// Nothing here reuses the oracle's integrands: each formula is written from
// CONTRACT.md section 2 in glm.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

#include "arealight/reference.hpp"
#include "test_support.hpp"

using namespace arealight;
using namespace arealight::test;

namespace {

constexpr double kPi = 3.14159265358979323846;
// The oracle is asked for 1e-10; closed forms are exact to rounding.
constexpr double kClosedFormTol = 1e-9;

using Poly = std::vector<glm::dvec3>;

// Unit directions of a polygon seen from the origin, counter-clockwise seen
// from outside the unit sphere (so that u_i x u_{i+1} points into the polygon).
Poly directions_ccw(const Poly& verts) {
    Poly u;
    glm::dvec3 c(0.0);
    for (auto& x : verts) {
        u.push_back(glm::normalize(x));
        c += u.back();
    }
    if (glm::dot(glm::cross(u[0], u[1]), c) < 0) std::reverse(u.begin(), u.end());
    return u;
}

// Clips a spherical polygon to the hemisphere m.w >= 0 (Sutherland-Hodgman).
Poly clip(const Poly& in, glm::dvec3 m) {
    Poly out;
    for (size_t i = 0; i < in.size(); ++i) {
        auto P = in[i], Q = in[(i + 1) % in.size()];
        double dp = glm::dot(m, P), dq = glm::dot(m, Q);
        if (dp >= 0) out.push_back(P);
        if ((dp >= 0) != (dq >= 0)) out.push_back(glm::normalize((dp * Q - dq * P) / (dp - dq)));
    }
    return out;
}

// Lambert's edge formula: E / pi = (1 / 2 pi) sum angle_i (n_i . n).
double polygon_irradiance(const Poly& u, glm::dvec3 n) {
    double s = 0;
    for (size_t i = 0; i < u.size(); ++i) {
        auto a = u[i], b = u[(i + 1) % u.size()];
        auto c = glm::cross(a, b);
        double len = glm::length(c);
        if (len == 0) continue;
        s += std::atan2(len, glm::dot(a, b)) * glm::dot(c / len, n);
    }
    return s / (2 * kPi);
}

// Arvo's axial moment of integer order N (seed 000 eq. 2-3, with the sign of
// the edge sum as verified there): (N+1) M = z_N Omega + sum (n_i . r) F_i, each
// F_i a sum of integrals of cos^j over the edge, by the recurrence
// I_j = [cos^(j-1) sin] / j + (j-1)/j I_(j-2), in long double.
long double arvo_moment(const Poly& u, glm::dvec3 r, int N) {
    using LD = long double;
    LD sum = 0;
    for (size_t i = 0; i < u.size(); ++i) {
        glm::dvec3 a = u[i], b = u[(i + 1) % u.size()];
        glm::dvec3 ni = glm::normalize(glm::cross(a, b));
        glm::dvec3 ti = glm::cross(ni, a);
        LD phi_len = std::atan2((LD)glm::length(glm::cross(a, b)), (LD)glm::dot(a, b));
        LD ai = glm::dot(a, r), bi = glm::dot(ti, r);
        LD c = std::sqrt(ai * ai + bi * bi), delta = std::atan2(bi, ai);
        LD lo = -delta, hi = phi_len - delta;
        // I_j over [lo, hi] for j = 0..N-1, and F = sum over j of N-1's parity.
        std::vector<LD> I(std::max(N, 2));
        I[0] = hi - lo;
        I[1] = std::sin(hi) - std::sin(lo);
        for (int j = 2; j < N; ++j) {
            I[j] = (std::pow(std::cos(hi), (LD)(j - 1)) * std::sin(hi) -
                    std::pow(std::cos(lo), (LD)(j - 1)) * std::sin(lo)) /
                       j +
                   (LD)(j - 1) / j * I[j - 2];
        }
        LD F = 0;
        for (int j = (N - 1) % 2; j <= N - 1; j += 2) F += std::pow(c, (LD)j) * I[j];
        sum += (LD)glm::dot(ni, r) * F;
    }
    LD omega = 0;  // solid angle by the spherical excess of the fan triangles
    for (size_t i = 1; i + 1 < u.size(); ++i) {
        auto A = u[0], B = u[i], C = u[i + 1];
        LD num = glm::dot(A, glm::cross(B, C));
        LD den = 1 + glm::dot(A, B) + glm::dot(B, C) + glm::dot(C, A);
        omega += 2 * std::atan2(std::abs(num), den);
    }
    LD z = (N % 2 == 0) ? 1 : 0;
    return (z * omega + sum) / (N + 1);
}

Poly random_convex_polygon(std::mt19937_64& rng, int k, glm::dvec3 center, double radius) {
    std::uniform_real_distribution<double> U(0, 1);
    glm::dvec3 w = glm::normalize(center), t1 = glm::normalize(glm::cross(w, {0.3, 0.7, 0.2}));
    glm::dvec3 t2 = glm::cross(w, t1);
    std::vector<double> ang;
    for (int i = 0; i < k; ++i) ang.push_back(2 * kPi * (i + 0.8 * U(rng)) / k);
    Poly p;
    for (double a : ang) p.push_back(center + radius * (std::cos(a) * t1 + std::sin(a) * t2));
    // Counter-clockwise about w puts the front (CONTRACT 1) away from the
    // origin: reverse so that the origin sees the emitting side.
    std::reverse(p.begin(), p.end());
    return p;
}

}  // namespace

TEST_CASE("polygon irradiance matches Lambert's edge formula, clipped or not", "[reference]") {
    std::mt19937_64 rng(1234);
    std::uniform_real_distribution<double> U(-1, 1);
    for (int trial = 0; trial < 40; ++trial) {
        glm::dvec3 dir = glm::normalize(glm::dvec3(U(rng), U(rng), U(rng)));
        auto verts = random_convex_polygon(rng, 3 + trial % 6, 2.0 * dir, 0.3 + 0.8 * (U(rng) + 1));
        glm::dvec3 n = glm::normalize(glm::dvec3(U(rng), U(rng), U(rng)));
        if (glm::dot(n, dir) < -0.2) n = -n;
        Case c = polygon_case("t", verts, n, n, Distribution::Phong, 10.0, true);
        double expected = polygon_irradiance(clip(directions_ccw(verts), n), n);
        auto r = reference_case(c);
        INFO("trial " << trial << " oracle " << *r.diffuse << " edge formula " << expected);
        CHECK(rel_err(*r.diffuse, expected, 1e-6) < kClosedFormTol);
        CHECK(*r.error_diffuse >= 0.0);
    }
}

TEST_CASE("sphere irradiance is (R/d)^2 cos(theta) above the horizon", "[reference]") {
    for (double d : {1.5, 4.0, 100.0, 3e4}) {
        for (double theta : {0.0, 0.4, 1.0}) {
            const double R = 0.7 * std::min(1.0, d * std::cos(theta + 0.05) * 0.9);
            if (std::asin(R / d) + theta >= kPi / 2) continue;
            Case c;
            c.id = "s";
            c.n = {0, 0, 1};
            c.v = {0, 0, 1};
            c.light.type = LightType::Sphere;
            c.light.center = {d * std::sin(theta), 0, d * std::cos(theta)};
            c.light.radius = R;
            c.material.distribution = Distribution::Ggx;
            c.material.alpha = 0.3;
            auto r = reference_case(c);
            double expected = (R / d) * (R / d) * std::cos(theta);
            INFO("d " << d << " theta " << theta << " rel err "
                      << std::abs(*r.diffuse / expected - 1) << expected);
            CHECK(std::abs(*r.diffuse - expected) <= kClosedFormTol * expected);
        }
    }
}

TEST_CASE("integer Phong moments match Arvo's recurrence", "[reference]") {
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> U(-1, 1);
    int checked = 0;
    for (int trial = 0; checked < 30 && trial < 500; ++trial) {
        glm::dvec3 n(0, 0, 1);
        glm::dvec3 v = glm::normalize(glm::dvec3(U(rng), U(rng), 1.2 + U(rng)));
        glm::dvec3 r = 2 * glm::dot(n, v) * n - v;
        glm::dvec3 dir = glm::normalize(r + 0.5 * glm::dvec3(U(rng), U(rng), U(rng)));
        auto verts = random_convex_polygon(rng, 3 + trial % 6, 3.0 * dir, 0.4 + 0.5 * (U(rng) + 1));
        Poly u = directions_ccw(verts);
        // Arvo's formula has no clipping: keep polygons inside both hemispheres.
        bool inside = true;
        for (auto& x : u) inside = inside && glm::dot(x, n) > 0.01 && glm::dot(x, r) > 0.01;
        if (!inside) continue;
        const int N = 1 + checked % 12;
        Case c = polygon_case("a", verts, n, v, Distribution::Phong, N);
        auto res = reference_case(c);
        double expected = (double)((N + 1) / (2 * kPi) * arvo_moment(u, r, N));
        INFO("N " << N << " oracle " << *res.moment << " Arvo " << expected);
        CHECK(rel_err(*res.moment, expected, 1e-6) < kClosedFormTol);
        ++checked;
    }
    CHECK(checked == 30);
}

namespace {

// CONTRACT.md section 2 written out directly, for the Monte Carlo estimator.
struct Brdf {
    Material m;
    glm::dvec3 n, v;
    double D(glm::dvec3 h) const {
        double c = glm::dot(n, h);
        if (c <= 0) return 0;
        double t2 = (1 - c * c) / (c * c);
        switch (m.distribution) {
            case Distribution::Blinn:
                return (m.exponent + 2) / (2 * kPi) * std::pow(c, m.exponent);
            case Distribution::Beckmann:
                return std::exp(-t2 / (m.alpha * m.alpha)) /
                       (kPi * m.alpha * m.alpha * c * c * c * c);
            case Distribution::Ggx: {
                double a2 = m.alpha * m.alpha, d = c * c * (a2 - 1) + 1;
                return a2 / (kPi * d * d);
            }
            default:
                return 0;
        }
    }
    double lambda(glm::dvec3 w) const {
        double c = glm::dot(n, w);
        double t = std::sqrt(std::max(0.0, 1 - c * c)) / c;
        if (t == 0) return 0;
        if (m.distribution == Distribution::Ggx) {
            return (std::sqrt(1 + m.alpha * m.alpha * t * t) - 1) / 2;
        }
        double alpha =
            m.distribution == Distribution::Blinn ? std::sqrt(2 / (m.exponent + 2)) : m.alpha;
        double a = 1 / (alpha * t);
        return (std::erf(a) - 1) / 2 + std::exp(-a * a) / (2 * a * std::sqrt(kPi));
    }
    // Integrands of specular and of ndf/moment at direction w.
    double specular(glm::dvec3 w) const {
        double nw = glm::dot(n, w), nv = glm::dot(n, v);
        if (nw <= 0) return 0;
        if (m.distribution == Distribution::Phong) {
            glm::dvec3 r = 2 * nv * n - v;
            return (m.exponent + 2) / (2 * kPi) *
                   std::pow(std::max(0.0, glm::dot(r, w)), m.exponent) * nw;
        }
        if (nv <= 0) return 0;
        glm::dvec3 h = glm::normalize(w + v);
        return D(h) / (1 + lambda(w) + lambda(v)) / (4 * nv) * fresnel(h);
    }
    // Schlick's F, written plainly (the oracle forms 1 - h.v without cancellation).
    double fresnel(glm::dvec3 h) const {
        if (!m.has_f0) return 1;
        return m.f0 + (1 - m.f0) * std::pow(1 - glm::dot(h, v), 5);
    }
    double second(glm::dvec3 w) const {
        double nw = glm::dot(n, w);
        if (nw <= 0) return 0;
        if (m.distribution == Distribution::Phong) {
            glm::dvec3 r = 2 * glm::dot(n, v) * n - v;
            return (m.exponent + 1) / (2 * kPi) *
                   std::pow(std::max(0.0, glm::dot(r, w)), m.exponent);
        }
        glm::dvec3 h = glm::normalize(w + v);
        return D(h) / (4 * glm::dot(h, v));
    }
};

struct Estimate {
    double mean[3] = {0, 0, 0}, se[3] = {0, 0, 0};
};

// Light-area sampling: each sample gives a direction and its solid-angle pdf.
template <class Sampler>
Estimate monte_carlo(const Brdf& b, Sampler sample, int count, std::mt19937_64& rng) {
    double s[3] = {0, 0, 0}, s2[3] = {0, 0, 0};
    for (int i = 0; i < count; ++i) {
        glm::dvec3 w;
        double pdf;
        if (!sample(rng, w, pdf)) continue;
        double f[3] = {std::max(0.0, glm::dot(b.n, w)) / kPi / pdf, b.specular(w) / pdf,
                       b.second(w) / pdf};
        for (int k = 0; k < 3; ++k) s[k] += f[k], s2[k] += f[k] * f[k];
    }
    Estimate e;
    for (int k = 0; k < 3; ++k) {
        e.mean[k] = s[k] / count;
        e.se[k] = std::sqrt(std::max(0.0, s2[k] / count - e.mean[k] * e.mean[k]) / count);
    }
    return e;
}

void check_against_monte_carlo(const Case& c, const Estimate& e) {
    auto r = reference_case(c);
    double oracle[3] = {*r.diffuse, *r.specular, r.moment ? *r.moment : *r.ndf};
    const char* names[3] = {"diffuse", "specular", "ndf/moment"};
    for (int k = 0; k < 3; ++k) {
        double z = std::abs(oracle[k] - e.mean[k]) / (e.se[k] + 1e-12);
        INFO(c.id << " " << names[k] << ": oracle " << oracle[k] << " MC " << e.mean[k] << " +- "
                  << e.se[k] << " z " << z);
        CHECK(z <= 4.0);  // a 4-sigma bound fails by chance with p < 1e-4
    }
}

}  // namespace

TEST_CASE("oracle agrees with seeded Monte Carlo for polygons, disks and spheres",
          "[reference][montecarlo]") {
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> U(0, 1);
    const int kSamples = 200000;
    const Material mats[] = {{Distribution::Phong, 12.0, 0},
                             {Distribution::Blinn, 30.0, 0},
                             {Distribution::Beckmann, 0, 0.35},
                             {Distribution::Ggx, 0, 0.25}};
    glm::dvec3 n = glm::normalize(glm::dvec3(0.1, -0.2, 1.0));
    glm::dvec3 v = glm::normalize(glm::dvec3(0.6, 0.1, 0.8));
    int idx = 0;
    for (const auto& m : mats) {
        Brdf b{m, n, v};
        // A quad crossing the horizon, near the mirror direction.
        {
            Poly verts = {
                {-0.9, -0.5, 0.9}, {-0.9, 0.6, 1.1}, {-2.2, 0.6, -0.3}, {-2.2, -0.5, -0.5}};
            // Flip the winding so the front faces the origin.
            glm::dvec3 N = glm::cross(verts[1] - verts[0], verts[2] - verts[0]);
            if (glm::dot(N, -verts[0]) < 0) std::reverse(verts.begin(), verts.end());
            Case c = polygon_case(
                "mc-quad-" + std::to_string(idx), verts, n, v, m.distribution,
                m.distribution == Distribution::Phong || m.distribution == Distribution::Blinn
                    ? m.exponent
                    : m.alpha);
            auto sample = [&](std::mt19937_64& g, glm::dvec3& w, double& pdf) {
                // Uniform on the two fan triangles by area.
                auto tri = [&](int k) {
                    return std::array<glm::dvec3, 3>{verts[0], verts[k], verts[k + 1]};
                };
                double a1 = glm::length(glm::cross(verts[1] - verts[0], verts[2] - verts[0])) / 2;
                double a2 = glm::length(glm::cross(verts[2] - verts[0], verts[3] - verts[0])) / 2;
                auto t = tri(U(g) * (a1 + a2) < a1 ? 1 : 2);
                double s1 = std::sqrt(U(g)), s2 = U(g);
                glm::dvec3 x = (1 - s1) * t[0] + s1 * (1 - s2) * t[1] + s1 * s2 * t[2];
                glm::dvec3 nl =
                    glm::normalize(glm::cross(verts[1] - verts[0], verts[2] - verts[0]));
                double d2 = glm::dot(x, x);
                w = x / std::sqrt(d2);
                double cosl = std::abs(glm::dot(nl, w));
                pdf = d2 / ((a1 + a2) * cosl);
                return cosl > 0;
            };
            check_against_monte_carlo(c, monte_carlo(b, sample, kSamples, rng));
        }
        // A sphere partly below the horizon.
        {
            Case c;
            c.id = "mc-sphere-" + std::to_string(idx);
            c.n = a3(n);
            c.v = a3(v);
            c.material = m;
            c.light.type = LightType::Sphere;
            glm::dvec3 C(-1.0, 0.3, 0.35);
            c.light.center = a3(C);
            c.light.radius = 0.6;
            double d = glm::length(C), cosmax = std::sqrt(1 - 0.36 / (d * d));
            glm::dvec3 w0 = C / d, t1 = glm::normalize(glm::cross(w0, {0, 0, 1})),
                       t2 = glm::cross(w0, t1);
            auto sample = [&](std::mt19937_64& g, glm::dvec3& w, double& pdf) {
                double ct = 1 - U(g) * (1 - cosmax), st = std::sqrt(1 - ct * ct),
                       ph = 2 * kPi * U(g);
                w = ct * w0 + st * (std::cos(ph) * t1 + std::sin(ph) * t2);
                pdf = 1 / (2 * kPi * (1 - cosmax));
                return true;
            };
            check_against_monte_carlo(c, monte_carlo(b, sample, kSamples, rng));
        }
        // An ellipse (disk light) facing the point.
        {
            Case c;
            c.id = "mc-disk-" + std::to_string(idx);
            c.n = a3(n);
            c.v = a3(v);
            c.material = m;
            c.light.type = LightType::Disk;
            glm::dvec3 C(-1.2, 0.1, 1.0), u(0.0, 0.7, 0.0), vv(0.3, 0.0, 0.36);
            if (glm::dot(glm::cross(u, vv), -C) < 0) vv = -vv;
            c.light.center = a3(C);
            c.light.u = a3(u);
            c.light.v = a3(vv);
            glm::dvec3 nl = glm::normalize(glm::cross(u, vv));
            double area = kPi * glm::length(u) * glm::length(vv);
            auto sample = [&](std::mt19937_64& g, glm::dvec3& w, double& pdf) {
                double rad = std::sqrt(U(g)), ph = 2 * kPi * U(g);
                glm::dvec3 x = C + rad * (std::cos(ph) * u + std::sin(ph) * vv);
                double d2 = glm::dot(x, x);
                w = x / std::sqrt(d2);
                pdf = d2 / (area * std::abs(glm::dot(nl, w)));
                return true;
            };
            check_against_monte_carlo(c, monte_carlo(b, sample, kSamples, rng));
        }
        ++idx;
    }
}

TEST_CASE("oracle is invariant under a random rigid motion of the whole case", "[reference]") {
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> U(-1, 1);
    const double kTol = 1e-8;  // two independent 1e-10 integrations
    Case base;
    base.n = {0.2, -0.1, 1.0};
    base.v = {0.5, 0.3, 0.7};
    std::vector<Case> cases;
    {
        Case c =
            polygon_case("poly", {{-1, 0.3, 1.2}, {-0.2, 0.3, 1.4}, {-0.2, 1.1, 1.1}, {-1, 1, 0.9}},
                         {0.2, -0.1, 1.0}, {0.5, 0.3, 0.7}, Distribution::Ggx, 0.2, true);
        cases.push_back(c);
        c.material = {Distribution::Phong, 150.0, 0};
        cases.push_back(c);
    }
    {
        Case c = base;
        c.light.type = LightType::Disk;
        c.light.center = {-0.8, -0.2, 0.9};
        c.light.u = {0.4, 0, 0.1};
        c.light.v = {0, 0.3, 0};
        c.light.two_sided = true;
        c.material = {Distribution::Beckmann, 0, 0.1};
        c.id = "disk";
        cases.push_back(c);
        c.light.type = LightType::Ellipsoid;
        c.light.axes = {Vec3{0.4, 0, 0.1}, Vec3{0, 0.3, 0}, Vec3{-0.05, 0, 0.2}};
        c.material = {Distribution::Blinn, 80.0, 0};
        c.id = "ellipsoid";
        cases.push_back(c);
        c.light.type = LightType::Sphere;
        c.light.radius = 0.35;
        c.material = {Distribution::Phong, 3.5, 0};
        c.id = "sphere";
        cases.push_back(c);
    }
    for (const auto& c : cases) {
        auto r0 = reference_case(c);
        for (int t = 0; t < 3; ++t) {
            auto R = random_rotation(rng);
            glm::dvec3 shift(5 * U(rng), 5 * U(rng), 5 * U(rng));
            auto r1 = reference_case(transformed(c, R, shift));
            INFO(c.id << " motion " << t << ": diffuse " << *r0.diffuse << " vs " << *r1.diffuse
                      << ", specular " << *r0.specular << " vs " << *r1.specular);
            CHECK(rel_err(*r1.diffuse, *r0.diffuse, 1e-6) < kTol);
            CHECK(rel_err(*r1.specular, *r0.specular, 1e-6) < kTol);
            double q0 = r0.moment ? *r0.moment : *r0.ndf, q1 = r1.moment ? *r1.moment : *r1.ndf;
            CHECK(rel_err(q1, q0, 1e-6) < kTol);
        }
    }
}

TEST_CASE("sides, planes and volumes: zero where the contract says so", "[reference]") {
    Poly quad = {{-0.5, -0.5, 1}, {0.5, -0.5, 1}, {0.5, 0.5, 1}, {-0.5, 0.5, 1}};
    // Front faces -z (towards the origin) when wound clockwise seen from +z.
    Poly front(quad.rbegin(), quad.rend());
    glm::dvec3 n(0, 0, 1), v(0.2, 0, 1);
    auto lit = reference_case(polygon_case("front", front, n, v, Distribution::Ggx, 0.3));
    auto back = reference_case(polygon_case("back", quad, n, v, Distribution::Ggx, 0.3));
    auto two = reference_case(polygon_case("two", quad, n, v, Distribution::Ggx, 0.3, true));
    INFO("front " << *lit.diffuse << " back " << *back.diffuse << " two-sided " << *two.diffuse);
    CHECK(*lit.diffuse > 0.05);
    CHECK(*back.diffuse == 0.0);
    CHECK(*back.specular == 0.0);
    CHECK(std::abs(*two.diffuse - *lit.diffuse) <= 1e-12);
    CHECK(std::abs(*two.specular - *lit.specular) <= 1e-12);

    Poly on_plane = {{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}};
    auto flat = reference_case(polygon_case("plane", on_plane, n, v, Distribution::Phong, 5, true));
    CHECK(*flat.diffuse == 0.0);
    CHECK(*flat.moment == 0.0);

    Case inside;
    inside.id = "inside";
    inside.n = {0, 0, 1};
    inside.v = {0, 0, 1};
    inside.light.type = LightType::Sphere;
    inside.light.center = {0.1, 0, 0};
    inside.light.radius = 0.5;
    inside.material = {Distribution::Beckmann, 0, 0.2};
    auto in = reference_case(inside);
    CHECK(*in.diffuse == 0.0);
    CHECK(*in.ndf == 0.0);
}

TEST_CASE("an ellipsoid with equal axes is a sphere", "[reference]") {
    for (auto d : {Distribution::Phong, Distribution::Ggx}) {
        Case s;
        s.id = "s";
        s.n = {0.1, 0.2, 1};
        s.v = {-0.4, 0.1, 0.9};
        s.light.type = LightType::Sphere;
        s.light.center = {0.5, -0.3, 1.2};
        s.light.radius = 0.45;
        s.material = {d, 40.0, 0.15};
        Case e = s;
        e.light.type = LightType::Ellipsoid;
        e.light.axes = {Vec3{0.45, 0, 0}, Vec3{0, 0, 0.45}, Vec3{0, -0.45, 0}};
        auto rs = reference_case(s), re = reference_case(e);
        INFO("sphere " << *rs.specular << " ellipsoid " << *re.specular);
        CHECK(rel_err(*re.diffuse, *rs.diffuse, 1e-6) < 1e-9);
        CHECK(rel_err(*re.specular, *rs.specular, 1e-6) < 1e-9);
    }
}

namespace {

// Whether the ray from the origin along w hits the convex polygon P, whose front (CONTRACT 1)
// faces the origin.
bool hits_polygon(const Poly& P, glm::dvec3 w) {
    const glm::dvec3 N = glm::cross(P[1] - P[0], P[2] - P[0]);
    const double nw = glm::dot(N, w);
    if (!(nw < 0)) return false;  // parallel to the plane, or leaving through the back
    const glm::dvec3 x = glm::dot(N, P[0]) / nw * w;
    for (size_t i = 0; i < P.size(); ++i) {
        const glm::dvec3& a = P[i];
        const glm::dvec3& b = P[(i + 1) % P.size()];
        if (glm::dot(glm::cross(b - a, x - a), N) < 0) return false;
    }
    return true;
}

// A half vector h drawn with density D(h) (n.h) over the hemisphere about n, by inverting
// the distribution's radial CDF (each D of CONTRACT 2 is normalized so that this integrates
// to 1): GGX tan^2 = a^2 u / (1 - u), Beckmann tan^2 = -a^2 log(1 - u), Blinn cos = u^(1/(N+2)).
glm::dvec3 sample_half_vector(const Brdf& b, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> U(0, 1);
    const double u = U(rng), phi = 2 * kPi * U(rng);
    double cos_t = 1;
    switch (b.m.distribution) {
        case Distribution::Ggx: {
            const double t2 = b.m.alpha * b.m.alpha * u / (1 - u);
            cos_t = 1 / std::sqrt(1 + t2);
            break;
        }
        case Distribution::Beckmann: {
            const double t2 = -b.m.alpha * b.m.alpha * std::log1p(-u);
            cos_t = 1 / std::sqrt(1 + t2);
            break;
        }
        case Distribution::Blinn:
            cos_t = std::pow(u, 1 / (b.m.exponent + 2));
            break;
        default:
            break;
    }
    const double sin_t = std::sqrt(std::max(0.0, 1 - cos_t * cos_t));
    glm::dvec3 t1 = glm::normalize(
        glm::cross(b.n, std::abs(b.n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    glm::dvec3 t2 = glm::cross(b.n, t1);
    return cos_t * b.n + sin_t * (std::cos(phi) * t1 + std::sin(phi) * t2);
}

// `specular` of a polygon light by sampling the BRDF: w is v mirrored about h, so its
// density is D(h) (n.h) / (4 h.v); a sample below the horizon of n or off the light
// contributes 0.
struct McValue {
    double mean = 0, se = 0;
};
McValue specular_by_brdf_sampling(const Brdf& b, const Poly& light, int count,
                                  std::mt19937_64& rng) {
    double s = 0, s2 = 0;
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 h = sample_half_vector(b, rng);
        const double hv = glm::dot(h, b.v);
        if (!(hv > 0)) continue;
        const glm::dvec3 w = 2 * hv * h - b.v;
        if (!(glm::dot(b.n, w) > 0) || !hits_polygon(light, w)) continue;
        const double pdf = b.D(h) * glm::dot(b.n, h) / (4 * hv);
        if (!(pdf > 0)) continue;
        const double f = b.specular(w) / pdf;
        s += f, s2 += f * f;
    }
    McValue e;
    e.mean = s / count;
    e.se = std::sqrt(std::max(0.0, s2 / count - e.mean * e.mean) / count);
    return e;
}

// n.v = 0.35: at such a view (1 - h.v)^5 is large enough near the mirror direction that
// F differs from 1 by a factor of several for small f0.
struct FresnelScene {
    glm::dvec3 n, v;
    std::vector<std::pair<std::string, Poly>> lights;
    std::vector<Material> materials;
};

FresnelScene fresnel_scene() {
    FresnelScene s;
    s.n = glm::normalize(glm::dvec3(0.1, -0.05, 1.0));
    const glm::dvec3 t = glm::normalize(glm::cross(s.n, glm::dvec3(0, 1, 0)));
    s.v = 0.35 * s.n + std::sqrt(1 - 0.35 * 0.35) * t;
    const glm::dvec3 r = 2 * glm::dot(s.n, s.v) * s.n - s.v;
    std::mt19937_64 rng(31);
    // A quad about the mirror direction; a pentagon straddling the horizon of n beside it;
    // a large hexagon (about 100 degrees across) over the mirror direction and the normal.
    s.lights.push_back({"mirror-quad", random_convex_polygon(rng, 4, 2.0 * r, 0.7)});
    const glm::dvec3 low =
        glm::normalize(r - glm::dot(r, s.n) * s.n + 0.05 * s.n + 0.3 * glm::cross(s.n, r));
    s.lights.push_back({"horizon-pentagon", random_convex_polygon(rng, 5, 2.0 * low, 0.9)});
    int below = 0;
    for (const auto& x : s.lights.back().second) below += glm::dot(s.n, x) < 0;
    REQUIRE(below > 0);
    REQUIRE(below < 5);
    s.lights.push_back(
        {"large-hexagon", random_convex_polygon(rng, 6, glm::normalize(r + s.n), 1.2)});
    s.materials = {{Distribution::Ggx, 0, 0.3},
                   {Distribution::Beckmann, 0, 0.2},
                   {Distribution::Blinn, 40.0, 0}};
    return s;
}

}  // namespace

TEST_CASE("oracle's Fresnel specular agrees with seeded BRDF-sampled Monte Carlo",
          "[reference][montecarlo][fresnel]") {
    // The weights f (n.w) / pdf = G2 F (h.v) / ((n.v)(n.h)) vary little over the lobe, so
    // the standard error is a reliable scale; 4 sigma fails by chance with p < 1e-4.
    const double kMcSigmas = 4.0;
    const int kSamples = 400000;
    const double f0s[] = {0.04, 0.5, 0.0};
    const FresnelScene scene = fresnel_scene();
    std::mt19937_64 rng(4242);
    int k = 0;
    for (const auto& [name, light] : scene.lights) {
        for (Material m : scene.materials) {
            m.f0 = f0s[k++ % 3];
            m.has_f0 = true;
            Case c = polygon_case(name, light, scene.n, scene.v, m.distribution, 0);
            c.material = m;
            const Brdf b{m, scene.n, scene.v};
            const McValue mc = specular_by_brdf_sampling(b, light, kSamples, rng);
            const auto r = reference_case(c);
            const double z = std::abs(*r.specular - mc.mean) / mc.se;
            INFO(name << " " << to_string(m.distribution) << " f0 " << m.f0 << ": oracle "
                      << *r.specular << " MC " << mc.mean << " +- " << mc.se << " z " << z);
            CHECK(mc.se < 0.01 * mc.mean);  // the comparison has teeth
            CHECK(z <= kMcSigmas);
        }
    }
}

TEST_CASE("oracle's specular is exactly unchanged at f0 = 1 and linear, increasing in f0",
          "[reference][fresnel]") {
    const double kLinearTol = 1e-9;  // independent integrations, each to 1e-10
    const FresnelScene scene = fresnel_scene();
    for (const auto& [name, light] : scene.lights) {
        for (const Material& m : scene.materials) {
            Case c = polygon_case(name, light, scene.n, scene.v, m.distribution, 0);
            c.material = m;
            auto specular_at = [&](double f0) {
                Case cf = c;
                cf.material.f0 = f0;
                cf.material.has_f0 = true;
                return *reference_case(cf).specular;
            };
            const auto none = reference_case(c);
            const double S1 = specular_at(1.0), S0 = specular_at(0.0);
            INFO(name << " " << to_string(m.distribution) << ": no f0 " << *none.specular
                      << ", f0 = 1 " << S1 << ", f0 = 0 " << S0);
            uint64_t b_none, b_one;
            std::memcpy(&b_none, &*none.specular, sizeof b_none);
            std::memcpy(&b_one, &S1, sizeof b_one);
            CHECK(b_none == b_one);
            CHECK(S0 > 0.0);
            CHECK(S0 < S1);
            double previous = S0;
            for (double f0 : {0.04, 0.5, 0.9}) {
                const double S = specular_at(f0), linear = f0 * S1 + (1 - f0) * S0;
                CAPTURE(f0, S, linear, previous);
                CHECK(S >= previous);
                CHECK(std::abs(S - linear) <= kLinearTol * S);
                previous = S;
            }
        }
    }
}
