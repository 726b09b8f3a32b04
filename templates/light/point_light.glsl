// A point light of solid angle omega in direction w (unit): the point-light baseline
// every speed ratio divides by (light/polygon_methods.glsl: the polygon's centre;
// light/point_curved.glsl: the ellipse's centre). Diffuse (n.w)+ omega / pi; specular the
// BRDF times the cosine at w, times omega. Domain: any unit w, omega >= 0. Error:
// that of the point approximation, growing with the light's angular size.
// Returns (diffuse, specular, 0, 0) (CONTRACT.md 2; no ndf or moment).
vec4 al_point_light(AlCase c, rvec3 n, rvec3 w, real solid_angle) {
    real nw = max(dot(n, w), AL_R(0.0));
#ifdef AL_DIST_PHONG
    real spec = al_phong_brdf(rvec3(c.r), w, real(c.params.x)) * nw * solid_angle;
#else
    real spec = al_microfacet_brdf_cos(n, rvec3(c.v), w, real(c.params.x), real(c.params.w)) *
                solid_angle;
#endif
    return vec4(nw / AL_PI * solid_angle, spec, AL_R(0.0), AL_R(0.0));
}
