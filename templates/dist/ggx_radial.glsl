// The radial variable of the exact microfacet specular rule for ggx (method/exact_microfacet.glsl).
// The specular rule's radial variable (method/exact_microfacet.glsl): z =
// asinh(tan(theta) / alpha), so y = 1 / cosh^2 z and D sin dtheta = |dy/dz| dz /
// (2 pi cos theta). GGX's tail falls as 1/theta^4: in z it decays like e^(-2z),
// and W varies on the scale of z ~ 1 both in the core and in the tail. Domain:
// c in [0, 1] (z capped at 40 for c = 0); relative error a few ulp.
// The scale of the lobe's core in z, past which the mass decays as e^(-z): the rule spreads
// its nodes in log(1 + z / AL_RADIAL_CORE) (method/exact_microfacet.glsl, al_mf_mean_weight).
#define AL_RADIAL_CORE AL_R(10.0)
real al_radial_z(AlDist d, real c, real s2) {
    if (!(c > AL_R(0.0))) return AL_R(40.0);
    real x = sqrt(s2) / (c * d.param);
    // asinh x = log1p(x + x^2 / (1 + sqrt(1 + x^2))), without cancellation at small x.
    return min(al_log1p(x + x * x / (AL_R(1.0) + sqrt(AL_R(1.0) + x * x))), AL_R(40.0));
}

// (cos theta, sin theta, |dy/dz|) at the radial variable z >= 0 (al_radial_z).
rvec3 al_radial_node(AlDist d, real z) {
    real em = al_expm1(z);
    real sh = em * (em + AL_R(2.0)) / (AL_R(2.0) * (em + AL_R(1.0)));
    real ch = AL_R(1.0) + em * em / (AL_R(2.0) * (em + AL_R(1.0)));
    real t = d.param * sh;
    real c = inversesqrt(AL_R(1.0) + t * t);
    return rvec3(c, t * c, AL_R(2.0) * sh / (ch * ch * ch));
}
