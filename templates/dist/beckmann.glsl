// Beckmann microfacet distribution, CONTRACT.md 2: D = exp(-tan^2/alpha^2) /
// (pi alpha^2 cos^4) for alpha in [0.001, 1]. With u = tan^2 t / alpha^2,
// D sin t dt = exp(-u) sqrt(1 + alpha^2 u) du / (2 pi) and 2 pi D cos t sin t dt =
// exp(-u) du, so with U = tan^2 theta / alpha^2:
//   y = exp(-U),  2 pi G = int_0^U exp(-u) sqrt(1 + alpha^2 u) du,
//   T = alpha/(2 pi) exp(-U) A(1/(alpha c)^2),  A(x) = sqrt(x) + sqrt(pi)/2 erfcx(sqrt(x))
// (shift u -> U + w in the tail and 1 + alpha^2 U = 1/c^2). Inputs: c = n.h,
// s2 = |n x h|^2 (c^2 + s2 = 1 to rounding).

// Defined in dist/microfacet.glsl, which follows this file.
real al_erfcx(real x);
real al_beckmann_lambda(real alpha, real c, real s2);

struct AlDist {
    real param;        // alpha
    real alpha2;       // alpha^2
    real gmax;         // G(pi/2) = (1 + sqrt(pi)/2 alpha erfcx(1/alpha)) / (2 pi)
    real width;        // alpha
    real smith_alpha;  // alpha
};

// The per-shading-point constants for alpha in [0.001, 1]; gmax from the tail's closed
// form at theta = 0 (checked against quadrature with G: fp64 <= 3e-15).
AlDist al_dist_make(real param) {
    AlDist d;
    d.param = param;
    d.alpha2 = param * param;
    d.gmax = (AL_R(1.0) + AL_R(0.88622692545275801365) * param * al_erfcx(AL_R(1.0) / param)) /
             AL_TWO_PI;
    d.width = param;
    d.smith_alpha = param;
    return d;
}

// U = s2 / (alpha c)^2, capped at 1e4 (exp(-U) is 0 beyond 745) so a grazing c
// gives neither inf nor NaN. Relative error 2 ulp, so exp(-U) carries U ulp.
real al_beckmann_u(AlDist d, real c, real s2) {
    return min(s2 / max(d.alpha2 * c * c, AL_R(1e-30)), AL_R(1e4));
}

// D(h), CONTRACT.md 2; 0 for c <= 0. Relative error ~U ulp; measured vs the
// contract's D in long double: fp64 <= 1.6e-13 (at D = 4e-231), fp32 <= 1.2e-5.
real al_ndf(AlDist d, real c, real s2) {
    if (c <= AL_R(0.0)) return AL_R(0.0);
    real e = al_exp(-al_beckmann_u(d, c, s2));
    if (e == AL_R(0.0)) return AL_R(0.0);
    real c2 = c * c;
    return e / (AL_PI * d.alpha2 * c2 * c2);
}

// T(theta) = exp(-U)/(2 pi c) (1 + sqrt(pi)/2 z erfcx(1/z)), z = alpha c (the closed
// form above, verified by quadrature); sum of positives, so relative for any theta.
// 0 for c <= 0. Measured vs quadrature: fp64 <= 1.6e-13 (U ulp, at T = 1e-234),
// fp32 <= 8.6e-6.
real al_ndf_tail(AlDist d, real c, real s2) {
    if (c <= AL_R(0.0)) return AL_R(0.0);
    real e = al_exp(-al_beckmann_u(d, c, s2));
    if (e == AL_R(0.0)) return AL_R(0.0);
    real z = d.param * c;
    return e * (AL_R(1.0) + AL_R(0.88622692545275801365) * z * al_erfcx(AL_R(1.0) / z)) /
           (AL_TWO_PI * c);
}

// G(theta): below U = 1/8 the Taylor series of 2 pi G = sum c_k U^(k+1)/(k+1), c_k of
// exp(-u) sqrt(1 + alpha^2 u) by the recurrence of its ODE (1 + a u) f' =
// (a/2 - 1 - a u) f, a = alpha^2, terms <= U^k; beyond, gmax - T (cancels <= 12x).
// c <= 0 gives gmax. Measured vs quadrature: fp64 <= 3.0e-15 (just above U = 1/8 at
// alpha = 1), fp32 <= 1.5e-6.
real al_ndf_cumulative(AlDist d, real c, real s2) {
    if (c <= AL_R(0.0)) return d.gmax;
    real u = al_beckmann_u(d, c, s2);
    if (u >= AL_R(0.125)) return d.gmax - al_ndf_tail(d, c, s2);
    real a = d.alpha2;
    real ck = AL_R(1.0), ck_prev = AL_R(0.0), uk = u, sum = AL_R(0.0);
#if AL_PRECISION_FP64
    const int terms = 19;
#else
    const int terms = 9;
#endif
    for (int k = 0; k < terms; ++k) {
        real kr = real(k), inv = AL_R(1.0) / (kr + AL_R(1.0));
        sum += ck * uk * inv;
        real next = ((AL_R(0.5) * a - AL_R(1.0) - a * kr) * ck - a * ck_prev) * inv;
        ck_prev = ck;
        ck = next;
        uk *= u;
    }
    return sum / AL_TWO_PI;
}

// y(theta) = exp(-U); 0 for c <= 0. Measured vs quadrature: fp64 <= 1.6e-13 (U ulp),
// fp32 <= 8.7e-6.
real al_ndf_y(AlDist d, real c, real s2) {
    if (c <= AL_R(0.0)) return AL_R(0.0);
    return al_exp(-al_beckmann_u(d, c, s2));
}

// (cos, sin) with exp(-tan^2/alpha^2) = y: t2 = -alpha^2 log y, c = 1/sqrt(1 + t2),
// s = sqrt(t2) c (no cancellation). y <= 0 gives (0, 1). Measured vs the exact
// inverse: fp64 <= 3.3e-16, fp32 <= 1.9e-7.
rvec2 al_ndf_y_inverse(AlDist d, real y) {
    if (y <= AL_R(0.0)) return rvec2(AL_R(0.0), AL_R(1.0));
    real t2 = d.alpha2 * max(-al_log(y), AL_R(0.0));
    real c = AL_R(1.0) / sqrt(AL_R(1.0) + t2);
    return rvec2(c, sqrt(t2) * c);
}

// CONTRACT.md 2's Beckmann Lambda (dist/microfacet.glsl). Measured: fp64 <= 2.8e-13 (2 a^2
// ulp at Lambda = 1e-248), fp32 <= 1.1e-5.
real al_smith_lambda(AlDist d, real c, real s2) {
    return al_beckmann_lambda(d.param, c, s2);
}
