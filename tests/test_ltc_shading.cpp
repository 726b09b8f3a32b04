// Linearly transformed cosines (templates/method/ltc.glsl) with arealight's fitted
// tables: every distribution's default and every key against the oracle on seeded
// random polygons (specular bounded, diffuse exact), both backends and their
// agreement, the folded Fresnel channel against the same variant without Fresnel,
// and finite non-negative values at the parameter and view extremes for every
// listed LTC variant.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>
#include <string>

#include "arealight/case_io.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/reference.hpp"
#include "eval_support.hpp"
#include "microfacet_cases.hpp"
#include "test_support.hpp"

namespace arealight::test {
namespace {

const Distribution kAll[] = {Distribution::Phong, Distribution::Blinn, Distribution::Beckmann,
                             Distribution::Ggx};

std::string ltc_name(Distribution d, const std::string& keys) {
    std::string s = std::string("dist=") + to_string(d) + ",method=ltc,light=polygon";
    return keys.empty() ? s : s + "," + keys;
}

// The random microfacet polygons of microfacet_cases.hpp; phong takes blinn's
// exponents (N in [1, 1e5]) and ignores f0.
CaseSet ltc_cases(Distribution d, std::uint64_t seed, int count) {
    const Distribution from = d == Distribution::Phong ? Distribution::Blinn : d;
    CaseSet set = random_microfacet_polygons(seed, count, from, "ltc-");
    for (auto& c : set.cases) c.material.distribution = d;
    return set;
}

// Specular relL2 bars on these 60 cases per distribution, about 1.5x the measured value
// (in brackets; both backends agree to 1e-6 there).
struct LtcBar {
    Distribution d;
    const char* keys;
    double specular;
};
const LtcBar kBars[] = {
    {Distribution::Ggx, "", 0.037},                                        // [0.0242]
    {Distribution::Ggx, "edge=poly", 0.037},                               // [0.0247]
    {Distribution::Ggx, "horizon=proxy", 0.039},                           // [0.0255]
    {Distribution::Ggx, "precision=fp16", 0.037},                          // [0.0241]
    {Distribution::Ggx, "precision=fp16,edge=poly,horizon=proxy", 0.039},  // [0.0257]
    // table=fit: the closed form in place of the tables, held to the tables' bars.
    {Distribution::Ggx, "table=fit", 0.037},
    {Distribution::Ggx, "table=fit,horizon=proxy", 0.039},
    {Distribution::Beckmann, "", 0.053},                                   // [0.0352]
    {Distribution::Blinn, "", 0.052},                                      // [0.0347]
    {Distribution::Phong, "", 0.056},                                      // [0.0375]
};
// diffuse is the exact Lambert term in fp32 (score metric, floor 1e-3).
constexpr double kDiffuseTol = 2e-5;
// The mirror against lavapipe: the same table through one bilinear rule (bit-identical,
// tests/test_vulkan_runner.cpp), fp32 arithmetic in a different order. fp16: al_half
// rounds each operation as lavapipe does, but the compilers order and fold the half
// expressions differently, each step worth 1e-3 (measured worst 4.4e-3).
constexpr double kBackendTol = 1e-3;
constexpr double kBackendTolFp16 = 1e-2;

}  // namespace

TEST_CASE("ltc: bounded specular error on random polygons, exact diffuse, backends agree",
          "[shading][vulkan][ltc]") {
    for (Distribution d : kAll) {
        const CaseSet cases = ltc_cases(d, 5100 + static_cast<int>(d), 60);
        std::map<std::string, CaseResult> ref;
        for (const auto& c : cases.cases) ref[c.id] = reference_case(c, {});
        for (const LtcBar& bar : kBars) {
            if (bar.d != d) continue;
            const std::string name = ltc_name(d, bar.keys);
            std::map<Backend, ResultSet> out;
            for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
                out[b] = run(b, name, cases);
                REQUIRE(out[b].results.size() == cases.cases.size());
                const double spec = rel_l2(out[b], ref, &CaseResult::specular);
                INFO(name << " on " << to_string(b) << ": specular relL2 " << spec);
                CHECK(spec <= bar.specular);
                double worst_diffuse = 0;
                for (const auto& r : out[b].results) {
                    INFO(r.id);
                    CHECK(*r.specular >= 0.0);
                    worst_diffuse =
                        std::max(worst_diffuse, rel_err(*r.diffuse, *ref.at(r.id).diffuse));
                }
                INFO("worst diffuse error " << worst_diffuse);
                CHECK(worst_diffuse <= kDiffuseTol);
            }
            double worst = 0;
            std::string worst_at;
            for (std::size_t i = 0; i < cases.cases.size(); ++i) {
                const auto &c = out[Backend::Cpu].results[i], &g = out[Backend::Vulkan].results[i];
                const double e = std::max(rel_err(*g.specular, *c.specular),
                                          rel_err(*g.diffuse, *c.diffuse));
                if (e > worst) worst = e, worst_at = c.id;
            }
            INFO(name << ": worst CPU/GPU relative difference " << worst << " at " << worst_at);
            CHECK(worst <= (variant(name).precision == Precision::Fp16 ? kBackendTolFp16
                                                                        : kBackendTol));
        }
    }
}

