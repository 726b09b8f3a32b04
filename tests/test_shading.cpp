// Shader variants against the oracle, with one test body run over both backends
// (the CPU mirror and the SPIR-V on lavapipe), and the two backends against each other.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <optional>
#include <random>

#include "arealight/evaluator.hpp"
#include "arealight/reference.hpp"
#include "degenerate_cases.hpp"
#include "eval_support.hpp"
#include "test_support.hpp"

using namespace arealight;
using namespace arealight::test;

namespace {

constexpr double kPi = 3.14159265358979323846;
// The exact variant's bar is kExactP95Tol / kExactMaxTol (test_support.hpp); the fp64
// default meets it (measured on these cases: p95 3.7e-7, max 5.2e-6).
// precision=fp32: the O(1) boundary terms of a small result cancel in fp32 (measured
// on these cases: p95 3.6e-6, max 4.5e-5); its bar is the max alone.
constexpr double kExactFp32MaxTol = 1e-4;
// The two backends run the same math. In fp64 every operation is IEEE-rounded and
// the transcendentals are the templates' own, so they agree to rounding (measured:
// bit-identical; the bar is issue 4's). In fp32 the drivers' sin/cos/exp differ,
// and each backend builds the library's frame from the fp32 inputs with its own
// rounding (lavapipe contracts to FMA), a direction difference of ~1e-7 that a lobe
// of exponent N amplifies by N theta (measured worst 3.9e-5: point, specular).
constexpr double kBackendTol = 1e-5;
constexpr double kBackendFp32Tol = 1e-4;

// Random convex polygons around the mirror direction (sometimes crossing the
// horizon), exponents log-uniform in [1, 1e5], a third of them two-sided.
CaseSet random_phong_polygons(std::uint64_t seed, int count) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    CaseSet set;
    for (int i = 0; i < count; ++i) {
        glm::dvec3 n(0, 0, 1);
        double th = std::acos(1 - 0.95 * U(rng)), ph = 2 * kPi * U(rng);
        glm::dvec3 v(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
        glm::dvec3 r = 2 * v.z * n - v;
        glm::dvec3 dir =
            glm::normalize(r + 0.6 * glm::dvec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.6));
        glm::dvec3 t1 = glm::normalize(glm::cross(dir, glm::dvec3(0.3, 0.5, 0.8)));
        glm::dvec3 t2 = glm::cross(dir, t1);
        int k = 3 + static_cast<int>(U(rng) * 6);
        double dist = 1 + 4 * U(rng), rad = (0.1 + 1.2 * U(rng)) * dist * 0.5;
        std::vector<glm::dvec3> verts;
        for (int j = 0; j < k; ++j) {
            double a = -2 * kPi * (j + 0.7 * U(rng)) / k;  // clockwise about dir: front faces p
            verts.push_back(dist * dir + rad * (std::cos(a) * t1 + std::sin(a) * t2));
        }
        double N = std::exp(std::log(1e5) * U(rng));
        Case c = polygon_case("rand-" + std::to_string(i), verts, n, v, Distribution::Phong, N,
                              i % 3 == 0);
        if (i % 3 == 0 && U(rng) < 0.5)
            std::reverse(c.light.vertices.begin(), c.light.vertices.end());
        // A random rigid motion: nothing may depend on the frame.
        set.cases.push_back(transformed(
            c, random_rotation(rng), glm::dvec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5) * 10.0));
    }
    return set;
}

