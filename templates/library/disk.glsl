// The library entry for disk lights (CONTRACT.md 1, 5): an ellipse with orthogonal
// semi-axes u, v, emitting towards u x v (both ways when two_sided). A point on its
// plane, or behind a one-sided disk, receives 0.

AlCase al_disk_record(ArealightSurface s, vec3 center, vec3 u, vec3 v, bool two_sided) {
    rvec3 rel = rvec3(center) - rvec3(s.p);
    rvec3 U = rvec3(u), V = rvec3(v);
    // > 0: p on the emitting side; exactly 0 on the plane (CONTRACT.md 1: nothing
    // then). No tolerance: a point a few fp32 ulp off the plane with its foot inside
    // the disk sees it fill half its sky (shared/validation's near-plane stress cases).
    real side = -dot(cross(U, V), rel);
    bool lit = side > AL_R(0.0) || (two_sided && side < AL_R(0.0));
    return al_light_record(al_ellipse_record(s, rel, U, V, lit));
}

// Every quantity the variant computes (diffuse, specular, then ndf or moment where
// it has one); the public function returns the first two. Never NaN, Inf or < 0.
vec4 al_disk_evaluate(ArealightSurface s, vec3 center, vec3 u, vec3 v, bool two_sided) {
    return al_clean(al_shade(al_disk_record(s, center, u, v, two_sided)));
}
