// The point-light baseline for curved lights (disk, sphere, ellipsoid): the
// ellipse record's centre (light/ellipse_record.glsl) as a point light with the solid
// angle of the cone over a disc of the ellipse's projected area facing p,
// 2 pi (1 - 1 / sqrt(1 + a)), a = area cos(theta_l) / (pi d^2): exact for a sphere
// and for a circular disc facing p, the point light's area cos / d^2 when the light
// is small (light/point_light.glsl). Error grows with the light's angular size; O(1), the
// cheapest method.

#ifdef AL_METHOD_POINT
vec4 al_shade(AlCase c) {
    if (c.params.z == AL_R(0.0)) return vec4(AL_R(0.0));
    rvec3 n = rvec3(c.n);
    // The centre is on +z at distance 1; a = |U x V|.z (pi cancels).
    real a = abs(cross(rvec3(c.verts[0]), rvec3(c.verts[1])).z);
    real q = sqrt(AL_R(1.0) + a);
    real solid_angle = AL_TWO_PI * a / (q * (AL_R(1.0) + q));  // 2 pi (1 - 1/q), no cancellation
    return al_point_light(c, n, rvec3(AL_R(0.0), AL_R(0.0), AL_R(1.0)), solid_angle);
}
#endif