// Polygons near n's horizon (the centre within 0.8 of the light's angular radius of
// it), r aimed at a point of the light or of its edge (up to 0.2 rad off), N
// log-uniform in [1, 200]: low-N lobes where the specular moment is a small
// difference of O(1) boundary terms (scripts/gen_curved_cases.py --kind aimed).
CaseSet aimed_horizon_polygons(std::uint64_t seed, int count) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    CaseSet set;
    const glm::dvec3 n(0, 0, 1);
    while (static_cast<int>(set.cases.size()) < count) {
        const double size = std::pow(10.0, -1 + 1.3 * U(rng));
        const double d = size * std::pow(10.0, 0.05 + 0.95 * U(rng));
        const double elevation = (1.6 * U(rng) - 0.8) * size / d, az = 2 * kPi * U(rng);
        const glm::dvec3 dir(std::cos(elevation) * std::cos(az),
                             std::cos(elevation) * std::sin(az), std::sin(elevation));
        const glm::dvec3 t1 = glm::normalize(glm::cross(dir, glm::dvec3(U(rng) - 0.5, 0.5, 0.8)));
        const glm::dvec3 t2 = glm::cross(dir, t1);
        const int k = 3 + static_cast<int>(U(rng) * 6);
        const double wide = std::pow(10.0, -0.7 * U(rng));
        std::vector<glm::dvec3> verts;
        for (int j = 0; j < k; ++j) {
            const double a = -2 * kPi * (j + 0.7 * U(rng)) / k;  // clockwise about dir
            verts.push_back(d * dir + size * (std::cos(a) * t1 + wide * std::sin(a) * t2));
        }
        const int j = static_cast<int>(U(rng) * k) % k;
        const double t = U(rng);
        glm::dvec3 q = (1 - t) * verts[j] + t * verts[(j + 1) % k];
        if (U(rng) < 0.5) q = 0.7 * q + 0.3 * d * dir;
        const glm::dvec3 jitter(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
        glm::dvec3 r = glm::normalize(glm::normalize(q) + 0.4 * U(rng) * jitter);
        if (r.z < 0.01) r = glm::normalize(r + (0.02 - r.z) * n);
        const glm::dvec3 v = 2 * r.z * n - r;
        const double N = std::pow(10.0, 2.3 * U(rng));
        if (v.z <= 1e-3) continue;
        set.cases.push_back(polygon_case("aimed-" + std::to_string(set.cases.size()), verts, n,
                                         glm::normalize(v), Distribution::Phong, N, false));
    }
    return set;
}

}  // namespace

TEST_CASE("exact Phong on polygons matches the oracle on both backends", "[shading][vulkan]") {
    const CaseSet cases = random_phong_polygons(4242, 120);
    std::map<std::string, CaseResult> ref;
    for (const auto& c : cases.cases) ref[c.id] = reference_case(c, {});
    struct Bar {
        const char* variant;
        double p95, max;
    };
    for (const Bar& bar : {Bar{"dist=phong,method=exact,light=polygon", kExactP95Tol, kExactMaxTol},
                           Bar{"dist=phong,method=exact,light=polygon,precision=fp32",
                               kExactFp32MaxTol, kExactFp32MaxTol}}) {
        for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
            const ResultSet out = run(b, bar.variant, cases);
            REQUIRE(out.results.size() == cases.cases.size());
            std::vector<double> errors;
            double worst = 0;
            std::string worst_id;
            for (const auto& r : out.results) {
                const auto& o = ref.at(r.id);
                for (auto [x, y] : {std::pair{*r.diffuse, *o.diffuse},
                                    {*r.specular, *o.specular},
                                    {*r.moment, *o.moment}}) {
                    errors.push_back(rel_err(x, y));
                    if (errors.back() > worst) worst = errors.back(), worst_id = r.id;
                }
            }
            std::sort(errors.begin(), errors.end());
            const double p95 = errors[static_cast<std::size_t>(0.95 * (errors.size() - 1))];
            INFO(bar.variant << ", backend " << to_string(b) << ": p95 " << p95 << ", worst "
                             << worst << " at " << worst_id);
            CHECK(p95 <= bar.p95);
            CHECK(worst <= bar.max);
        }
    }
}

