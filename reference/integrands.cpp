#include "integrands.hpp"

#include <cmath>

namespace arealight::ref {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Blinn-Phong's Smith term is Beckmann's with alpha = sqrt(2 / (N + 2)) (CONTRACT 2).
double effective_alpha(const Material& m) {
    return m.distribution == Distribution::Blinn ? std::sqrt(2.0 / (m.exponent + 2.0)) : m.alpha;
}

}  // namespace

double cos_power(const Vec3& a, const Vec3& b, double N) {
    const double half_chord2 = 0.5 * norm2(a - b);
    if (half_chord2 >= 1.0) return 0.0;
    return std::exp(N * std::log1p(-half_chord2));
}

double ndf_value(const Material& m, const Vec3& n, const Vec3& h) {
    const double c = dot(n, h);
    if (!(c > 0.0)) return 0.0;
    const double s2 = norm2(cross(n, h));  // sin^2(theta_h) without 1 - c^2
    switch (m.distribution) {
        case Distribution::Blinn:
            return (m.exponent + 2.0) / (2.0 * kPi) * cos_power(n, h, m.exponent);
        case Distribution::Beckmann: {
            const double a2 = m.alpha * m.alpha, c2 = c * c;
            return std::exp(-s2 / (c2 * a2)) / (kPi * a2 * c2 * c2);
        }
        case Distribution::Ggx: {
            // (n.h)^2 (a^2 - 1) + 1 = sin^2 + a^2 cos^2: no cancellation near n.
            const double a2 = m.alpha * m.alpha;
            const double d = s2 + a2 * c * c;
            return a2 / (kPi * d * d);
        }
        case Distribution::Phong:
            break;
    }
    return 0.0;
}

double smith_lambda(const Material& m, const Vec3& n, const Vec3& w) {
    const double c = dot(n, w);
    const double s = norm(cross(n, w));
    if (s == 0.0) return 0.0;  // normal incidence
    if (!(c > 0.0)) return INFINITY;
    const double alpha = effective_alpha(m);
    if (m.distribution == Distribution::Ggx) {
        // (sqrt(1 + x) - 1) / 2 = x / (2 (sqrt(1 + x) + 1)), x = alpha^2 tan^2.
        const double t = alpha * s / c;
        const double x = t * t;
        return x / (2.0 * (std::sqrt(1.0 + x) + 1.0));
    }
    // Beckmann and Blinn: a = 1 / (alpha tan), Lambda = (exp(-a^2)/(a sqrt(pi)) - erfc(a)) / 2.
    const double a = c / (alpha * s);
    if (a > 26.0) return 0.0;  // exp(-a^2) underflows; Lambda < 1e-290
    return 0.5 * (std::exp(-a * a) / (a * std::sqrt(kPi)) - std::erfc(a));
}

double schlick_fresnel(double f0, const Vec3& w, const Vec3& v) {
    const double x = norm2(w - v) / (2.0 * (2.0 + norm(w + v)));
    const double x2 = x * x;
    return f0 + (1.0 - f0) * (x2 * x2 * x);
}

}  // namespace arealight::ref
