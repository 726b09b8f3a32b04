// The library entry for polygon lights (CONTRACT.md 5): the renderer's fp32 values,
// in any consistent space, turned into the record the methods work on, in the
// variant's precision. A renderer's host never sees the shading point, so every
// per-point step happens here.

// The record of common/common.glsl: p moved to the origin, lengths divided by the distance
// d to the vertices' mean, the frame turned to put that mean on +z (directions near
// the light then differ from the pole in small components that keep their relative
// precision), n, v and r unit, vertices as offsets from the mean. count is cut to
// AL_MAX_VERTS. Fewer than 3 vertices, p at the mean or a non-finite d give a record
// with no vertices, which every method shades as 0.
AlCase al_polygon_record(ArealightSurface s, vec3 vertices[8], int count, bool two_sided) {
    int m = clamp(count, 0, AL_MAX_VERTS);
    rvec3 centre = rvec3(AL_R(0.0));
    for (int i = 0; i < AL_MAX_VERTS; ++i) {
        if (i >= m) break;
        centre += rvec3(vertices[i]);
    }
    centre /= real(max(m, 1));
    rvec3 rel = centre - rvec3(s.p);
    real d = length(rel);
    if (!(d > AL_R(0.0)) || isinf(d) || m < 3) {
        m = 0;
        d = AL_R(1.0);
    }
    rvec3 z = m == 0 ? rvec3(AL_R(0.0), AL_R(0.0), AL_R(1.0)) : rel / d;
    rvec3 x, y;
    al_tangent_frame(z, x, y);
    rvec3 n = normalize(rvec3(s.n));
    rvec3 v = normalize(rvec3(s.v));
    rvec3 r = normalize(AL_R(2.0) * dot(n, v) * n - v);
    AlCase c;
    c.n = rvec4(dot(n, x), dot(n, y), dot(n, z), AL_R(0.0));
    c.v = rvec4(dot(v, x), dot(v, y), dot(v, z), AL_R(0.0));
    c.r = rvec4(dot(r, x), dot(r, y), dot(r, z), AL_R(0.0));
    c.params = rvec4(real(s.param), two_sided ? AL_R(1.0) : AL_R(0.0), real(m), real(s.f0));
    c.center = rvec4(AL_R(0.0), AL_R(0.0), AL_R(1.0), AL_R(0.0));
    for (int i = 0; i < AL_MAX_VERTS; ++i) {
        rvec3 e = i < m ? (rvec3(vertices[i]) - centre) / d : rvec3(AL_R(0.0));
        c.verts[i] = rvec4(dot(e, x), dot(e, y), dot(e, z), AL_R(0.0));
    }
    return c;
}

// Every quantity the variant computes (diffuse, specular, then ndf or moment where
// it has one): the public function returns the first two; the validation kernel
// also reads the others. No NaN, infinity or negative value leaves (al_clean).
vec4 al_polygon_evaluate(ArealightSurface s, vec3 vertices[8], int count, bool two_sided) {
    return al_clean(al_shade(al_polygon_record(s, vertices, count, two_sided)));
}
