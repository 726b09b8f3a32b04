// The LTC specular of a polygon case exactly as the shader computes it (the frame of
// include/arealight/ltc_table.hpp, bilinear lookup with texel centres and clamp to edge,
// Minv applied to the vertices, clipped to z > 0, edge integrals), in double precision:
// the fitter's measure of a table against the oracle.
#pragma once

#include "arealight/case.hpp"
#include "arealight/ltc_table.hpp"

namespace arealight::ltcfit {

// Bilinear lookup of a table at a distribution parameter (exponent or alpha) and view.
LtcCell ltc_lookup(const LtcTable& t, double param, double cos_theta_v);

// specular (and diffuse: the plain polygon form factor) of a polygon case; false when the
// case is not a polygon of the table's distribution.
bool ltc_polygon_case(const LtcTable& t, const Case& c, double& specular, double& diffuse);

}  // namespace arealight::ltcfit