TEST_CASE("CPU mirror and lavapipe agree on every case", "[shading][vulkan]") {
    const CaseSet cases = random_phong_polygons(777, 200);
    for (auto [name, tol] :
         {std::pair{"dist=phong,method=exact,light=polygon", kBackendTol},
          {"dist=phong,method=exact,light=polygon,precision=fp32", kBackendFp32Tol},
          {"dist=phong,method=point,light=polygon", kBackendFp32Tol}}) {
        const ResultSet cpu = run(Backend::Cpu, name, cases);
        const ResultSet gpu = run(Backend::Vulkan, name, cases);
        REQUIRE(cpu.results.size() == gpu.results.size());
        double worst = 0;
        std::string where;
        for (std::size_t i = 0; i < cpu.results.size(); ++i) {
            const auto& a = cpu.results[i];
            const auto& g = gpu.results[i];
            auto track = [&](const char* q, double x, double y) {
                if (rel_err(x, y) <= worst) return;
                worst = rel_err(x, y);
                where =
                    a.id + " " + q + ": cpu " + std::to_string(y) + " vulkan " + std::to_string(x);
            };
            track("diffuse", *g.diffuse, *a.diffuse);
            track("specular", *g.specular, *a.specular);
            if (a.moment) track("moment", *g.moment, *a.moment);
        }
        INFO(name << ": worst CPU/GPU relative difference " << worst << " at " << where);
        CHECK(worst <= tol);
    }
}

TEST_CASE("exact Phong: two-sided symmetry, back faces, exponent extremes", "[shading][vulkan]") {
    std::vector<glm::dvec3> quad = {
        {-0.6, -0.5, 1.5}, {-0.6, 0.5, 1.5}, {-1.6, 0.5, 1.4}, {-1.6, -0.5, 1.4}};
    glm::dvec3 n(0, 0, 1), v = glm::normalize(glm::dvec3(0.7, 0.0, 0.8));
    CaseSet set;
    for (double N : {1.0, 1.5, 2.0, 37.0, 1000.0, 1e5}) {
        auto front = polygon_case("front-" + std::to_string(N), quad, n, v, Distribution::Phong, N);
        if (reference_case(front).diffuse.value() == 0.0)
            std::reverse(front.light.vertices.begin(), front.light.vertices.end());
        auto back = front;
        back.id = "back-" + std::to_string(N);
        std::reverse(back.light.vertices.begin(), back.light.vertices.end());
        auto two = back;
        two.id = "two-" + std::to_string(N);
        two.light.two_sided = true;
        set.cases.insert(set.cases.end(), {front, back, two});
    }
    for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
        const ResultSet out = run(b, "dist=phong,method=exact,light=polygon", set);
        for (std::size_t i = 0; i < out.results.size(); i += 3) {
            const auto &f = out.results[i], &bk = out.results[i + 1], &t = out.results[i + 2];
            const auto ref = reference_case(set.cases[i]);
            INFO(to_string(b) << " " << f.id << ": specular " << *f.specular << " oracle "
                              << *ref.specular << ", back " << *bk.specular << ", two-sided back "
                              << *t.specular);
            CHECK(*bk.diffuse == 0.0);
            CHECK(*bk.specular == 0.0);
            CHECK(rel_err(*t.specular, *f.specular) <= kBackendTol);
            CHECK(rel_err(*t.moment, *f.moment) <= kBackendTol);
            CHECK(rel_err(*f.specular, *ref.specular) <= kExactMaxTol);
            CHECK(rel_err(*f.moment, *ref.moment) <= kExactMaxTol);
        }
    }
}

