// Internals of the fitter shared by the fit, the table code and the check tool.
#pragma once

#include "arealight/ltc_table.hpp"

namespace arealight::ltcfit {

// The fit's smallest cos theta_v (the grazing row is fitted there; see ltc_fit.cpp).
constexpr double kCosThetaMin = 1e-3;

// The view and roughness (alpha = rho^2) a cell of a size x size table is fitted at.
double fit_cos_theta(int size, int j);
double fit_alpha(Distribution d, int size, int i);

// Fits the LTC of one (alpha, cos theta_v) (fit_ltc_cell's work); isotropic: fit only
// m11 = m22 (the normal view).
LtcCell fit_ltc_at(Distribution d, double alpha, double cos_theta_v, const LtcCell* start,
                   bool isotropic);

// Phase 2's metric (sqrt of the relative cap error) of an LTC for the lobe of (alpha,
// cos theta_v), its samples drawn from that LTC: the fit's `error` of a cell.
double ltc_fit_error(Distribution d, double alpha, double cos_theta_v, const LtcCell& c);

}  // namespace arealight::ltcfit
