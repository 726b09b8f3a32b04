// Shading of curved lights (disk, sphere, ellipsoid; CONTRACT.md 2) by the exact
// boundary methods (method=exact): the light's ellipse record clipped in closed form
// and its boundary streamed into the method's accumulator (light/ellipse_clip.glsl). A
// record with params.z == 0 (p on a disk's plane, behind a one-sided disk, inside
// a sphere or ellipsoid) shades as 0. Domain: every N in [1, 1e5] and alpha in
// [1e-3, 1], views from normal to grazing, lights across the horizon, p at any
// distance outside the light.
//
// Error (lavapipe, through the library, arealight eval + shared/tools/score
// --floor 1e-3; the worst over distributions and lights of the p95 and max of
// diffuse, specular and moment or ndf): typical 6.2e-6 / 6.2e-6, horizon 1.3e-5 /
// 1.3e-5 (ggx disk ndf), glossy 5.0e-5 / 5.0e-5 (ggx disk), stress 2.1e-5 /
// 2.1e-5 with no bad value; on 240 harder seeded cases (scripts/gen_curved_cases.py
// 240 13: horizon, p near the light, r at the rim, grazing) 4.6e-5 / 1.2e-4, and
// on 96 with p 1e-2 to 1e-5 from the light (--kind near) 1.3e-4 / 1.3e-4. What
// exceeds 1e-5 there is the fp32 rounding of the uploaded case, which a sharp lobe
// or a nearby light amplifies: with the case in double (the templates as C++) the
// diffuse, moment and ndf are within 3e-6 of the oracle on all those sets but for
// two cases with p 1e-5 from a disk's rim (diffuse 9.4e-6, 9.8e-5), Phong's
// specular within 5.5e-6, and the microfacet specular adds the radial rule's error
// (method/exact_microfacet.glsl, AL_RADIAL = 16, as for polygons: up to 1e-5 at
// alpha ~ 0.8, 1e-4 at grazing views; radial 32 brings both to 1e-7). On 2001
// extreme cases (gen_curved_cases.py --kind extreme) p95 <= 5.8e-5 against the
// oracle of the fp32-rounded inputs; beyond 1e-4 there: views within 2e-7 of
// grazing, ndf at n.v < 0, p beside a needle's tip or 1e-8 off a disk's rim.
// Cost (arealight bench, lavapipe, typical disk cases): phong 24 us per case
// (57 270 x86-64 instructions), ggx 136 to 179 us, blinn 227 to 289 us, the same
// within those ranges from N = 1 to 1e5 and alpha = 1e-3 to 1 (a fixed bound on the
// nodes, light/ellipse_clip.glsl; which pieces a case needs varies).

#ifdef AL_DIST_PHONG
// Diffuse, specular and moment for Phong: D = light ∩ {n.w >= 0} ∩ {r.w >= 0}.
vec4 al_shade(AlCase c) {
    if (!(c.params.z > AL_R(0.0))) return vec4(0.0);
    rvec3 n = rvec3(c.n), r = rvec3(c.r);
    real N = real(c.params.x);
    AlMoments M = al_moments_begin(r);
    real diffuse = al_ellipse_stream(c, n, r, true, N, M);
    rvec2 sm = al_moments_end(M, r, n, N);
    return vec4(diffuse, sm.x, sm.y, AL_R(0.0));
}
#else
// Diffuse, specular and ndf for a microfacet distribution: the lit region light ∩
// {n.w >= 0} in half-vector space (method/exact_microfacet.glsl), in the direct form
// when r lies in the light's cone or within 1e-5 of it.
vec4 al_shade(AlCase c) {
    if (!(c.params.z > AL_R(0.0))) return vec4(0.0);
    rvec3 n = normalize(rvec3(c.n)), v = normalize(rvec3(c.v)), r = normalize(rvec3(c.r));
    real param = real(c.params.x);
    bool direct = dot(n, v) > AL_R(0.0) &&
                  al_ellipse_holds(rvec3(c.center), rvec3(c.verts[0]), rvec3(c.verts[1]), r,
                                   AL_R(1e-5));
    AlMoments M = al_mf_begin(n, v, r, param, real(c.params.w), direct);
    real diffuse = al_ellipse_stream(c, n, n, false, param, M);
    rvec2 sn = al_mf_end(M);
    return vec4(diffuse, sn.x, sn.y, AL_R(0.0));
}
#endif