namespace {

// Half of the variants (`half` 0 or 1): lavapipe JIT-compiles on the calling thread
// (seconds per variant with a cold shader cache), so the sweep is split in two test
// cases that ctest runs in parallel. Neighbours in the enumeration differ in
// precision only, and fp64 compiles slower: i + i/2 alternates them between halves.
void check_variants_run(std::size_t half) {
    // The same polygons for every distribution (alpha from the exponent for
    // beckmann and ggx, in the contract's range).
    CaseSet cases = random_phong_polygons(5, 16);
    const std::size_t phong = cases.cases.size();
    for (Distribution d : {Distribution::Blinn, Distribution::Beckmann, Distribution::Ggx}) {
        for (std::size_t i = 0; i < phong; ++i) {
            Case c = cases.cases[i];
            c.id += std::string("-") + to_string(d);
            c.material.distribution = d;
            c.material.alpha = std::clamp(1.0 / std::sqrt(c.material.exponent), 1e-3, 1.0);
            cases.cases.push_back(c);
        }
    }
    const CaseSet curved = curved_cases_like(cases, 17);
    cases.cases.insert(cases.cases.end(), curved.cases.begin(), curved.cases.end());
    const CaseSet& degenerate = degenerate_cases();
    cases.cases.insert(cases.cases.end(), degenerate.cases.begin(), degenerate.cases.end());
    const auto all = enumerate_variants();
    for (std::size_t i = 0; i < all.size(); ++i) {
        if ((i + i / 2) % 2 != half) continue;
        const Variant& v = all[i];
        std::string why;
        auto out = evaluator(Backend::Vulkan).run(v, cases, [&](const Diagnostic& d) {
            why += d.message;
        });
        INFO(canonical_name(v) << ": " << why);
        REQUIRE(out);
        CHECK(!out->results.empty());
        check_finite_non_negative(*out, canonical_name(v));
    }
}

}  // namespace

TEST_CASE("every listed variant compiles, validates and runs on lavapipe (1/2)",
          "[shading][vulkan]") {
    check_variants_run(0);
}

TEST_CASE("every listed variant compiles, validates and runs on lavapipe (2/2)",
          "[shading][vulkan]") {
    check_variants_run(1);
}

