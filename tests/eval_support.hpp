// Helpers for the tests that run shader variants: one evaluator per backend for
// the whole test binary, variants by name, and the score metric's relL2.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "arealight/evaluator.hpp"

namespace arealight::test {

inline Evaluator& evaluator(Backend b) {
    static std::map<Backend, std::unique_ptr<Evaluator>> cache;
    auto& e = cache[b];
    if (!e) {
        EvalOptions opt;
        opt.backend = b;
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

}  // namespace arealight::test