// The public validation sets' GGX polygon cases (tests/data/ltc_ggx_polygon_public.cases.json,
// written by scripts/extract_cases.py from typical, horizon and glossy of shared/validation,
// ids kept), per set: specular relL2 of table=texture and table=fit against the oracle.
// Bars about 1.3x the measured value (in brackets, both backends alike); table=fit against
// table=texture on each set within kFitOverTexture.
struct PublicBar {
    const char* set;  // the ids' prefix
    double texture;
    double fit;
};
const PublicBar kPublicBars[] = {
    {"pub-typical-", 0.032, 0.033},   // [0.0242, 0.0249]
    {"pub-horizon-", 0.012, 0.012},   // [0.00897, 0.00858]
    {"pub-glossy-", 0.013, 0.0086},   // [0.00999, 0.00656]
};
// table=fit's relL2 over table=texture's on one set (measured: typical 1.03, horizon 0.96,
// glossy 0.66; the degree (7, 9) fit measured 0.96, 1.08, 0.63).
constexpr double kFitOverTexture = 1.1;

TEST_CASE("ltc table=fit: public GGX polygon cases, per set, both backends", "[shading][vulkan][ltc]") {
    std::string why;
    const auto all = read_cases(AREALIGHT_TEST_DATA "/ltc_ggx_polygon_public.cases.json",
                                [&](const Diagnostic& d) { why += d.message + "\n"; });
    INFO(why);
    REQUIRE(all);
    for (const PublicBar& bar : kPublicBars) {
        CaseSet set;
        for (const auto& c : all->cases)
            if (c.id.rfind(bar.set, 0) == 0) set.cases.push_back(c);
        REQUIRE(!set.cases.empty());
        const auto ref = oracle(set);
        const std::string texture = "dist=ggx,method=ltc,light=polygon";
        const std::string fit = texture + ",table=fit";
        auto t_out = check_both_backends(texture, set, ref, kClosedFormDiffuse.with_specular(bar.texture));
        auto f_out = check_both_backends(fit, set, ref, kClosedFormDiffuse.with_specular(bar.fit));
        for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
            const double t = rel_l2(t_out[b], ref, &CaseResult::specular);
            const double f = rel_l2(f_out[b], ref, &CaseResult::specular);
            INFO(bar.set << " on " << to_string(b) << ": specular relL2 texture " << t
                         << ", fit " << f << " (ratio " << f / t << ")");
            CHECK(f <= kFitOverTexture * t);
        }
    }
}