namespace {


// Every peak-function variant with its bars on these 120 cases: relL2 of moment and
// specular against the oracle, each about 1.5x the worst of the two backends
// measured (in brackets). The paper's fits and the lobe product are kept as
// baselines, so theirs are looser.
struct PeakBar {
    const char* variant;
    double moment, specular;
};
const PeakBar kPeakBars[] = {
    {"dist=phong,method=lorentz,light=polygon", 1.1e-2, 1.2e-2},              // [7.4e-3, 8.1e-3]
    {"dist=phong,method=pearson,light=polygon", 5.5e-3, 6e-3},                // [3.5e-3, 4.0e-3]
    {"dist=phong,method=ellipsoid,light=polygon", 5.5e-3, 6.5e-3},            // [3.7e-3, 4.2e-3]
    {"dist=phong,method=lorentz,light=polygon,fit=paper", 7e-3, 8e-3},        // [4.7e-3, 5.3e-3]
    {"dist=phong,method=pearson,light=polygon,fit=paper", 9.5e-3, 9e-3},      // [6.4e-3, 6.1e-3]
    {"dist=phong,method=ellipsoid,light=polygon,fit=paper", 6.5e-3, 7.5e-3},  // [4.2e-3, 5.0e-3]
    {"dist=phong,method=lorentz,light=polygon,specular=sg", 1.1e-2, 4e-2},    // [.., 2.7e-2]
    {"dist=phong,method=pearson,light=polygon,specular=sg", 5.5e-3, 4e-2},    // [.., 2.6e-2]
    {"dist=phong,method=ellipsoid,light=polygon,specular=sg", 5.5e-3, 4e-2},  // [.., 2.6e-2]
    {"dist=phong,method=ellipsoid,light=polygon,fit=paper,specular=sg", 6.5e-3, 4e-2},
};
// The fits' clamps and the near/far choice are branch points, so fp32 rounding
// differences between the backends can grow past one ulp; measured worst 1.8e-5 on
// these cases, 9.3e-5 (specular of N = 1.4) over 600 other random cases; with the
// frame built in fp32 on each backend (kBackendFp32Tol), 3.5e-4 (lorentz, fit=paper).
constexpr double kPeakBackendTol = 5e-4;


// Lights whose lobe peak the horizon cuts (issue 25 item 3): N log-uniform in [1, 1e5], r
// grazing, 1e-7 rad to 2 lobe widths (2 / sqrt(N + 2), at most 0.3 rad) above n's horizon
// (log-uniform); the light's centre within 2 lobe widths
// (2 / sqrt(N + 2)) of r in azimuth and within 0.3 to 3 widths of the horizon in
// elevation, so the horizon crosses it near the peak; convex 3- to 8-gons (points of an
// ellipse, axis ratio 0.2 to 1), 1.2 to 8 away, 0.05 to 2 times that wide.
// (scripts/gen_curved_cases.py --kind horizon-peak writes such a set to a file.)
CaseSet horizon_peak_polygons(std::uint64_t seed, int count) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    CaseSet set;
    const glm::dvec3 n(0, 0, 1);
    const double elevation_scale[] = {0.3, 1.0, 3.0}, size_scale[] = {0.05, 0.2, 1.0, 2.0};
    const int sides[] = {3, 4, 5, 6, 8};
    for (int i = 0; i < count; ++i) {
        const double N = std::exp(std::log(1e5) * U(rng));
        const double width = 2 / std::sqrt(N + 2);
        const double top = std::log10(std::min(0.3, 2 * width));
        const double er = std::pow(10.0, -7 + (top + 7) * U(rng));
        const glm::dvec3 r(std::cos(er), 0, std::sin(er));
        const glm::dvec3 v = 2 * r.z * n - r;
        const double az = (4 * U(rng) - 2) * width;
        const double el =
            (2 * U(rng) - 1) * width * elevation_scale[static_cast<int>(3 * U(rng)) % 3];
        const glm::dvec3 dir(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az),
                             std::sin(el));
        const double dist = 1.2 + 6.8 * U(rng);
        const double half =
            0.5 * (0.05 + 0.95 * U(rng)) * dist * size_scale[static_cast<int>(4 * U(rng)) % 4];
        const glm::dvec3 t1 = glm::normalize(glm::cross(dir, glm::dvec3(U(rng) - 0.5, 0.5, 0.8)));
        const glm::dvec3 t2 = glm::cross(dir, t1);
        const int k = sides[static_cast<int>(5 * U(rng)) % 5];
        const double aspect = 0.2 + 0.8 * U(rng);
        std::vector<glm::dvec3> verts;
        for (int j = 0; j < k; ++j) {
            const double a = -2 * kPi * (j + 0.7 * U(rng)) / k;  // clockwise about dir
            verts.push_back(dist * dir + half * (std::cos(a) * t1 + aspect * std::sin(a) * t2));
        }
        set.cases.push_back(polygon_case("horizon-peak-" + std::to_string(i), verts, n,
                                         glm::normalize(v), Distribution::Phong, N, false));
    }
    return set;
}

// Each variant against the oracle over cases, on both backends: specular and moment relL2
// within its bar.
void check_relL2_bars(const CaseSet& cases,
                      std::initializer_list<std::pair<const char*, double>> bars) {
    std::map<std::string, CaseResult> ref;
    for (const auto& c : cases.cases) ref[c.id] = reference_case(c, {});
    for (const auto& [name, bar] : bars) {
        for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
            const ResultSet out = run(b, name, cases);
            REQUIRE(out.results.size() == cases.cases.size());
            const double moment = rel_l2(out, ref, &CaseResult::moment);
            const double specular = rel_l2(out, ref, &CaseResult::specular);
            INFO(name << " on " << to_string(b) << ": relL2 specular " << specular << ", moment "
                      << moment);
            CHECK(specular <= bar);
            CHECK(moment <= bar);
        }
    }
}

// The three Phong peak methods on polygons: lorentz within lorentz_tol, pearson and
// ellipsoid within tol.
void check_phong_peaks(const CaseSet& cases, double lorentz_tol, double tol) {
    check_relL2_bars(cases, {{"dist=phong,method=lorentz,light=polygon", lorentz_tol},
                             {"dist=phong,method=pearson,light=polygon", tol},
                             {"dist=phong,method=ellipsoid,light=polygon", tol}});
}
}  // namespace

