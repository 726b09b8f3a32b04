// Per-case outputs (CONTRACT.md section 3, arealight-results/1).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace arealight {

struct CaseResult {
    std::string id;
    std::optional<double> diffuse, specular, ndf, moment;
    // Oracle only: estimated absolute error bounds and convergence.
    std::optional<double> error, error_diffuse, error_ndf, error_moment;
    std::optional<bool> converged;
};

struct ResultSet {
    std::string variant;  // "oracle" for the reference
    std::string backend;  // "cpu" or "vulkan"
    std::vector<CaseResult> results;
};

}  // namespace arealight