TEST_CASE("ltc: Fresnel in the magnitude: its error against the plain output's",
          "[shading][ltc]") {
    // The same 80 cases without f0 (F = 1) and with f0 on every case: a seeded f0 in
    // [0, 1] (an earlier issue's criterion, relL2 within 1.2x of the plain relL2, GGX's bar;
    // the two-lobe tables' below), and 0.04 (a
    // dielectric). Fresnel also reweights the cases (F is small at normal views, near 1 at
    // grazing ones, where the LTC's own error is larger), so the test also checks the
    // channel against a second yardstick: the plain output scaled by the oracle's exact
    // per-case ratio ref_F / ref_1 (a perfect Fresnel channel on the same fit).
    // GGX's channel (the split sum with its lobe-position correction) is held to ratios:
    // measured, random f0: relL2 / plain 1.01, to the yardstick 0.93; at f0 0.04, to the
    // yardstick 1.16. The two-lobe tables of blinn and beckmann (method/ltc.glsl) keep the
    // plain split sum (GGX's correction doubles their error), which is now most of their
    // error: their plain error fell with each change to the lobe (two lobes, the albedo
    // ceiling, the clip to n's horizon: blinn 0.0266 -> 0.0097, beckmann 0.0405 -> 0.0086)
    // while the Fresnel channel's stayed (random f0 blinn 0.0306 -> 0.0261, beckmann
    // 0.0476 -> 0.0291; f0 0.04 0.0825 -> 0.0870, 0.0820 -> 0.0756), so a ratio to the
    // plain error only recorded the plain error's progress. Their bars are absolute relL2,
    // the measured values with ~10% to spare: the channel itself is what is weak
    // (docs/ltc.md).
    struct FresnelBar {
        Distribution d;
        bool absolute;                 // bars on relL2 itself, not on ratios
        double random_f0, dielectric;  // bars on the ratio to the yardstick (or relL2)
        double plain;                  // bar on relL2 with random f0 over relL2 without
    };
    const FresnelBar bars[] = {{Distribution::Blinn, true, 0.029, 0.096, 0},
                               {Distribution::Beckmann, true, 0.032, 0.083, 0},
                               {Distribution::Ggx, false, 1.2, 1.5, 1.2}};
    for (const FresnelBar& bar : bars) {
        const Distribution d = bar.d;
        const CaseSet plain_set = [&] {
            CaseSet s = ltc_cases(d, 5200 + static_cast<int>(d), 80);
            for (auto& c : s.cases) {
                c.material.f0 = 1.0;
                c.material.has_f0 = false;
            }
            return s;
        }();
        std::map<std::string, CaseResult> ref_plain;
        for (const auto& c : plain_set.cases) ref_plain[c.id] = reference_case(c, {});
        const std::string name = ltc_name(d, "");
        const ResultSet out_plain = run(Backend::Cpu, name, plain_set);
        for (int k = 0; k < 2; ++k) {
            std::mt19937_64 rng(77 + static_cast<int>(d));
            std::uniform_real_distribution<double> U(0, 1);
            CaseSet set = plain_set;
            for (auto& c : set.cases) {
                c.material.f0 = k == 0 ? 0.04 : U(rng);
                c.material.has_f0 = true;
            }
            std::map<std::string, CaseResult> ref;
            for (const auto& c : set.cases) ref[c.id] = reference_case(c, {});
            const ResultSet out = run(Backend::Cpu, name, set);
            ResultSet scaled = out_plain;
            for (auto& r : scaled.results) {
                const double one = *ref_plain.at(r.id).specular, f = *ref.at(r.id).specular;
                r.specular = one > 0 ? *r.specular * (f / one) : 0.0;
            }
            const double e = rel_l2(out, ref, &CaseResult::specular);
            const double e_scaled = rel_l2(scaled, ref, &CaseResult::specular);
            const double e_plain = rel_l2(out_plain, ref_plain, &CaseResult::specular);
            INFO(name << (k == 0 ? ", f0 0.04" : ", random f0") << ": specular relL2 " << e
                      << ", plain output scaled by the exact F ratio " << e_scaled
                      << ", plain (F = 1) " << e_plain);
            const double limit = k == 0 ? bar.dielectric : bar.random_f0;
            if (bar.absolute) {
                CHECK(e <= limit);
            } else {
                CHECK(e <= limit * e_scaled);
                if (k == 1) CHECK(e <= bar.plain * e_plain);
            }
        }
    }
}

