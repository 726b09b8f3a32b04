// The scaled complementary error function erfcx(x) = exp(x^2) erfc(x), x >= 0, for the
// microfacet distributions (the Beckmann Lambda, the slivers of the peak methods) and the
// Phong peak methods' z integral (method/phong_lobe_z.glsl): finite for every x, no
// underflow of exp(-x^2) before the product that needs it.

// R(x) of erfcx(x) = (1/sqrt(pi) - R(x)) / x for x > 4: Cody's third rational
// (W. J. Cody, Math. Comp. 23 (1969) 631-637, the coefficients of netlib specfun
// CALERF), R ~ 1/(2 sqrt(pi) x^2). Kept apart so the Beckmann Lambda gets
// 1/(x sqrt(pi)) - erfcx(x) = R/x without cancellation. x = inf gives 0.
real al_erfcx_asym(real x) {
    real z = AL_R(1.0) / (x * x);
    real num = AL_R(1.63153871373020978e-2) * z;
    real den = z;
    num = (num + AL_R(3.05326634961232344e-1)) * z;
    den = (den + AL_R(2.56852019228982242)) * z;
    num = (num + AL_R(3.60344899949804439e-1)) * z;
    den = (den + AL_R(1.87295284992346047)) * z;
    num = (num + AL_R(1.25781726111229246e-1)) * z;
    den = (den + AL_R(5.27905102951428412e-1)) * z;
    num = (num + AL_R(1.60837851487422766e-2)) * z;
    den = (den + AL_R(6.05183413124413191e-2)) * z;
    return z * (num + AL_R(6.58749161529837803e-4)) / (den + AL_R(2.33520497626869185e-3));
}

// erfcx(x) = exp(x^2) erfc(x) for x >= 0 (finite, -> 0, for x -> inf). Cody's
// near-minimax rationals (reference above; 18-digit approximations): x <= 0.46875
// erfc = 1 - x P(x^2)/Q(x^2) (cancels at most 2x), up to 4 P(x)/Q(x), beyond via R.
// Measured against Boost's erfc in long double, x in [0, 1e12]: fp64 <= 6.4e-16
// relative, fp32 <= 3.6e-7.
real al_erfcx(real x) {
    if (x <= AL_R(0.46875)) {
        real z = x * x;
        real num = AL_R(1.85777706184603153e-1) * z;
        real den = z;
        num = (num + AL_R(3.16112374387056560)) * z;
        den = (den + AL_R(2.36012909523441209e1)) * z;
        num = (num + AL_R(1.13864154151050156e2)) * z;
        den = (den + AL_R(2.44024637934444173e2)) * z;
        num = (num + AL_R(3.77485237685302021e2)) * z;
        den = (den + AL_R(1.28261652607737228e3)) * z;
        real erf_x = x * (num + AL_R(3.20937758913846947e3)) / (den + AL_R(2.84423683343917062e3));
        return al_exp(z) * (AL_R(1.0) - erf_x);
    }
    if (x <= AL_R(4.0)) {
        real num = AL_R(2.15311535474403846e-8) * x;
        real den = x;
        num = (num + AL_R(5.64188496988670089e-1)) * x;
        den = (den + AL_R(1.57449261107098347e1)) * x;
        num = (num + AL_R(8.88314979438837594)) * x;
        den = (den + AL_R(1.17693950891312499e2)) * x;
        num = (num + AL_R(6.61191906371416295e1)) * x;
        den = (den + AL_R(5.37181101862009858e2)) * x;
        num = (num + AL_R(2.98635138197400131e2)) * x;
        den = (den + AL_R(1.62138957456669019e3)) * x;
        num = (num + AL_R(8.81952221241769090e2)) * x;
        den = (den + AL_R(3.29079923573345963e3)) * x;
        num = (num + AL_R(1.71204761263407058e3)) * x;
        den = (den + AL_R(4.36261909014324716e3)) * x;
        num = (num + AL_R(2.05107837782607147e3)) * x;
        den = (den + AL_R(3.43936767414372164e3)) * x;
        return (num + AL_R(1.23033935479799725e3)) / (den + AL_R(1.23033935480374942e3));
    }
    return (AL_R(0.56418958354775628695) - al_erfcx_asym(x)) / x;
}

// erfcx(x) for x >= 0, where a method takes the fast form. AL_FAST_ARC: t Q(t), t = 1 / (1 + x/2), Q of degree 9 fitted
// near-minimax in relative error (scripts/fit_erfcx_fast.py): fp32 relative error <= 4.3e-7
// (al_erfcx: 3.6e-7) for one division and nine FMAs, where al_erfcx's three branches of
// rationals all count on a GPU (ggx pearson 26 857 -> 25 722 cycles a wave, navi21).
// Otherwise al_erfcx.
real al_erfcx_fast(real x) {
#ifdef AL_FAST_ARC
    real t = AL_R(1.0) / (AL_R(1.0) + AL_R(0.5) * x);
    real q = AL_R(-2.552324875e-02);
    q = q * t + AL_R(6.446360764e-02);
    q = q * t + AL_R(3.074845513e-02);
    q = q * t + AL_R(-1.985430958e-01);
    q = q * t + AL_R(7.946518291e-02);
    q = q * t + AL_R(5.826319569e-02);
    q = q * t + AL_R(1.804145358e-01);
    q = q * t + AL_R(2.465122442e-01);
    q = q * t + AL_R(2.821042176e-01);
    q = q * t + AL_R(2.820947471e-01);
    return t * q;
#else
    return al_erfcx(x);
#endif
}