TEST_CASE("peak-function methods: bounded error on random polygons, backends agree",
          "[shading][vulkan]") {
    const CaseSet cases = random_phong_polygons(4242, 120);
    std::map<std::string, CaseResult> ref;
    for (const auto& c : cases.cases) ref[c.id] = reference_case(c, {});
    for (const PeakBar& bar : kPeakBars) {
        const char* name = bar.variant;
        std::map<Backend, ResultSet> out;
        for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
            out[b] = run(b, name, cases);
            REQUIRE(out[b].results.size() == cases.cases.size());
            const double moment = rel_l2(out[b], ref, &CaseResult::moment);
            const double specular = rel_l2(out[b], ref, &CaseResult::specular);
            INFO(name << " on " << to_string(b) << ": relL2 moment " << moment << ", specular "
                      << specular);
            CHECK(moment <= bar.moment);
            CHECK(specular <= bar.specular);
            for (const auto& r : out[b].results) {
                INFO(r.id);
                CHECK(*r.moment >= 0.0);
                CHECK(*r.specular >= 0.0);
            }
        }
        double worst = 0;
        for (std::size_t i = 0; i < cases.cases.size(); ++i) {
            const auto &c = out[Backend::Cpu].results[i], &g = out[Backend::Vulkan].results[i];
            worst =
                std::max({worst, rel_err(*g.specular, *c.specular), rel_err(*g.moment, *c.moment)});
        }
        INFO(name << ": worst CPU/GPU relative difference " << worst);
        CHECK(worst <= kPeakBackendTol);
    }
}

// The tuned peak methods near the horizon at low N (method/peak_lobe_edge.glsl: the Gauss
// rule below N = 32 and for every arc's z integral). Bars on the relL2 of specular
// and moment: about 1.5x the worst of the two backends and quantities on these
// cases (lorentz specular 3.4e-3, moment 5.6e-3; pearson 1.3e-3, 2.3e-3; ellipsoid
// 1.3e-3, 2.2e-3). The fits alone measured specular 2.4e-2 (lorentz) and 1.4e-2
// (ellipsoid) on 1500 such cases (scripts/gen_curved_cases.py --kind aimed).
constexpr double kPeakAimedLorentzTol = 8.5e-3;
constexpr double kPeakAimedTol = 3.5e-3;

TEST_CASE("peak-function methods: low-N lobes on lights near the horizon", "[shading][vulkan]") {
    const CaseSet cases = aimed_horizon_polygons(977, 150);
    check_phong_peaks(cases, kPeakAimedLorentzTol, kPeakAimedTol);
}

// Issue 25 item 3's goal for the best non-exact Phong methods on lights cut by the horizon
// through the lobe's peak: specular and moment relL2 <= 1e-2 (measured on these cases,
// specular / moment: pearson 2.6e-3 / 5.7e-3, ellipsoid 2.7e-3 / 5.7e-3). lorentz, the
// cheapest, 7.8e-3 / 1.3e-2, is held to 1.5x its moment. A first draw of this set with r
// up to 0.3 rad above the horizon whatever N had one case with r at a vertex of an
// octagon, N = 3.2e4, 4.8% off in all three: that is the fits' corner error, not the
// horizon's, and is left to the accuracy issue.
constexpr double kHorizonPeakTol = 1e-2;
constexpr double kHorizonPeakLorentzTol = 2e-2;

TEST_CASE("peak-function methods: lights cut by the horizon through the lobe's peak",
          "[shading][vulkan]") {
    const CaseSet cases = horizon_peak_polygons(2512, 300);
    check_phong_peaks(cases, kHorizonPeakLorentzTol, kHorizonPeakTol);
}