TEST_CASE("ltc: a light filling the hemisphere is exact, with and without Fresnel",
          "[shading][ltc]") {
    // The magnitudes are divided by the LTC's own hemisphere integral (ltc_table.hpp), and
    // GGX's Fresnel correction vanishes for such a light: a 2000 x 2000 quad at height 1
    // (within 0.03 degrees of the horizon) for f0 = 1 and f0 = 0. What is left is the
    // table's interpolation between cells (measured worst 0.9%, beckmann at n.v = 0.9).
    constexpr double kHemisphereTol = 0.015;
    const std::vector<glm::dvec3> quad = {{-1000, 1000, 1}, {1000, 1000, 1}, {1000, -1000, 1},
                                          {-1000, -1000, 1}};
    for (Distribution d : {Distribution::Blinn, Distribution::Beckmann, Distribution::Ggx}) {
        CaseSet set;
        for (double rough : {0.05, 0.2, 0.5}) {
            for (double nv : {0.9, 0.5, 0.2, 0.08}) {
                for (double f0 : {1.0, 0.0}) {
                    const double param = d == Distribution::Blinn ? 2 / (rough * rough) - 2 : rough;
                    Case c = polygon_case("h-" + std::to_string(set.cases.size()), quad,
                                          {0, 0, 1}, {std::sqrt(1 - nv * nv), 0, nv}, d, param);
                    c.material.f0 = f0;
                    c.material.has_f0 = true;
                    set.cases.push_back(c);
                }
            }
        }
        const ResultSet out = run(Backend::Cpu, ltc_name(d, ""), set);
        REQUIRE(out.results.size() == set.cases.size());
        for (std::size_t i = 0; i < set.cases.size(); ++i) {
            const double ref = *reference_case(set.cases[i], {}).specular;
            INFO(ltc_name(d, "") << " " << out.results[i].id << ": specular "
                                 << *out.results[i].specular << ", reference " << ref);
            CHECK(rel_err(*out.results[i].specular, ref) <= kHemisphereTol);
        }
    }
}

