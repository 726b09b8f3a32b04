// One linearly transformed cosine in the local frame of include/arealight/ltc_table.hpp:
// Minv = [[a, 0, b], [0, c, 0], [d, 0, 1]], density D(w) = D_o(w_o) |dw_o / dw|.
#pragma once

#include <vector>

#include "ltc_vec.hpp"

namespace arealight::ltcfit {

class LtcDistribution {
  public:
    LtcDistribution() = default;
    explicit LtcDistribution(const M3& minv);  // any positive multiple of Minv
    static LtcDistribution from_cell(double a, double b, double c, double d);

    const M3& minv() const { return minv_; }
    const M3& m() const { return m_; }

    // Density over the sphere (integrates to 1).
    double eval(V3 w) const;
    // Cosine-distributed w_o from (u1, u2), mapped by M.
    V3 sample(double u1, double u2) const;
    // Integral of the density over the upper hemisphere z > 0 (closed form).
    double hemisphere_integral() const;

  private:
    M3 minv_, m_;
    double det_minv_ = 1;
};

// Projected solid angle / pi of the polygon with these (local-frame, not necessarily
// unit) vertex directions after mapping by Minv, clipped to z > 0: the LTC's integral
// over the polygon (the absolute value: independent of the winding).
double ltc_polygon_integral(const M3& minv, const std::vector<V3>& vertices);

}  // namespace arealight::ltcfit
