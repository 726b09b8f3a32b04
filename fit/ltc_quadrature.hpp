// Gauss-Legendre rules on [0, 1] for the fitter's deterministic quadratures.
#pragma once

#include <cmath>
#include <vector>

#include "ltc_vec.hpp"

namespace arealight::ltcfit {

struct GaussRule {
    std::vector<double> x, w;  // nodes and weights on [0, 1]
};

// n-point Gauss-Legendre rule on [0, 1] (Newton on P_n, double precision).
inline GaussRule gauss_legendre(int n) {
    GaussRule r;
    r.x.resize(n);
    r.w.resize(n);
    for (int i = 0; i < n; ++i) {
        double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
        double dp = 1;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1, p1 = z;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (z * p1 - p0) / (z * z - 1);
            const double dz = p1 / dp;
            z -= dz;
            if (std::abs(dz) < 1e-16) break;
        }
        r.x[n - 1 - i] = 0.5 * (z + 1);
        r.w[n - 1 - i] = 1.0 / ((1 - z * z) * dp * dp);  // 2 / ((1 - z^2) P'^2), halved for [0, 1]
    }
    return r;
}

// Composite rule: `panels` equal panels of an n-point rule on [0, 1].
inline GaussRule composite_gauss(int panels, int n) {
    const GaussRule g = gauss_legendre(n);
    GaussRule r;
    for (int p = 0; p < panels; ++p) {
        for (int i = 0; i < n; ++i) {
            r.x.push_back((p + g.x[i]) / panels);
            r.w.push_back(g.w[i] / panels);
        }
    }
    return r;
}

}  // namespace arealight::ltcfit