TEST_CASE("ltc: no light gives more than a light filling the hemisphere", "[shading][ltc]") {
    // Monotonicity: a light inside the hemisphere holds part of the lobe, so its specular is
    // at most that of the 2000 x 2000 quad at height 1 (the hemisphere, to 0.03 degrees).
    // The two-lobe kernel is negative in its far tail and the LTC's own clip counts lobe
    // mass below n's horizon, so before the albedo ceiling (al_ltc_specular) quads about
    // the mirror direction exceeded it (public glossy beckmann poly8 065: 1.0166 against
    // 1.0000), and glossy microfacet lobes (albedo ~1) went above 1. kCeiling: the ceiling's allowance for the table's albedo (AL_LTC_ALBEDO_TOL,
    // templates/method/ltc.glsl) and what the hemisphere quad misses near the horizon. Glossy
    // lobes, views n.v 0.9 to 0.2, square lights about r of half-angle 10 to 80 degrees (the
    // larger ones crossing the horizon), every distribution.
    constexpr double kCeiling = 0.011;
    const std::vector<glm::dvec3> hemisphere = {{-1000, 1000, 1}, {1000, 1000, 1},
                                                {1000, -1000, 1}, {-1000, -1000, 1}};
    for (Distribution d : {Distribution::Phong, Distribution::Blinn, Distribution::Beckmann,
                           Distribution::Ggx}) {
        CaseSet set;
        for (double rough : {0.01, 0.03, 0.1}) {
            for (double nv : {0.9, 0.5, 0.2}) {
                const double param =
                    d == Distribution::Phong || d == Distribution::Blinn ? 2 / (rough * rough) - 2 : rough;
                const glm::dvec3 n(0, 0, 1), v(std::sqrt(1 - nv * nv), 0, nv);
                const glm::dvec3 r(-v.x, 0, nv);
                const glm::dvec3 t1(0, 1, 0), t2 = glm::cross(r, t1);
                set.cases.push_back(polygon_case("hemi-" + std::to_string(set.cases.size()),
                                                 hemisphere, n, v, d, param));
                for (double deg : {10.0, 30.0, 50.0, 65.0, 80.0}) {
                    const double h = std::tan(deg * M_PI / 180);
                    // Counter-clockwise seen from p: (t2, t1) right-handed about -r... walk
                    // so that (v1 - v0) x (v2 - v0) points back towards p.
                    std::vector<glm::dvec3> quad = {r + h * (t1 + t2), r + h * (t2 - t1),
                                                    r - h * (t1 + t2), r + h * (t1 - t2)};
                    if (glm::dot(glm::cross(quad[1] - quad[0], quad[2] - quad[0]), r) > 0)
                        std::swap(quad[1], quad[3]);
                    set.cases.push_back(polygon_case("quad-" + std::to_string(set.cases.size()),
                                                     quad, n, v, d, param));
                }
            }
        }
        const ResultSet out = run(Backend::Cpu, ltc_name(d, ""), set);
        REQUIRE(out.results.size() == set.cases.size());
        double whole = 0;
        for (const CaseResult& res : out.results) {
            if (res.id.rfind("hemi-", 0) == 0) {
                whole = *res.specular;
                continue;
            }
            INFO(ltc_name(d, "") << " " << res.id << ": specular " << *res.specular
                                 << ", the hemisphere's " << whole);
            CHECK(*res.specular > 0);  // the quads face p and hold r
            CHECK(*res.specular <= whole * (1 + kCeiling));
            // F = 1: phong, beckmann and ggx reflect at most all (blinn's D with Beckmann's
            // Lambda does not: 1.044 at n.v = 0.08, the test above).
            if (d != Distribution::Blinn) CHECK(*res.specular <= 1 + 1e-6);
        }
    }
}

