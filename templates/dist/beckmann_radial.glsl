// The radial variable of the exact microfacet specular rule for beckmann
// (method/exact_microfacet.glsl): z = tan(theta) / alpha = sqrt(-log y), y =
// exp(-z^2) the cosine-weighted tail (al_ndf_y), so D sin dtheta = |dy/dz| dz /
// (2 pi cos theta) with |dy/dz| = 2 z exp(-z^2): a Gaussian-like mass on z in
// [0, 6.5] (beyond, y < 3e-19), over which W varies smoothly. Domain: c in [0, 1];
// relative error a few ulp.
// With few radial nodes (AL_RADIAL <= 4) the rule uses y itself, z = 1 - y:
// the nodes sit at quantiles of the lobe's mass, which estimates the mean of W
// better than two or four nodes spread over the Gaussian-like variable
// (measured: specular relL2 on the public sets, 2 x 2 nodes, about 2x lower).
#if AL_RADIAL <= 4
real al_radial_z(AlDist d, real c, real s2) {
    if (!(c > AL_R(0.0))) return AL_R(1.0);
    return -al_expm1(-s2 / (c * c * d.param * d.param));
}
rvec3 al_radial_node(AlDist d, real z) {
    if (!(z < AL_R(1.0))) return rvec3(AL_R(0.0), AL_R(1.0), AL_R(1.0));
    real t2 = -d.param * d.param * al_log1p(-z);
    real c = inversesqrt(AL_R(1.0) + t2);
    return rvec3(c, sqrt(t2) * c, AL_R(1.0));
}
#else
real al_radial_z(AlDist d, real c, real s2) {
    if (!(c > AL_R(0.0))) return AL_R(6.5);
    return min(sqrt(s2) / (c * d.param), AL_R(6.5));
}

// (cos theta, sin theta, |dy/dz|) at the radial variable z >= 0 (al_radial_z).
rvec3 al_radial_node(AlDist d, real z) {
    real t = d.param * z;
    real c = inversesqrt(AL_R(1.0) + t * t);
    return rvec3(c, t * c, AL_R(2.0) * z * al_exp(-z * z));
}
#endif
