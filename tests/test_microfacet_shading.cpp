// Microfacet polygon variants (blinn, beckmann, ggx) against the oracle, one test
// body over both backends: the exact half-vector boundary rule at its reference
// node counts and at its O(1) counts, the point baseline, backend agreement, and
// finite non-negative values at the parameter and view extremes.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>

#include "arealight/evaluator.hpp"
#include "arealight/reference.hpp"
#include "eval_support.hpp"
#include "microfacet_cases.hpp"
#include "test_support.hpp"

using namespace arealight;
using namespace arealight::test;

namespace {

const Distribution kMicrofacets[] = {Distribution::Blinn, Distribution::Beckmann,
                                     Distribution::Ggx};

// Issue 10's bars for exact (score metric, floor 1e-3): ndf and diffuse p95 1e-5,
// specular p95 1e-4; and a max bar for both.
constexpr double kExactNdfP95Tol = 1e-5;
constexpr double kExactSpecularP95Tol = 1e-4;
constexpr double kMicrofacetExactMaxTol = 1e-3;
// fp64 arithmetic with the templates' own transcendentals: the backends agree to
// rounding (measured: bit-identical on these cases). fp32: the drivers' sin/cos/exp
// differ, and the pieces' branch points (near/far arc, core reach) amplify it at
// two or three nodes (measured worst 4.2e-4, blinn nodes=3).
constexpr double kBackendTol = 1e-6;
constexpr double kBackendFp32Tol = 1e-3;

std::string name_of(Distribution d, const std::string& rest) {
    return std::string("dist=") + to_string(d) + ",light=polygon," + rest;
}

double percentile95(std::vector<double> e) {
    std::sort(e.begin(), e.end());
    return e.empty() ? 0.0 : e[static_cast<std::size_t>(0.95 * (e.size() - 1))];
}

}  // namespace

TEST_CASE("exact microfacet shading matches the oracle on both backends", "[shading][vulkan][microfacet]") {
    for (Distribution d : kMicrofacets) {
        const CaseSet cases = random_microfacet_polygons(1000 + static_cast<int>(d), 50, d, "mf-");
        std::map<std::string, CaseResult> ref;
        for (const auto& c : cases.cases) ref[c.id] = reference_case(c, {});
        const std::string name = name_of(d, "method=exact");
        std::map<Backend, ResultSet> out;
        for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
            out[b] = run(b, name, cases);
            REQUIRE(out[b].results.size() == cases.cases.size());
            std::vector<double> e_ndf, e_spec, e_diff;
            double worst = 0;
            std::string worst_at;
            for (const auto& r : out[b].results) {
                const CaseResult& o = ref.at(r.id);
                e_ndf.push_back(rel_err(*r.ndf, *o.ndf));
                e_spec.push_back(rel_err(*r.specular, *o.specular));
                e_diff.push_back(rel_err(*r.diffuse, *o.diffuse));
                for (double e : {e_ndf.back(), e_spec.back(), e_diff.back()}) {
                    if (e > worst) worst = e, worst_at = r.id;
                }
            }
            INFO(name << " on " << to_string(b) << ": p95 ndf " << percentile95(e_ndf)
                      << ", specular " << percentile95(e_spec) << ", diffuse "
                      << percentile95(e_diff) << "; worst " << worst << " at " << worst_at);
            CHECK(percentile95(e_ndf) <= kExactNdfP95Tol);
            CHECK(percentile95(e_diff) <= kExactNdfP95Tol);
            CHECK(percentile95(e_spec) <= kExactSpecularP95Tol);
            CHECK(worst <= kMicrofacetExactMaxTol);
        }
        double worst = 0;
        for (std::size_t i = 0; i < cases.cases.size(); ++i) {
            const auto &c = out[Backend::Cpu].results[i], &g = out[Backend::Vulkan].results[i];
            worst = std::max({worst, rel_err(*g.specular, *c.specular), rel_err(*g.ndf, *c.ndf),
                              rel_err(*g.diffuse, *c.diffuse)});
        }
        INFO(name << ": worst CPU/GPU relative difference " << worst);
        CHECK(worst <= kBackendTol);
    }
}

