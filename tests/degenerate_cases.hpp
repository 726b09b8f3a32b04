// The seeded set of exactly degenerate but common inputs (tests/data/degenerate.cases.json,
// written by scripts/gen_curved_cases.py 160 23 --kind degenerate): v exactly n, floor points
// under axis-aligned lights on fp32-exact grids, axis-aligned views, r exactly through a
// corner or a silhouette point; every light type and distribution.
#pragma once

#include <catch2/catch.hpp>
#include <string>

#include "arealight/case_io.hpp"

namespace arealight::test {

inline const CaseSet& degenerate_cases() {
    static const CaseSet set = [] {
        std::string why;
        auto s = read_cases(AREALIGHT_TEST_DATA "/degenerate.cases.json",
                            [&](const Diagnostic& d) { why += d.message + "\n"; });
        INFO(why);
        REQUIRE(s);
        return *s;
    }();
    return set;
}

}  // namespace arealight::test
