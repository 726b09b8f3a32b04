// The vector form factor of a polygon light clipped by the horizon, as an accumulator
// of light/polygon.glsl's arc stream: F = (1/2 pi) sum over the arcs of the clipped
// boundary of arc_i m_i (Lambert's formula for the irradiance vector of a polygon, in
// Arvo 1995, "Applications of Irradiance Tensors to the Simulation of Non-Lambertian
// Phenomena"; the edge normals m_i as light/polygon.glsl orients them). F.n is the exact diffuse of
// CONTRACT.md 2 and |F| the form factor about F's own direction: the light's angular
// size for methods that need one (method/mrp.glsl). Domain: the arcs of a convex
// spherical polygon in one open hemisphere. Error: fp32 rounding of al_arc.

// Defined in light/polygon.glsl, which follows this file.
real al_arc(rvec3 a, rvec3 b, rvec3 m);

struct AlMoments {
    rvec3 F;  // 2 pi times the vector form factor so far
};

AlMoments al_vector_ff_begin() {
    AlMoments M;
    M.F = rvec3(AL_R(0.0));
    return M;
}

// light/polygon.glsl's accumulator interface; the lobe axis and exponent are not used.
void al_moments_arc(AL_INOUT(AlMoments) M, rvec3 a, rvec3 b, rvec3 m, rvec3 axis, rvec3 n,
                    real N) {
    M.F += al_arc(a, b, m) * m;
}
