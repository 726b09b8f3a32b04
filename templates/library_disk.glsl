// The library entry for disk lights (CONTRACT.md 1, 5): an ellipse with orthogonal
// semi-axes u, v, emitting towards u x v (both ways when two_sided). A point on its
// plane, or behind a one-sided disk, receives 0.

AlCase al_disk_record(ArealightSurface s, vec3 center, vec3 u, vec3 v, bool two_sided) {
    rvec3 rel = rvec3(center) - rvec3(s.p);
    rvec3 U = rvec3(u), V = rvec3(v);
    // > 0: p on the emitting side. Within 1e-6 of the inputs' magnitude (a few fp32
    // ulp) p is on the plane as far as the renderer's values can tell: 0 there, as
    // CONTRACT.md 1 asks, rather than a value decided by rounding.
    rvec3 UxV = cross(U, V);
    real side = -dot(UxV, rel);
    real on_plane = AL_R(1e-6) * length(UxV) * max(length(rvec3(center)), length(rvec3(s.p)));
    bool lit = side > on_plane || (two_sided && side < -on_plane);
    return al_light_record(al_ellipse_record(s, rel, U, V, lit));
}

// Every quantity the variant computes (diffuse, specular, then ndf or moment where
// it has one); the public function returns the first two. Never NaN, Inf or < 0.
vec4 al_disk_evaluate(ArealightSurface s, vec3 center, vec3 u, vec3 v, bool two_sided) {
    return al_clean(al_shade(al_disk_record(s, center, u, v, two_sided)));
}
