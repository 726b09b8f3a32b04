// GGX (Trowbridge-Reitz) microfacet distribution, CONTRACT.md 2: D = alpha^2 /
// (pi ((n.h)^2 (alpha^2 - 1) + 1)^2), alpha in [0.001, 1]; the denominator's base is
// q = 1 - b c^2 = s2 + alpha^2 c^2 (b = 1 - alpha^2), formed without cancellation.
// From int du/(1 - b u^2)^2 = F(u) = u/(2(1 - b u^2)) + atanh(sqrt(b) u)/(2 sqrt(b)):
//   G = alpha^2/pi (F(1) - F(c)),  T = alpha^2/pi F(c),  y = alpha^2 c^2 / q.
// Inputs: c = n.h, s2 = |n x h|^2 (c^2 + s2 = 1 to rounding).

struct AlDist {
    real param;        // alpha
    real alpha2;       // alpha^2
    real sqrt_b;       // sqrt(1 - alpha^2), 0 at alpha = 1
    real gmax;         // G(pi/2) = (1 + alpha^2 atanh(sqrt b)/sqrt b) / (2 pi)
    real width;        // alpha
    real smith_alpha;  // alpha
};

// atanh(x)/x for x in [0, 1), with q = 1 - x^2 given accurately (x may be 1 - 5e-7):
// the odd series (common/common.glsl) up to 0.17, else atanh = log1p(2x(1+x)/q)/2, which
// needs no 1 - x. A few ulp; -> 1 at x = 0 (alpha = 1).
real al_ggx_atanh_ratio(real x, real q) {
    if (x < AL_R(1e-9)) return AL_R(1.0);
    if (x < AL_R(0.17)) return al_log_ratio_series(x) / (AL_R(2.0) * x);
    return AL_R(0.5) * al_log1p(AL_R(2.0) * x * (AL_R(1.0) + x) / q) / x;
}

// The per-shading-point constants for alpha in [0.001, 1]; gmax = T(0) (checked
// against quadrature with G: fp64 <= 4.8e-16).
AlDist al_dist_make(real param) {
    AlDist d;
    d.param = param;
    d.alpha2 = param * param;
    d.sqrt_b = sqrt(max(AL_R(1.0) - d.alpha2, AL_R(0.0)));
    d.gmax = (AL_R(1.0) + d.alpha2 * al_ggx_atanh_ratio(d.sqrt_b, d.alpha2)) / AL_TWO_PI;
    d.width = param;
    d.smith_alpha = param;
    return d;
}

// D(h), CONTRACT.md 2; 0 for c <= 0. Measured vs the contract's D in long double:
// fp64 <= 8.2e-16 relative, fp32 <= 4.6e-7.
real al_ndf(AlDist d, real c, real s2) {
    if (c <= AL_R(0.0)) return AL_R(0.0);
    real q = s2 + d.alpha2 * c * c;
    return d.alpha2 / (AL_PI * q * q);
}

// T(theta) = alpha^2 c/(2 pi) (1/q + atanh(x)/x), x = sqrt(b) c, 1 - x^2 = q: a sum
// of positives, relative for any theta. 0 for c <= 0. Measured vs quadrature: fp64
// <= 4.7e-16, fp32 <= 2.9e-7.
real al_ndf_tail(AlDist d, real c, real s2) {
    if (c <= AL_R(0.0)) return AL_R(0.0);
    real q = s2 + d.alpha2 * c * c;
    return d.alpha2 * c / AL_TWO_PI *
           (AL_R(1.0) / q + al_ggx_atanh_ratio(d.sqrt_b * c, q));
}

// G(theta) = alpha^2/pi (F(1) - F(c)) rewritten without any difference:
//   1/(2 alpha^2) - c/(2q) = s2 (1 - alpha^2 c/(1+c)) / (2 alpha^2 q)   (1 - c = s2/(1+c)),
//   atanh(sqrt b) - atanh(sqrt b c) = atanh(Z) = log1p(W)/2 with
//   W = 2Z/(1-Z) = 2 sqrt(b) s2 / (alpha^2 M),  M = s2/(1 + sqrt b) + c(1 + c),
// so G = s2/(2 pi) ((1 - alpha^2 c/(1+c))/q + (log1p(W)/W)/M): positive terms only,
// relative for every theta, c in [0, 1]. c <= 0 gives gmax. Measured vs quadrature:
// fp64 <= 4.8e-16, fp32 <= 2.9e-7.
real al_ndf_cumulative(AlDist d, real c, real s2) {
    if (c <= AL_R(0.0)) return d.gmax;
    real q = s2 + d.alpha2 * c * c;
    real m = s2 / (AL_R(1.0) + d.sqrt_b) + c * (AL_R(1.0) + c);
    real w = AL_R(2.0) * d.sqrt_b * s2 / (d.alpha2 * m);
    real log_ratio = w > AL_R(1e-30) ? al_log1p(w) / w : AL_R(1.0);
    return s2 / AL_TWO_PI *
           ((AL_R(1.0) - d.alpha2 * c / (AL_R(1.0) + c)) / q + log_ratio / m);
}

// y(theta) = alpha^2 c^2 / q (2 alpha^2 int_0^c u du/(1 - b u^2)^2); 0 for c <= 0.
// Measured vs quadrature: fp64 <= 4.2e-16, fp32 <= 2.2e-7.
real al_ndf_y(AlDist d, real c, real s2) {
    if (c <= AL_R(0.0)) return AL_R(0.0);
    real ac2 = d.alpha2 * c * c;
    return ac2 / (s2 + ac2);
}

// (cos, sin) with y(theta) = y: tan^2 = alpha^2 (1 - y)/y, written over
// y + alpha^2 (1 - y) so y = 0 (the horizon) stays finite. Measured vs the exact
// inverse: fp64 <= 2.3e-16, fp32 <= 1.1e-7.
rvec2 al_ndf_y_inverse(AlDist d, real y) {
    real yc = clamp(y, AL_R(0.0), AL_R(1.0));
    real t = d.alpha2 * (AL_R(1.0) - yc);
    real den = yc + t;
    return rvec2(sqrt(yc / den), sqrt(t / den));
}

// CONTRACT.md 2's (sqrt(1 + alpha^2 tan^2) - 1)/2 as alpha^2 s2 / (2c (r + c)),
// r = sqrt(c^2 + alpha^2 s2): no cancellation at small angles; 0 at s2 = 0; c floored
// at 1e-20 so grazing gives a large finite value (<= 5e19). Measured vs the contract's
// formula in long double: fp64 <= 3.6e-16, fp32 <= 1.9e-7.
real al_smith_lambda(AlDist d, real c, real s2) {
    if (s2 <= AL_R(0.0)) return AL_R(0.0);
    real cc = max(c, AL_R(1e-20));
    real r = sqrt(cc * cc + d.alpha2 * s2);
    return d.alpha2 * s2 / (AL_R(2.0) * cc * (r + cc));
}
