// The library entry for sphere lights (CONTRACT.md 1, 5). Seen from p at distance
// d > R, the sphere fills the cone of its silhouette circle, which lies in the
// polar plane of p: centre c + (p - c) R^2 / d^2, radius R sqrt(d^2 - R^2) / d.
// Relative to p the centre is at rho^2 (c - p) with rho^2 = 1 - R^2 / d^2, formed
// as (d - R)(d + R) / d^2 without cancellation. p inside or on the sphere gets 0.

AlCase al_sphere_record(ArealightSurface s, vec3 center, float radius) {
    rvec3 to_c = rvec3(center) - rvec3(s.p);
    real d = length(to_c), R = abs(real(radius));
    bool lit = d > R && R > AL_R(0.0);
    real rho2 = lit ? (d - R) * (d + R) / (d * d) : AL_R(0.0);
    rvec3 e1, e2;
    al_tangent_frame(lit ? to_c / d : rvec3(AL_R(0.0), AL_R(0.0), AL_R(1.0)), e1, e2);
    real radius_s = R * sqrt(rho2);
    return al_light_record(al_ellipse_record(s, rho2 * to_c, radius_s * e1, radius_s * e2, lit));
}

vec4 al_sphere_evaluate(ArealightSurface s, vec3 center, float radius) {
    return al_clean(al_shade(al_sphere_record(s, center, radius)));
}
