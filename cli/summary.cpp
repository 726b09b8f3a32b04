#include "summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace arealight::cli {
namespace {

std::string cell(const std::optional<double>& x) {
    return x ? fmt::format("{:>12.6g}", *x) : fmt::format("{:>12}", "-");
}

}  // namespace

std::string results_table(const ResultSet& results) {
    std::size_t w = 4;
    for (const auto& r : results.results) w = std::max(w, r.id.size());
    std::string out = fmt::format("{:<{}} {:>12} {:>12} {:>12} {:>12} {:>10}\n", "case", w,
                                  "diffuse", "specular", "moment", "ndf", "error");
    for (const auto& r : results.results) {
        out += fmt::format("{:<{}} {} {} {} {} {:>10}\n", r.id, w, cell(r.diffuse),
                           cell(r.specular), cell(r.moment), cell(r.ndf),
                           r.error ? fmt::format("{:.1e}", *r.error) : "-");
    }
    return out;
}

std::string results_summary(const ResultSet& results, double seconds) {
    std::size_t unconverged = 0;
    double worst = 0.0;
    for (const auto& r : results.results) {
        if (r.converged && !*r.converged) ++unconverged;
        // Relative bound with the 1e-3 floor of shared/tools/score.
        auto rel = [](const std::optional<double>& v, const std::optional<double>& e) {
            return v && e ? *e / std::max(std::abs(*v), 1e-3) : 0.0;
        };
        worst = std::max({worst, rel(r.specular, r.error), rel(r.diffuse, r.error_diffuse),
                          rel(r.moment, r.error_moment), rel(r.ndf, r.error_ndf)});
    }
    return fmt::format(
        "{} cases in {:.2f} s; {} not converged; largest relative error bound {:.1e}\n",
        results.results.size(), seconds, unconverged, worst);
}

}  // namespace arealight::cli
