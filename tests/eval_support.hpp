// Helpers for the tests that run shader variants: one evaluator per backend for
// the whole test binary, variants by name, and the score metric's relL2.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>

#include "arealight/evaluator.hpp"
#include "arealight/reference.hpp"
#include "test_support.hpp"

namespace arealight::test {

// AREALIGHT_SPIRV_CACHE: the folder of compiled kernels the suite's processes share
// (spirv_cache.hpp; scripts/test.sh sets it). Unset: each process compiles its own.
inline std::string spirv_cache_folder() {
    const char* dir = std::getenv("AREALIGHT_SPIRV_CACHE");
    return dir ? dir : "";
}

inline Evaluator& evaluator(Backend b) {
    static std::map<Backend, std::unique_ptr<Evaluator>> cache;
    auto& e = cache[b];
    if (!e) {
        EvalOptions opt;
        opt.backend = b;
        opt.spirv_cache = spirv_cache_folder();
        std::string why;
        e = Evaluator::create(opt, [&](const Diagnostic& d) { why += d.message; });
        INFO(why);
        REQUIRE(e);
    }
    return *e;
}

inline Variant variant(const std::string& name) {
    std::string why;
    auto v = parse_variant(name, [&](const Diagnostic& d) { why += d.message; });
    INFO(why);
    REQUIRE(v);
    return *v;
}

inline ResultSet run(Backend b, const std::string& name, const CaseSet& cases) {
    std::string why;
    auto r = evaluator(b).run(variant(name), cases, [&](const Diagnostic& d) { why += d.message; });
    INFO(why);
    REQUIRE(r);
    return *r;
}

// relL2 of one quantity over a result set, the metric of shared/tools/score.
inline double rel_l2(const ResultSet& out, const std::map<std::string, CaseResult>& ref,
                     std::optional<double> CaseResult::*q) {
    double num = 0, den = 0;
    for (const auto& r : out.results) {
        const double x = *(r.*q), y = *(ref.at(r.id).*q);
        num += (x - y) * (x - y);
        den += y * y;
    }
    return std::sqrt(num / den);
}

// The oracle's results for every case of a set, by id.
inline std::map<std::string, CaseResult> oracle(const CaseSet& set) {
    std::map<std::string, CaseResult> ref;
    for (const auto& c : set.cases) ref[c.id] = reference_case(c);
    return ref;
}

// Largest relative difference (score metric with `floor`) of diffuse and specular
// between two runs of the same cases, and the case where it is.
inline double worst_difference(const ResultSet& a, const ResultSet& b, std::string& where,
                               double floor = 1e-3) {
    double worst = 0;
    for (std::size_t i = 0; i < a.results.size() && i < b.results.size(); ++i) {
        for (auto q : {&CaseResult::diffuse, &CaseResult::specular}) {
            const double e = rel_err(*(a.results[i].*q), *(b.results[i].*q), floor);
            if (e > worst) {
                worst = e;
                where = a.results[i].id;
            }
        }
    }
    return worst;
}

// diffuse and specular of every result finite and >= 0 (CONTRACT.md 2), naming the
// run (`label`) and the case on failure.
inline void check_finite_non_negative(const ResultSet& out, const std::string& label) {
    for (const auto& res : out.results) {
        INFO(label << " " << res.id << ": diffuse " << *res.diffuse << ", specular "
                   << *res.specular);
        CHECK(std::isfinite(*res.diffuse));
        CHECK(std::isfinite(*res.specular));
        CHECK(*res.diffuse >= 0.0);
        CHECK(*res.specular >= 0.0);
    }
}

// The bars of one variant against the oracle on both backends.
struct OracleBars {
    double specular;        // specular relL2
    double diffuse_rel_l2;  // diffuse relL2
    double diffuse_case;    // the largest diffuse case error (floor 1e-3)
    double backend;         // CPU mirror against lavapipe, per case (floor 1e-2)
    OracleBars with_specular(double s) const { return {s, diffuse_rel_l2, diffuse_case, backend}; }
};

// A diffuse in closed form computed in fp32 (a polygon's vector form factor, an ellipse
// cone's form factor): fp32 rounding only; the two backends are the same fp32 math in
// another order. No specular bar (infinite): set one with with_specular.
constexpr OracleBars kClosedFormDiffuse = {1e300, 1e-5, 1e-4, 1e-3};

// Runs `name` on `cases` on the CPU mirror and on lavapipe and checks each against the
// oracle's `ref` and the two against each other, printing the measured values; returns
// each backend's results for further checks.
inline std::map<Backend, ResultSet> check_both_backends(const std::string& name, const CaseSet& cases,
                                const std::map<std::string, CaseResult>& ref,
                                const OracleBars& bars) {
    std::map<Backend, ResultSet> out;
    for (Backend b : {Backend::Cpu, Backend::Vulkan}) {
        out[b] = run(b, name, cases);
        REQUIRE(out[b].results.size() == cases.cases.size());
        check_finite_non_negative(out[b], name + " " + to_string(b));
        const double spec = rel_l2(out[b], ref, &CaseResult::specular);
        const double diff = rel_l2(out[b], ref, &CaseResult::diffuse);
        double worst = 0, worst_spec = 0;
        std::string worst_at, worst_spec_at;
        for (const auto& r : out[b].results) {
            const double e = rel_err(*r.diffuse, *ref.at(r.id).diffuse);
            if (e > worst) worst = e, worst_at = r.id;
            const double s = rel_err(*r.specular, *ref.at(r.id).specular);
            if (s > worst_spec) worst_spec = s, worst_spec_at = r.id;
        }
        INFO(name << " on " << to_string(b) << ": specular relL2 " << spec << " (bar "
                  << bars.specular << "), worst specular case " << worst_spec << " at "
                  << worst_spec_at << "; diffuse relL2 " << diff << ", worst diffuse case "
                  << worst << " at " << worst_at);
        CHECK(spec <= bars.specular);
        CHECK(diff <= bars.diffuse_rel_l2);
        CHECK(worst <= bars.diffuse_case);
    }
    std::string worst_at;
    const double worst = worst_difference(out[Backend::Vulkan], out[Backend::Cpu], worst_at, 1e-2);
    INFO(name << ": worst CPU/GPU relative difference " << worst << " at " << worst_at);
    CHECK(worst <= bars.backend);
    return out;
}

// The variant on the CPU mirror on `cases` and on the same cases each moved by a random
// rotation and a translation of up to 5 per axis: the library works relative to p, so
// only the fp32 rounding of the moved inputs may differ, by at most `tol` (floor 1e-3).
inline void check_rigid_motion(const std::string& name, const CaseSet& cases,
                               std::mt19937_64& rng, double tol) {
    std::uniform_real_distribution<double> U(-5, 5);
    CaseSet moved = cases;
    for (auto& c : moved.cases)
        c = transformed(c, random_rotation(rng), glm::dvec3(U(rng), U(rng), U(rng)));
    const ResultSet a = run(Backend::Cpu, name, cases);
    const ResultSet b = run(Backend::Cpu, name, moved);
    REQUIRE(a.results.size() == b.results.size());
    std::string at;
    const double worst = worst_difference(b, a, at);
    INFO(name << ": largest change under a rigid motion " << worst << " at " << at);
    CHECK(worst <= tol);
}

}  // namespace arealight::test
