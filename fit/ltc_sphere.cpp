// Horizon clipping of a sphere light (seed 001, Snyder's closed form; checked against
// quadrature in tests/test_ltc_fit.cpp).
#include <algorithm>
#include <cmath>

#include "arealight/ltc_table.hpp"

namespace arealight {

double sphere_horizon_form_factor(double cos_omega, double sin_sigma) {
    constexpr double kPi = 3.14159265358979323846;
    const double co = std::clamp(cos_omega, -1.0, 1.0);
    const double ss = std::clamp(sin_sigma, 0.0, 1.0);
    if (!(ss > 0)) return 0;
    const double so = std::sqrt(std::max(0.0, (1 - co) * (1 + co)));
    const double cs = std::sqrt(std::max(0.0, (1 - ss) * (1 + ss)));
    const double omega = std::acos(co), sigma = std::asin(ss);
    if (omega <= kPi / 2 - sigma) return co * ss * ss;  // entirely above the horizon
    if (omega >= kPi / 2 + sigma) return 0;             // entirely below
    // Straddling: sin omega > cos sigma >= 0 here (omega within sigma of pi / 2).
    const double gamma = std::asin(so > 0 ? std::min(1.0, cs / so) : 1.0);
    const double cg = std::cos(gamma), sg = std::sin(gamma);
    const double g = -2 * so * cs * cg + kPi / 2 - gamma + sg * cg;
    const double h =
        co * (cg * std::sqrt(std::max(0.0, ss * ss - cg * cg)) +
              ss * ss * std::asin(std::clamp(cg / ss, -1.0, 1.0)));
    const double i = co > 0 ? (kPi * co * ss * ss + g - h) / kPi : (g + h) / kPi;
    return std::clamp(i, 0.0, 1.0);
}

}  // namespace arealight
