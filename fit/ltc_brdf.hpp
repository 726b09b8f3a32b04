// The BRDF-times-cosine lobes that the LTC tables approximate (CONTRACT.md 2), written
// here in double precision for the fitter and its checks (no code from templates/ or
// reference/). Local frame of include/arealight/ltc_table.hpp: n = z, the view in the
// xz plane, v = (sin theta_v, 0, cos theta_v).
#pragma once

#include "arealight/case.hpp"
#include "ltc_vec.hpp"

namespace arealight::ltcfit {

// Roughness of a distribution's parameter as the tables index it: alpha for beckmann
// and ggx, sqrt(2 / (N + 2)) for phong and blinn (N the exponent).
double ltc_alpha_of_param(Distribution d, double param);

class BrdfLobe {
  public:
    // alpha as above (phong and blinn: N = 2 / alpha^2 - 2); cos_theta_v in (0, 1].
    BrdfLobe(Distribution d, double alpha, double cos_theta_v);

    Distribution dist() const { return dist_; }
    double alpha() const { return alpha_; }
    double exponent() const { return exponent_; }
    V3 view() const { return v_; }

    // f(w, v) (n.w)_+ at the unit direction w (0 below the horizon); when x is given it
    // receives Schlick's weight (1 - h.v)^5 (0 for phong).
    double eval(V3 w, double* x = nullptr) const;

    // Importance sampling: the direction of (u1, u2) in (0, 1)^2 (phong: around the
    // mirror direction; microfacets: the half vector from D(h) (n.h), reflected), and the
    // density of that sampling at any unit w, over the whole sphere.
    V3 sample(double u1, double u2) const;
    double pdf(V3 w) const;

    // Integrals over the upper hemisphere by deterministic quadrature: of f (n.w) and of
    // x f (n.w) (phong: 0).
    struct Moments {
        double total = 0, schlick = 0;
    };
    Moments hemisphere_moments() const;

  private:
    double ndf(V3 h) const;        // D(h)
    double lambda(V3 w) const;     // Smith Lambda
    void half_vector_of(double u1, double& cos_h, double& sin_h) const;

    Distribution dist_;
    double alpha_, exponent_;
    V3 v_, r_;
    double lambda_v_ = 0;
};

}  // namespace arealight::ltcfit
