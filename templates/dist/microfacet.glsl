// Distribution-independent microfacet helpers (CONTRACT.md 2): Smith's G2, Schlick's
// Fresnel and the Beckmann Lambda. Stitched after the dist file; blinn's and beckmann's
// files declare al_beckmann_lambda ahead and use it, so a variant with either
// distribution must stitch this file too (and common/erfcx.glsl, which it uses).

// Height-correlated Smith G2 = 1 / (1 + Lambda(w) + Lambda(v)), CONTRACT.md 2.
// Lambdas >= 0; exact to rounding.
real al_smith_g2(real lambda_w, real lambda_v) {
    return AL_R(1.0) / (AL_R(1.0) + lambda_w + lambda_v);
}

// Schlick's F = f0 + (1 - f0)(1 - h.v)^5, CONTRACT.md 2; h.v clamped to [0, 1] so a
// rounding excess cannot make F leave [f0, 1]. Exact to rounding.
real al_schlick(real f0, real hv) {
    real m = AL_R(1.0) - clamp(hv, AL_R(0.0), AL_R(1.0));
    real m2 = m * m;
    return f0 + (AL_R(1.0) - f0) * (m2 * m2 * m);
}

#if defined(AL_DIST_BECKMANN) || defined(AL_DIST_BLINN)
// Beckmann Smith Lambda, CONTRACT.md 2, a = 1/(alpha tan theta) = c/(alpha sqrt(s2)):
// (erf(a) - 1)/2 + exp(-a^2)/(2 a sqrt(pi)) = exp(-a^2)/2 (1/(a sqrt(pi)) - erfcx(a)),
// the bracket R(a)/a beyond a = 4 (no cancellation; at most 36x below). 0 at s2 = 0;
// c is floored at 1e-20 so grazing gives a large finite value (<= 3e19). Relative
// error ~2 a^2 ulp (exp(-a^2)); measured vs the contract's formula in long double:
// fp64 <= 2.8e-13 (at Lambda = 1e-248), fp32 <= 1.5e-5 (a near 4, the bracket cancels).
real al_beckmann_lambda(real alpha, real c, real s2) {
    if (s2 <= AL_R(0.0)) return AL_R(0.0);
    real a = max(c, AL_R(1e-20)) / (alpha * sqrt(s2));
    if (a > AL_R(27.0)) return AL_R(0.0);  // exp(-a^2) < 3e-317
    real h = a > AL_R(4.0) ? al_erfcx_asym(a) / a
                           : AL_R(0.56418958354775628695) / a - al_erfcx(a);
    return AL_R(0.5) * al_exp(-a * a) * h;
}
#endif
