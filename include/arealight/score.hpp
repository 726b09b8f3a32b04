// Error of a results file against a reference, with the metric of
// shared/tools/score: rel = |x - ref| / max(|ref|, floor), and relative L2.
#pragma once

#include <string>
#include <vector>

#include "arealight/results.hpp"

namespace arealight {

struct QuantityScore {
    std::string quantity;  // diffuse, specular, ndf, moment
    std::size_t n = 0, missing = 0, bad = 0;
    double median = 0, p95 = 0, max = 0, rel_l2 = 0;
    std::string worst;  // case id of the max
};

// One row per quantity the reference has, over the reference's cases that
// `out` holds (a variant runs on the cases it applies to).
std::vector<QuantityScore> score_results(const ResultSet& ref, const ResultSet& out,
                                         double floor = 1e-3);

// Fixed-width table of the scores.
std::string format_scores(const std::vector<QuantityScore>& scores);

}  // namespace arealight