TEST_CASE("fp64 exact microfacet specular at grazing views matches the oracle",
          "[shading][vulkan][microfacet]") {
    // Issue 25's bar at n.v = 1e-3, 1e-4 and 1e-7, alpha up to 1. Measured on these
    // cases: 6.4e-6 (ggx), 4.4e-6 (beckmann), 1.3e-7 (blinn); before GGX's radial nodes
    // followed its core (dist/ggx_radial.glsl) and Newton steps found each arc's closest
    // approach (al_moments_arc), 1.6e-4 (ggx) and 1.8e-4 (beckmann alpha 0.1), both at
    // n.v = 1e-7.
    constexpr double kGrazingSpecularTol = 1e-4;
    for (Distribution d : kMicrofacets) {
        const CaseSet cases = grazing_microfacet_polygons(3000 + static_cast<int>(d), d);
        const std::string name = name_of(d, "method=exact");
        for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
            const ResultSet out = run(b, name, cases);
            REQUIRE(out.results.size() == cases.cases.size());
            for (std::size_t i = 0; i < cases.cases.size(); ++i) {
                const CaseResult ref = reference_case(cases.cases[i], {});
                const auto& r = out.results[i];
                const Case& c = cases.cases[i];
                const double nv = glm::dot(g(c.n), g(c.v));
                const double e = rel_err(*r.specular, *ref.specular);
                INFO(name << " on " << to_string(b) << ", " << r.id << " (n.v " << nv
                          << "): specular "
                          << *r.specular << " against " << *ref.specular << ", error " << e);
                CHECK(e <= kGrazingSpecularTol);
            }
        }
    }
}

TEST_CASE("exact microfacet at O(1) node counts: bounded relL2, backends agree",
          "[shading][vulkan][microfacet]") {
    // Bars about 1.5x the worse backend's measured relL2 on these cases (in brackets).
    struct Bar {
        Distribution d;
        const char* keys;
        double ndf, specular;
    };
    const Bar bars[] = {
        {Distribution::Ggx, "method=exact,nodes=2,radial=2,precision=fp32", 1e-2, 1.2e-2},         // [6.5e-3, 8.0e-3]
        {Distribution::Beckmann, "method=exact,nodes=2,radial=2,precision=fp32", 2.2e-2, 1.7e-2},  // [1.47e-2, 1.14e-2]
        {Distribution::Blinn, "method=exact,nodes=2,radial=2,precision=fp32", 1.5e-2, 1.1e-2},     // [1.02e-2, 7.5e-3]
        {Distribution::Blinn, "method=exact,nodes=3,radial=2,precision=fp32", 4.2e-3, 3.7e-3},     // [2.7e-3, 2.4e-3]
    };
    for (const Bar& bar : bars) {
        const CaseSet cases = random_microfacet_polygons(2000 + static_cast<int>(bar.d), 50, bar.d, "mf-");
        std::map<std::string, CaseResult> ref;
        for (const auto& c : cases.cases) ref[c.id] = reference_case(c, {});
        const std::string name = name_of(bar.d, bar.keys);
        std::map<Backend, ResultSet> out;
        for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
            out[b] = run(b, name, cases);
            const double ndf = rel_l2(out[b], ref, &CaseResult::ndf);
            const double spec = rel_l2(out[b], ref, &CaseResult::specular);
            INFO(name << " on " << to_string(b) << ": relL2 ndf " << ndf << ", specular " << spec);
            CHECK(ndf <= bar.ndf);
            CHECK(spec <= bar.specular);
        }
        double worst = 0;
        for (std::size_t i = 0; i < cases.cases.size(); ++i) {
            const auto &c = out[Backend::Cpu].results[i], &g = out[Backend::Vulkan].results[i];
            worst = std::max({worst, rel_err(*g.specular, *c.specular), rel_err(*g.ndf, *c.ndf)});
        }
        INFO(name << ": worst CPU/GPU relative difference " << worst);
        CHECK(worst <= kBackendFp32Tol);
    }
}

TEST_CASE("microfacet variants: finite and non-negative at the extremes",
          "[shading][vulkan][microfacet]") {
    // alpha 1e-3 and 1 (N 1 and 1e5), views from normal to grazing (n.v 1e-6) and
    // from below (n.v < 0: specular 0), lights tiny, along r, crossing the horizon
    // and nearly filling the hemisphere.
    const CaseSet set = extreme_microfacet_polygons();
    for (Distribution d : kMicrofacets) {
        for (const char* keys : {"method=exact", "method=exact,nodes=2,radial=2,precision=fp32",
                                 "method=point"}) {
            const std::string name = name_of(d, keys);
            for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
                for (const auto& res : run(b, name, set).results) {
                    INFO(name << " " << to_string(b) << " " << res.id << ": diffuse "
                              << *res.diffuse << ", specular " << *res.specular);
                    CHECK(std::isfinite(*res.diffuse));
                    CHECK(std::isfinite(*res.specular));
                    CHECK(*res.specular >= 0.0);
                    if (res.ndf) {
                        CHECK(std::isfinite(*res.ndf));
                        CHECK(*res.ndf >= 0.0);
                    }
                }
            }
        }
    }
}