// A glossy lobe beside a light's edge under a view exactly along n (r = n): N log-uniform in
// [32, 1e4], rectangles in the plane z = h turned about n, one edge's plane 0.5 to 3 lobe
// widths (N^-1/2) from r, the light on the far side of it (r outside) or on r's side (r
// inside); and spheres whose rim is as far from r, outside. With r outside the light the
// result is the nearest arcs' terms alone, where the azimuth's width s and the lobe's are
// alike (method/peak_lobe_edge.glsl: the rule there). Seeded; v = n to the bit, as the
// public degenerate set's grid cases.
CaseSet lobe_beside_edge_lights(std::uint64_t seed, int count) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    CaseSet set;
    const glm::dvec3 n(0, 0, 1);
    for (int i = 0; i < count; ++i) {
        const double N = 32 * std::exp(std::log(1e4 / 32) * U(rng));
        const double delta = (0.5 + 2.5 * U(rng)) / std::sqrt(N);
        const double h = 1 + 3 * U(rng), turn = 2 * kPi * U(rng);
        const glm::dvec3 ex(std::cos(turn), std::sin(turn), 0), ey(-ex.y, ex.x, 0);
        if (i % 3 != 2) {
            const double x0 = h * std::tan(delta);
            const double len = h * (0.05 + 0.6 * U(rng)), half_y = h * (0.05 + 0.6 * U(rng));
            const double x1 = i % 3 == 0 ? x0 + len : x0 - len;  // r outside, inside
            const double y0 = -half_y * U(rng) * 2 + half_y;
            std::vector<glm::dvec3> quad = {
                glm::dvec3(0, 0, h) + x0 * ex + (y0 - half_y) * ey,
                glm::dvec3(0, 0, h) + x1 * ex + (y0 - half_y) * ey,
                glm::dvec3(0, 0, h) + x1 * ex + (y0 + half_y) * ey,
                glm::dvec3(0, 0, h) + x0 * ex + (y0 + half_y) * ey,
            };
            set.cases.push_back(polygon_case("beside-" + std::to_string(i), quad, n, n,
                                             Distribution::Phong, N, true));
        } else {
            const double beta = 0.02 + 0.3 * U(rng);  // the sphere's angular radius
            const double theta = beta + delta, dist = h / std::cos(theta);
            Case c = polygon_case("beside-" + std::to_string(i), {}, n, n, Distribution::Phong, N);
            c.light = Light{};
            c.light.type = LightType::Sphere;
            c.light.center = a3(dist * (std::sin(theta) * ex + std::cos(theta) * n));
            c.light.radius = dist * std::sin(beta);
            set.cases.push_back(c);
        }
    }
    return set;
}

// The tuned peak methods on those lights, specular relL2 (moment alike, both backends alike):
// polygons pearson / ellipsoid 4.2e-4 / 4.1e-4, lorentz 1.2e-3, where the fits on every arc at
// N >= 32 (before the rule took the arcs between core and tail) measured 9.6e-3 / 9.8e-3 /
// 2.1e-2; spheres 9.4e-3 / 9.4e-3 / 8.3e-3 (before: 1.7e-2 / 1.7e-2 / 2.6e-2), most of it the
// 16-gon proxy's own error (1.1e-2 against the sphere's oracle on 200 spheres drawn the same
// way, scripts/proxy_polygon_cases.py; pearson on the proxy 2.8e-3 of the proxy's oracle).
constexpr double kBesideEdgeTol = 1e-3;
constexpr double kBesideEdgeLorentzTol = 3e-3;
constexpr double kBesideEdgeSphereTol = 1.4e-2;

TEST_CASE("peak-function methods: a glossy lobe beside a light's edge, v exactly n",
          "[shading][vulkan]") {
    const CaseSet all = lobe_beside_edge_lights(8128, 150);
    CaseSet polygons, spheres;
    for (const Case& c : all.cases)
        (c.light.type == LightType::Polygon ? polygons : spheres).cases.push_back(c);
    check_phong_peaks(polygons, kBesideEdgeLorentzTol, kBesideEdgeTol);
    check_relL2_bars(spheres, {{"dist=phong,method=lorentz,light=sphere", kBesideEdgeSphereTol},
                               {"dist=phong,method=pearson,light=sphere", kBesideEdgeSphereTol},
                               {"dist=phong,method=ellipsoid,light=sphere", kBesideEdgeSphereTol}});
}

