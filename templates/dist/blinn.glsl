// Blinn-Phong microfacet distribution, CONTRACT.md 2: D = (N+2)/(2 pi) (n.h)_+^N for
// N in [1, 1e5]; Smith from Beckmann's Lambda at alpha = sqrt(2/(N+2)). With
// u = cos t every integral of D is a power of c:
//   G = (N+2)/(2 pi (N+1)) (1 - c^(N+1)),  T = gmax c^(N+1),  y = c^(N+2).
// Inputs: c = n.h, s2 = |n x h|^2 (c^2 + s2 = 1 to rounding).

// Defined in dist/microfacet.glsl, which follows this file.
real al_beckmann_lambda(real alpha, real c, real s2);

struct AlDist {
    real param;        // N
    real norm;         // (N+2)/(2 pi) = D(0)
    real gmax;         // G(pi/2) = (N+2)/(2 pi (N+1))
    real width;        // sqrt(2/(N+2)): D ~ exp(-theta^2/width^2) near the pole
    real smith_alpha;  // sqrt(2/(N+2)), CONTRACT.md 2
};

// The per-shading-point constants for N in [1, 1e5], exact to rounding (gmax is
// checked against quadrature with G).
AlDist al_dist_make(real param) {
    AlDist d;
    d.param = param;
    d.norm = (param + AL_R(2.0)) / AL_TWO_PI;
    d.gmax = d.norm / (param + AL_R(1.0));
    d.width = sqrt(AL_R(2.0) / (param + AL_R(2.0)));
    d.smith_alpha = d.width;
    return d;
}

// log(cos theta) for c > 0, from s2 near the pole (log1p, relative to s2/2) and from
// c elsewhere: the powers c^k below then carry k ulp of it, below 1e-13 where c^k is
// a normal number.
real al_blinn_log_cos(real c, real s2) {
    return s2 < AL_R(0.5) ? AL_R(0.5) * al_log1p(-s2) : al_log(c);
}

// D(h), CONTRACT.md 2; 0 for c <= 0. Relative error ~|N log c| ulp; measured vs the
// contract's D in long double: fp64 <= 1.4e-13 (at D = 1e-273), fp32 <= 1.4e-5.
real al_ndf(AlDist d, real c, real s2) {
    if (c <= AL_R(0.0)) return AL_R(0.0);
    return d.norm * al_exp(d.param * al_blinn_log_cos(c, s2));
}

// G(theta) = gmax (1 - c^(N+1)) via expm1: relative to G also at tiny theta.
// c <= 0 gives gmax. Measured vs quadrature of D: fp64 <= 4.9e-16, fp32 <= 2.7e-7.
real al_ndf_cumulative(AlDist d, real c, real s2) {
    if (c <= AL_R(0.0)) return d.gmax;
    return -d.gmax * al_expm1((d.param + AL_R(1.0)) * al_blinn_log_cos(c, s2));
}

// T(theta) = gmax c^(N+1); 0 for c <= 0. Measured vs quadrature: fp64 <= 1.8e-13
// (|N log c| ulp, at T = 1e-278), fp32 <= 1.0e-5 (at T = 6e-28).
real al_ndf_tail(AlDist d, real c, real s2) {
    if (c <= AL_R(0.0)) return AL_R(0.0);
    return d.gmax * al_exp((d.param + AL_R(1.0)) * al_blinn_log_cos(c, s2));
}

// y(theta) = c^(N+2) (2 pi int_0^c (N+2)/(2 pi) u^(N+1) du); 0 for c <= 0. Measured
// vs quadrature: fp64 <= 1.7e-13, fp32 <= 9.8e-6 (as the tail).
real al_ndf_y(AlDist d, real c, real s2) {
    if (c <= AL_R(0.0)) return AL_R(0.0);
    return al_exp((d.param + AL_R(2.0)) * al_blinn_log_cos(c, s2));
}

// (cos, sin) with c^(N+2) = y: log c = log(y)/(N+2), sin = sqrt(-expm1(2 log c)) (no
// cancellation near the pole). y <= 0 gives (0, 1). Measured vs the exact inverse of
// the given y: sin fp64 3.0e-16, fp32 1.5e-7; cos 2.4e-16 (9.1e-8) times 1 + |log c|.
rvec2 al_ndf_y_inverse(AlDist d, real y) {
    if (y <= AL_R(0.0)) return rvec2(AL_R(0.0), AL_R(1.0));
    real lc = min(al_log(y), AL_R(0.0)) / (d.param + AL_R(2.0));
    return rvec2(al_exp(lc), sqrt(-al_expm1(AL_R(2.0) * lc)));
}

// Beckmann Lambda at alpha = sqrt(2/(N+2)) (CONTRACT.md 2; dist/microfacet.glsl). Measured
// vs the contract's formula: fp64 <= 2.8e-13 (2 a^2 ulp at Lambda = 1e-266), fp32 1.5e-5.
real al_smith_lambda(AlDist d, real c, real s2) {
    return al_beckmann_lambda(d.smith_alpha, c, s2);
}
