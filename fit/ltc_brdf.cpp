#include "ltc_brdf.hpp"

#include <algorithm>
#include <cmath>

#include "ltc_quadrature.hpp"

namespace arealight::ltcfit {

namespace {

constexpr double kSqrtPi = 1.77245385090551602730;

double pow5(double x) {
    const double x2 = x * x;
    return x2 * x2 * x;
}

}  // namespace

double ltc_alpha_of_param(Distribution d, double param) {
    if (d == Distribution::Phong || d == Distribution::Blinn) return std::sqrt(2.0 / (param + 2.0));
    return param;
}

BrdfLobe::BrdfLobe(Distribution d, double alpha, double cos_theta_v)
    : dist_(d), alpha_(alpha), exponent_(2.0 / (alpha * alpha) - 2.0) {
    const double c = std::clamp(cos_theta_v, 0.0, 1.0);
    const double s = std::sqrt(std::max(0.0, (1 - c) * (1 + c)));
    v_ = {s, 0, c};
    r_ = {-s, 0, c};
    if (d != Distribution::Phong) lambda_v_ = lambda(v_);
}

double BrdfLobe::ndf(V3 h) const {
    const double s2 = h.x * h.x + h.y * h.y;  // sin^2 theta_h, accurate near the peak
    const double c2 = h.z * h.z;
    switch (dist_) {
        case Distribution::Ggx: {
            const double a2 = alpha_ * alpha_;
            const double den = s2 + a2 * c2;  // (n.h)^2 (a^2 - 1) + 1
            return a2 / (kPi * den * den);
        }
        case Distribution::Beckmann: {
            const double a2 = alpha_ * alpha_;
            return std::exp(-s2 / (c2 * a2)) / (kPi * a2 * c2 * c2);
        }
        case Distribution::Blinn:
            // (n.h)^N with log(n.h) = log1p(-sin^2) / 2.
            return (exponent_ + 2) / (2 * kPi) * std::exp(0.5 * exponent_ * std::log1p(-s2));
        case Distribution::Phong:
            break;
    }
    return 0;
}

double BrdfLobe::lambda(V3 w) const {
    const double s2 = w.x * w.x + w.y * w.y;
    if (s2 <= 0) return 0;
    if (w.z <= 0) return HUGE_VAL;
    const double t2 = s2 / (w.z * w.z);
    if (dist_ == Distribution::Ggx) {
        const double q = alpha_ * alpha_ * t2;
        return q / (2 * (std::sqrt(1 + q) + 1));  // (sqrt(1 + q) - 1) / 2
    }
    // Beckmann's (blinn too, with its alpha): a = 1 / (alpha tan theta).
    const double a = 1 / (alpha_ * std::sqrt(t2));
    const double l = 0.5 * (std::exp(-a * a) / (a * kSqrtPi) - std::erfc(a));
    return std::max(l, 0.0);
}

double BrdfLobe::eval(V3 w, double* x) const {
    if (x) *x = 0;
    if (w.z <= 0) return 0;
    if (dist_ == Distribution::Phong) {
        const double rw = dot(r_, w);
        if (rw <= 0) return 0;
        return (exponent_ + 2) / (2 * kPi) * std::exp(exponent_ * std::log(rw)) * w.z;
    }
    if (v_.z <= 0) return 0;
    V3 h = w + v_;
    const double hl = length(h);
    if (!(hl > 0)) return 0;
    h = (1 / hl) * h;
    const double hv = std::clamp(dot(h, v_), 0.0, 1.0);
    const double d = ndf(h);
    const double lw = lambda(w);
    if (!std::isfinite(lw)) return 0;
    const double g2 = 1 / (1 + lw + lambda_v_);
    if (x) *x = pow5(1 - hv);
    return d * g2 / (4 * v_.z);
}

void BrdfLobe::half_vector_of(double u1, double& cos_h, double& sin_h) const {
    switch (dist_) {
        case Distribution::Ggx: {
            // tan^2 = a^2 u / (1 - u)
            const double t2 = alpha_ * alpha_ * u1 / (1 - u1);
            cos_h = 1 / std::sqrt(1 + t2);
            sin_h = std::sqrt(t2 / (1 + t2));
            return;
        }
        case Distribution::Beckmann: {
            const double t2 = -alpha_ * alpha_ * std::log1p(-u1);
            cos_h = 1 / std::sqrt(1 + t2);
            sin_h = std::sqrt(t2 / (1 + t2));
            return;
        }
        case Distribution::Blinn:
        case Distribution::Phong: {
            // cos = u^(1 / (N + k)), k = 2 (blinn: D (n.h)) or 1 (phong: (r.w)^N)
            const double k = dist_ == Distribution::Blinn ? 2 : 1;
            const double l = std::log(u1) / (exponent_ + k);
            cos_h = std::exp(l);
            const double one_minus = -std::expm1(l);
            sin_h = std::sqrt(std::max(0.0, one_minus * (1 + cos_h)));
            return;
        }
    }
}

V3 BrdfLobe::sample(double u1, double u2) const {
    double c, s;
    half_vector_of(u1, c, s);
    const double phi = 2 * kPi * u2;
    if (dist_ == Distribution::Phong) {
        const V3 t1{v_.z, 0, v_.x};  // perpendicular to r in the xz plane
        const V3 t2{0, 1, 0};
        return normalize(c * r_ + (s * std::cos(phi)) * t1 + (s * std::sin(phi)) * t2);
    }
    const V3 h{s * std::cos(phi), s * std::sin(phi), c};
    return normalize((2 * dot(v_, h)) * h - v_);
}

double BrdfLobe::pdf(V3 w) const {
    if (dist_ == Distribution::Phong) {
        const double rw = dot(r_, w);
        if (rw <= 0) return 0;
        return (exponent_ + 1) / (2 * kPi) * std::exp(exponent_ * std::log(rw));
    }
    V3 h = w + v_;
    const double hl = length(h);
    if (!(hl > 0)) return 0;
    h = (1 / hl) * h;
    const double hv = dot(h, v_);
    if (hv <= 0 || h.z <= 0) return 0;
    return ndf(h) * h.z / (4 * hv);
}

BrdfLobe::Moments BrdfLobe::hemisphere_moments() const {
    // The outer variable is the sampling's u1 (the polar angle about the lobe's axis, its
    // density flattened); the inner one the azimuth over the part that is above the
    // horizon, where the integrand is smooth (see below).
    static const GaussRule outer = composite_gauss(64, 8);
    static const GaussRule inner = gauss_legendre(32);
    Moments m;
    const double cv = v_.z, sv = v_.x;
    if (dist_ == Distribution::Phong) {
        // w = c r + s (cos phi t1 + sin phi t2): n.w = a + b cos phi, a = c cos_v, b = s sin_v;
        // the azimuthal integral of (a + b cos phi)_+ is closed form. dw = du1 dphi / pdf.
        for (std::size_t i = 0; i < outer.x.size(); ++i) {
            double c, s;
            half_vector_of(outer.x[i], c, s);
            const double a = c * cv, b = s * sv;
            double ring;
            if (b <= std::abs(a)) {
                ring = a > 0 ? 2 * kPi * a : 0;
            } else {
                const double phi0 = std::acos(std::clamp(-a / b, -1.0, 1.0));
                ring = 2 * (a * phi0 + b * std::sin(phi0));
            }
            m.total += outer.w[i] * (exponent_ + 2) / (exponent_ + 1) * ring / (2 * kPi);
        }
        return m;
    }
    if (cv <= 0) return m;
    // Half vector h(u1, phi) with density D(h) (n.h): the integral of f (n.w) over w is
    // that of G2 (h.v) / ((n.v)(n.h)) over du1 dphi / 2 pi, where w = reflect(v, h) is
    // above the horizon: 2 (h.v)(n.h) > n.v, i.e. cos phi > kappa (symmetric in phi).
    // u1 = 1 - (1 - t)^2 clusters the nodes at u1 = 1, where the integrand grows like
    // (1 - u1)^(-1/2) at grazing views (1 / (n.h) with D's long tail).
    for (std::size_t i = 0; i < outer.x.size(); ++i) {
        const double t = outer.x[i];
        const double weight = outer.w[i] * 2 * (1 - t);
        double ch, sh;
        half_vector_of(1 - (1 - t) * (1 - t), ch, sh);
        double phi0;
        if (sv * sh * ch <= 0) {
            phi0 = cv * (1 - 2 * ch * ch) < 0 ? kPi : 0;
        } else {
            const double kappa = cv * (1 - 2 * ch * ch) / (2 * ch * sh * sv);
            phi0 = kappa <= -1 ? kPi : kappa >= 1 ? 0 : std::acos(kappa);
        }
        if (phi0 <= 0) continue;
        double tot = 0, sch = 0;
        for (std::size_t k = 0; k < inner.x.size(); ++k) {
            const double phi = phi0 * inner.x[k];
            const V3 h{sh * std::cos(phi), sh * std::sin(phi), ch};
            const double hv = dot(h, v_);
            const V3 w = (2 * hv) * h - v_;
            if (w.z <= 0 || hv <= 0) continue;
            const double g2 = 1 / (1 + lambda(w) + lambda_v_);
            const double val = g2 * hv / (cv * ch) * inner.w[k];
            tot += val;
            sch += val * pow5(1 - std::min(hv, 1.0));
        }
        // phi over [-phi0, phi0] of d phi / (2 pi): 2 phi0 / (2 pi) times the mean.
        m.total += weight * tot * phi0 / kPi;
        m.schlick += weight * sch * phi0 / kPi;
    }
    return m;
}

}  // namespace arealight::ltcfit
