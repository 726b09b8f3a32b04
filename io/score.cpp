#include "arealight/score.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace arealight {
namespace {

const std::optional<double>& field(const CaseResult& r, const std::string& q) {
    if (q == "diffuse") return r.diffuse;
    if (q == "specular") return r.specular;
    if (q == "ndf") return r.ndf;
    return r.moment;
}

// The q-quantile as shared/tools/score takes it: element ceil(q n) - 1.
double quantile(const std::vector<double>& sorted, double q) {
    if (sorted.empty()) return NAN;
    const auto i = static_cast<std::size_t>(std::ceil(q * sorted.size()));
    return sorted[std::min(sorted.size() - 1, i > 0 ? i - 1 : 0)];
}

}  // namespace

std::vector<QuantityScore> score_results(const ResultSet& ref, const ResultSet& out, double floor) {
    std::map<std::string, const CaseResult*> by_id;
    for (const auto& r : out.results) by_id[r.id] = &r;
    std::vector<QuantityScore> scores;
    for (const std::string q : {"diffuse", "specular", "ndf", "moment"}) {
        QuantityScore s;
        s.quantity = q;
        std::vector<double> rels;
        double se = 0, sr = 0, worst = -1;
        for (const auto& r : ref.results) {
            const auto& rv = field(r, q);
            auto it = by_id.find(r.id);
            if (!rv || it == by_id.end()) continue;
            ++s.n;
            const auto& x = field(*it->second, q);
            if (!x) {
                ++s.missing;
                continue;
            }
            if (!std::isfinite(*x) || *x < 0) {
                ++s.bad;
                continue;
            }
            const double e = std::abs(*x - *rv), rel = e / std::max(std::abs(*rv), floor);
            rels.push_back(rel);
            se += e * e;
            sr += *rv * *rv;
            if (rel > worst) worst = rel, s.worst = r.id;
        }
        if (s.n == 0) continue;
        std::sort(rels.begin(), rels.end());
        s.median = quantile(rels, 0.5);
        s.p95 = quantile(rels, 0.95);
        s.max = rels.empty() ? NAN : rels.back();
        s.rel_l2 = sr > 0 ? std::sqrt(se / sr) : NAN;
        scores.push_back(s);
    }
    return scores;
}

std::string format_scores(const std::vector<QuantityScore>& scores) {
    std::string t = fmt::format("{:<9} {:>5} {:>5} {:>4} {:>9} {:>9} {:>9} {:>9}  {}\n", "quantity",
                                "n", "miss", "bad", "median", "p95", "max", "relL2", "worst");
    for (const auto& s : scores) {
        t += fmt::format("{:<9} {:>5} {:>5} {:>4} {:>9.2e} {:>9.2e} {:>9.2e} {:>9.2e}  {}\n",
                         s.quantity, s.n, s.missing, s.bad, s.median, s.p95, s.max, s.rel_l2,
                         s.worst);
    }
    return t;
}

}  // namespace arealight
