// The radial variable of the exact microfacet specular rule for blinn
// (method/exact_microfacet.glsl): z = sqrt(-log y) = sqrt(-(N+2) log cos(theta)),
// y = cos^(N+2)(theta) the cosine-weighted tail (al_ndf_y), so D sin dtheta =
// |dy/dz| dz / (2 pi cos theta) with |dy/dz| = 2 z exp(-z^2): a Gaussian-like mass
// on z in [0, 6.5] (beyond, y < 3e-19) for every N, over which W varies smoothly.
// Domain: c in [0, 1]; relative error a few ulp.
// With few radial nodes (AL_RADIAL <= 4) the rule uses y itself, z = 1 - y:
// the nodes sit at quantiles of the lobe's mass, which estimates the mean of W
// better than two or four nodes spread over the Gaussian-like variable
// (measured: specular relL2 on the public sets, 2 x 2 nodes, about 2x lower).
#if AL_RADIAL <= 4
real al_radial_z(AlDist d, real c, real s2) {
    if (!(c > AL_R(0.0))) return AL_R(1.0);
    return -al_expm1(AL_R(0.5) * (d.param + AL_R(2.0)) * al_log1p(-s2));
}
rvec3 al_radial_node(AlDist d, real z) {
    if (!(z < AL_R(1.0))) return rvec3(AL_R(0.0), AL_R(1.0), AL_R(1.0));
    real lc = al_log1p(-z) / (d.param + AL_R(2.0));
    return rvec3(al_exp(lc), sqrt(-al_expm1(AL_R(2.0) * lc)), AL_R(1.0));
}
#else
real al_radial_z(AlDist d, real c, real s2) {
    if (!(c > AL_R(0.0))) return AL_R(6.5);
    return min(sqrt(-AL_R(0.5) * (d.param + AL_R(2.0)) * al_log1p(-s2)), AL_R(6.5));
}

// (cos theta, sin theta, |dy/dz|) at the radial variable z >= 0 (al_radial_z).
rvec3 al_radial_node(AlDist d, real z) {
    real lc = -z * z / (d.param + AL_R(2.0));  // log cos(theta)
    return rvec3(al_exp(lc), sqrt(-al_expm1(AL_R(2.0) * lc)), AL_R(2.0) * z * al_exp(-z * z));
}
#endif
