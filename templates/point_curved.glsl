// The point-light baseline for curved lights (disk, sphere, ellipsoid): the
// ellipse record's centre (ellipse_record.glsl) as a point light with the solid
// angle of the cone over a disc of the ellipse's projected area facing p,
// 2 pi (1 - 1 / sqrt(1 + a)), a = area cos(theta_l) / (pi d^2): exact for a sphere
// and for a circular disc facing p, the point light's area cos / d^2 when the light
// is small. Error grows with the light's angular size; O(1), the cheapest method.
// Returns (diffuse, specular, 0, 0) (CONTRACT.md 2; no ndf or moment).

#ifdef AL_METHOD_POINT
vec4 al_shade(AlCase c) {
    if (c.params.z == AL_R(0.0)) return vec4(AL_R(0.0));
    rvec3 n = rvec3(c.n);
    // The centre is on +z at distance 1; a = |U x V|.z (pi cancels).
    real a = abs(cross(rvec3(c.verts[0]), rvec3(c.verts[1])).z);
    real q = sqrt(AL_R(1.0) + a);
    real solid_angle = AL_TWO_PI * a / (q * (AL_R(1.0) + q));  // 2 pi (1 - 1/q), no cancellation
    rvec3 w = rvec3(AL_R(0.0), AL_R(0.0), AL_R(1.0));
    real nw = max(n.z, AL_R(0.0));
#ifdef AL_DIST_PHONG
    real spec = al_phong_brdf(rvec3(c.r), w, real(c.params.x)) * nw * solid_angle;
#else
    real spec = al_microfacet_brdf_cos(n, rvec3(c.v), w, real(c.params.x), real(c.params.w)) *
                solid_angle;
#endif
    return vec4(nw / AL_PI * solid_angle, spec, AL_R(0.0), AL_R(0.0));
}
#endif
