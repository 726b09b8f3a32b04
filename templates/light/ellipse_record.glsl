// The record every curved light (disk, sphere, ellipsoid; CONTRACT.md 1) is shaded
// from: an ellipse whose cone from p is the light's solid angle (a disk is its own
// ellipse; a sphere or an ellipsoid is its silhouette, library/sphere.glsl and
// library/ellipsoid.glsl). Methods that integrate along the true boundary read it
// as it is; the polygon methods first turn it into the spinning proxy polygon
// (light/spin_polygon.glsl).

// The ellipse record (an AlCase, common/common.glsl), in the working precision: p at the
// origin, lengths divided by d = |rel| (rel = ellipse centre - p), the frame turned
// to put the centre on +z. verts[0] = U, verts[1] = V: conjugate semi-diameters,
// so that the boundary is centre + U cos(psi) + V sin(psi) (orthogonal for a disk,
// not for an ellipsoid's silhouette), V's sign chosen so that (U x V).centre > 0:
// with psi increasing, u x du/dpsi then points into the light's cone.
// params = (exponent or alpha, 0, 1 when a light is seen else 0, f0). `lit` false,
// a non-finite or zero d, or an ellipse seen edge-on give a record with params.z = 0,
// which every method shades as 0.
AlCase al_ellipse_record(ArealightSurface s, rvec3 rel, rvec3 U, rvec3 V, bool lit) {
    real d = length(rel);
    bool seen = lit && d > AL_R(0.0) && !isinf(d);
    if (!seen) d = AL_R(1.0);
    rvec3 z = seen ? rel / d : rvec3(AL_R(0.0), AL_R(0.0), AL_R(1.0));
    rvec3 x, y;
    al_tangent_frame(z, x, y);
    rvec3 n = normalize(rvec3(s.n));
    rvec3 v = normalize(rvec3(s.v));
    rvec3 r = normalize(AL_R(2.0) * dot(n, v) * n - v);
    rvec3 u1 = rvec3(dot(U, x), dot(U, y), dot(U, z)) / d;
    rvec3 v1 = rvec3(dot(V, x), dot(V, y), dot(V, z)) / d;
    // facing = area cos(theta_l) / d^2: the cone's opening. Below the rounding of
    // u1 and v1 in the working precision p lies on the light's plane as far as the
    // arithmetic can tell, and the cone has no interior: the contract's 0. Not the
    // inputs' fp32 rounding: the fp32 inputs are exact values, and a point 1e-8 off
    // the plane at the rim (or at a needle's tip) sees a lune of half the sky.
    real facing = cross(u1, v1).z;
    if (facing < AL_R(0.0)) v1 = -v1;
#if AL_PRECISION_FP64
    const real facing_min = AL_R(1e-13);
#else
    const real facing_min = AL_R(1e-7);
#endif
    seen = seen && abs(facing) > facing_min * length(u1) * length(v1) && !isinf(facing);
    AlCase c;
    c.n = rvec4(dot(n, x), dot(n, y), dot(n, z), AL_R(0.0));
    c.v = rvec4(dot(v, x), dot(v, y), dot(v, z), AL_R(0.0));
    c.r = rvec4(dot(r, x), dot(r, y), dot(r, z), AL_R(0.0));
    c.params = rvec4(real(s.param), AL_R(0.0), seen ? AL_R(1.0) : AL_R(0.0), real(s.f0));
    c.center = rvec4(AL_R(0.0), AL_R(0.0), AL_R(1.0), AL_R(0.0));
    for (int i = 0; i < AL_CASE_VERTS; ++i) c.verts[i] = rvec4(AL_R(0.0));
    if (seen) {
        c.verts[0] = rvec4(u1, AL_R(0.0));
        c.verts[1] = rvec4(v1, AL_R(0.0));
    }
    return c;
}