TEST_CASE("ltc: a light is shaded by its part above n's horizon", "[shading][vulkan][ltc]") {
    // (f (n.w))+ is 0 below n's horizon, so a light crossing it must give what its part above
    // gives, and a light below it nothing; the LTC's own clip (z >= 0 in its space) is the
    // plane (-d, 0, a).w = 0, not n's horizon, and before al_ltc_horizon_arc
    // (templates/method/ltc.glsl) counted the lobe between the two: every distribution failed
    // both checks here (docs/ltc.md, "True horizon"). Seeded quads 2 away, about the lobe's
    // azimuth, their centre within 20 degrees of the horizon, views n.v 0.1 to 0.9; the part
    // above is the quad clipped to z >= 0 in double (a 3- to 5-gon in the same plane).
    // kSameRegion (relative, floor 1e-2): the shader forms the crossing from fp32 directions
    // (al_crossing), the test's vertex is the double one; measured worst 1.5e-5 relative
    // above 1e-2, 1.1e-7 absolute below (blinn at 1.1e-4, its two lobes cancelling).
    constexpr double kSameRegion = 1e-4;
    std::mt19937_64 rng(9100);
    std::uniform_real_distribution<double> U(0, 1);
    for (Distribution d : kAll) {
        CaseSet crossing, part, below;
        while (crossing.cases.size() < 24 || below.cases.size() < 8) {
            const double nv = 0.1 + 0.8 * U(rng);
            const glm::dvec3 n(0, 0, 1), v(std::sqrt(1 - nv * nv), 0, nv);
            const double phi = M_PI + 1.6 * (U(rng) - 0.5), elev = 0.7 * (U(rng) - 0.5);
            const glm::dvec3 dir(std::cos(elev) * std::cos(phi), std::cos(elev) * std::sin(phi),
                                 std::sin(elev));
            const glm::dvec3 t1 = glm::normalize(glm::cross(dir, n)), t2 = glm::cross(t1, dir);
            const double h1 = 0.2 + 1.2 * U(rng), h2 = 0.05 + 1.2 * U(rng);
            const glm::dvec3 C = 2.0 * dir;
            std::vector<glm::dvec3> quad = {C - h1 * t1 - h2 * t2, C + h1 * t1 - h2 * t2,
                                            C + h1 * t1 + h2 * t2, C - h1 * t1 + h2 * t2};
            if (glm::dot(glm::cross(quad[1] - quad[0], quad[2] - quad[0]), -quad[0]) < 0)
                std::swap(quad[1], quad[3]);
            std::vector<glm::dvec3> above;
            for (std::size_t i = 0; i < quad.size(); ++i) {
                const glm::dvec3 a = quad[i], b = quad[(i + 1) % quad.size()];
                if (a.z >= 0) above.push_back(a);
                if ((a.z >= 0) != (b.z >= 0)) above.push_back(a + (b - a) * (a.z / (a.z - b.z)));
            }
            const double param = d == Distribution::Phong || d == Distribution::Blinn
                                     ? std::exp(std::log(2e3) * U(rng))
                                     : 0.03 + 0.5 * U(rng);
            const std::string id = "q" + std::to_string(crossing.cases.size() + below.cases.size());
            if (above.empty() && below.cases.size() < 8) {
                below.cases.push_back(polygon_case(id, quad, n, v, d, param));
            } else if (above.size() >= 3 &&
                       std::min({quad[0].z, quad[1].z, quad[2].z, quad[3].z}) < -0.05 &&
                       crossing.cases.size() < 24) {
                crossing.cases.push_back(polygon_case(id, quad, n, v, d, param));
                part.cases.push_back(polygon_case(id, above, n, v, d, param));
            }
        }
        for (const std::string keys : {"", "table=fit"}) {
            if (!keys.empty() && d != Distribution::Ggx) continue;
            const std::string name = ltc_name(d, keys);
            for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
                const ResultSet whole = run(b, name, crossing), upper = run(b, name, part),
                                none = run(b, name, below);
                REQUIRE(whole.results.size() == crossing.cases.size());
                REQUIRE(upper.results.size() == part.cases.size());
                REQUIRE(none.results.size() == below.cases.size());
                for (std::size_t i = 0; i < whole.results.size(); ++i) {
                    const double x = *whole.results[i].specular, y = *upper.results[i].specular;
                    INFO(name << " on " << to_string(b) << ", " << whole.results[i].id
                              << ": specular " << x << ", its part above the horizon " << y);
                    CHECK(std::abs(x - y) <= kSameRegion * std::max(std::abs(y), 1e-2));
                }
                for (const CaseResult& r : none.results) {
                    INFO(name << " on " << to_string(b) << ", " << r.id
                              << " (below the horizon): specular " << *r.specular);
                    CHECK(*r.specular == 0);
                }
            }
        }
    }
}

TEST_CASE("ltc: every variant finite and non-negative at the extremes", "[shading][vulkan][ltc]") {
    // alpha 1e-3 and 1 (N 1 and 1e5), views from normal to grazing (n.v 1e-6) and from
    // below (specular 0), lights tiny, along r, crossing the horizon and nearly filling
    // the hemisphere; phong on blinn's cases.
    CaseSet set = extreme_microfacet_polygons();
    const std::size_t microfacet = set.cases.size();
    for (std::size_t i = 0; i < microfacet; ++i) {
        if (set.cases[i].material.distribution != Distribution::Blinn) continue;
        Case c = set.cases[i];
        c.id += "-phong";
        c.material.distribution = Distribution::Phong;
        set.cases.push_back(c);
    }
    for (const auto& v : enumerate_variants()) {
        // Curved lights: test_ltc_curved.cpp.
        if (v.method != Method::Ltc || v.light != LightType::Polygon) continue;
        const std::string name = canonical_name(v);
        for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
            const ResultSet out = run(b, name, set);
            CHECK(!out.results.empty());
            check_finite_non_negative(out, name + " " + to_string(b));
        }
    }
}

}  // namespace arealight::test