TEST_CASE("peak-function and arvo methods: finite and non-negative at the extremes",
          "[shading][vulkan]") {
    // Exponents 1, 1.5, 2, 1e5; lights straight along r (c -> 1 on every edge),
    // grazing r's horizon (c -> 0), tiny and nearly hemisphere-filling.
    glm::dvec3 n(0, 0, 1), v = glm::normalize(glm::dvec3(0.4, 0.0, 0.9));
    glm::dvec3 r = 2 * v.z * n - v;
    glm::dvec3 t1 = glm::normalize(glm::cross(r, glm::dvec3(0, 1, 0))), t2 = glm::cross(r, t1);
    CaseSet set;
    int id = 0;
    for (double N : {1.0, 1.5, 2.0, 1e5}) {
        for (double rad : {1e-4, 0.3, 30.0}) {
            for (double offset : {0.0, 0.5 * rad, 1.5 * rad}) {
                std::vector<glm::dvec3> quad;
                for (int j = 0; j < 4; ++j) {
                    const double a = -kPi / 2 * j;
                    quad.push_back(2.0 * r + offset * t1 +
                                   rad * (std::cos(a) * t1 + std::sin(a) * t2));
                }
                set.cases.push_back(polygon_case("x" + std::to_string(id++), quad, n, v,
                                                 Distribution::Phong, N, true));
            }
        }
    }
    std::vector<std::string> names = {"dist=phong,method=arvo,light=polygon"};
    for (const PeakBar& bar : kPeakBars) names.push_back(bar.variant);
    names.push_back("dist=phong,method=lorentz,light=polygon,fit=paper,specular=sg");
    names.push_back("dist=phong,method=pearson,light=polygon,fit=paper,specular=sg");
    // Disks, spheres and ellipsoids of the same places and sizes, for every listed
    // curved-light variant of these methods.
    const CaseSet curved = curved_cases_like(set, 19);
    set.cases.insert(set.cases.end(), curved.cases.begin(), curved.cases.end());
    for (const auto& v : enumerate_variants())
        if (v.dist == Distribution::Phong && is_peak_method(v.method) &&
            v.light != LightType::Polygon)
            names.push_back(canonical_name(v));
    for (const std::string& name : names) {
        for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
            for (const auto& res : run(b, name, set).results) {
                INFO(name << " " << to_string(b) << " " << res.id << ": moment " << *res.moment
                          << ", specular " << *res.specular);
                CHECK(std::isfinite(*res.moment));
                CHECK(std::isfinite(*res.specular));
                CHECK(*res.moment >= 0.0);
                CHECK(*res.specular >= 0.0);
            }
        }
    }
}

TEST_CASE("arvo: exact for integer exponents up to fp32 rounding, both backends",
          "[shading][vulkan]") {
    // Arvo's recurrence is exact for integer N; what is left is fp32 rounding summed
    // over N terms and the edges. Exponents rounded (and capped at 3000 to bound the
    // O(N) loop) on the random polygons.
    CaseSet cases = random_phong_polygons(777, 60);
    for (auto& c : cases.cases)
        c.material.exponent = std::min(std::round(c.material.exponent), 3000.0);
    std::map<std::string, CaseResult> ref;
    for (const auto& c : cases.cases) ref[c.id] = reference_case(c, {});
    // Measured on these cases: relL2 moment / specular 4.3e-6 / 4.5e-6 (worse backend).
    constexpr double kArvoRelL2Tol = 2e-5;
    for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
        const ResultSet out = run(b, "dist=phong,method=arvo,light=polygon", cases);
        REQUIRE(out.results.size() == cases.cases.size());
        const double moment = rel_l2(out, ref, &CaseResult::moment);
        const double specular = rel_l2(out, ref, &CaseResult::specular);
        INFO(to_string(b) << ": relL2 moment " << moment << ", specular " << specular);
        CHECK(moment <= kArvoRelL2Tol);
        CHECK(specular <= kArvoRelL2Tol);
    }
}
