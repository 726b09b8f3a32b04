// The CPU oracle: CONTRACT.md section 2 by adaptive cubature over the exact
// direction-space domain. It shares no code with the shader math.
#pragma once

#include <cstddef>

#include "arealight/case.hpp"
#include "arealight/diagnostics.hpp"
#include "arealight/results.hpp"

namespace arealight {

struct ReferenceOptions {
    double rel_tol = 1e-10;             // requested relative accuracy of every quantity
    double abs_tol = 1e-300;            // absolute accuracy that suffices (default: relative only)
    std::size_t max_eval = 20'000'000;  // integrand evaluations per quantity before giving up
    unsigned threads = 1;               // worker threads for reference_all
};

// One case: diffuse, specular, and moment (phong) or ndf (microfacet), each with
// an absolute error bound; `converged` is false when max_eval stopped a quantity.
CaseResult reference_case(const Case& c, const ReferenceOptions& opt = {});

// All cases, in order, on opt.threads threads; progress goes to `progress`.
ResultSet reference_all(const CaseSet& cases, const ReferenceOptions& opt,
                        const ProgressConsumer& progress = {});

}  // namespace arealight
