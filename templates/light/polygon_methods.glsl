// Shading of polygon lights (CONTRACT.md 2) by each method: the point-light
// baseline, or clipping (light/polygon.glsl) and the method's boundary moments.

#ifdef AL_METHOD_POINT
// Baseline: the polygon's centre as a point light of the same power, solid angle
// ~ area cos(theta_l) / d^2 (light/point_light.glsl). Error grows with the light's angular
// size; O(1), cheapest.
vec4 al_shade(AlCase c) {
    rvec3 n = rvec3(c.n);
    real side = al_polygon_side(c);
    if (side == AL_R(0.0)) return vec4(AL_R(0.0));
    int count = int(c.params.z);
    rvec3 area2 = rvec3(AL_R(0.0));
    rvec3 d0 = rvec3(c.verts[0]);
    for (int i = 2; i < AL_MAX_VERTS; ++i) {
        if (i >= count) break;
        area2 += cross(rvec3(c.verts[i - 1]) - d0, rvec3(c.verts[i]) - d0);
    }
    rvec3 centre = rvec3(c.center);
    real d2 = dot(centre, centre);
    rvec3 w = centre * inversesqrt(d2);
    real solid_angle = abs(dot(area2, w)) * AL_R(0.5) / d2;
    return al_point_light(c, n, w, solid_angle);
}
#endif

#if !defined(AL_DIST_PHONG) && !defined(AL_METHOD_POINT)
// Whether the mirror direction r lies in the light's solid angle, or within
// 1e-5 rad of its boundary: the inward normals of the unclipped edges, oriented
// as light/polygon.glsl walks them.
bool al_polygon_holds(AlCase c, real side, rvec3 r) {
    int count = int(c.params.z);
    rvec3 center = rvec3(c.center);
    bool inside = true;
    for (int i = 0; i < AL_MAX_VERTS; ++i) {
        if (i >= count) break;
        int j = i + 1 < count ? i + 1 : 0;
        int p = side > AL_R(0.0) ? j : i, q = side > AL_R(0.0) ? i : j;
        rvec3 dp = rvec3(c.verts[p]), dq = rvec3(c.verts[q]);
        rvec3 m = normalize(cross(center + dp, dq - dp));
        inside = inside && dot(r, m) >= AL_R(-1e-5);
    }
    return inside;
}

// Diffuse, specular and ndf (CONTRACT.md 2) for a microfacet distribution: the
// lit region (light clipped to the horizon of n, never to a lobe's hemisphere)
// streamed into the half-vector accumulator.
vec4 al_shade(AlCase c) {
    rvec3 n = normalize(rvec3(c.n));
    rvec3 v = normalize(rvec3(c.v));
    real side = al_polygon_side(c);
    if (side == AL_R(0.0)) return vec4(AL_R(0.0));
    real nv = dot(n, v);
    real param = real(c.params.x);
    rvec3 r = normalize(rvec3(c.r));
    bool direct = nv > AL_R(0.0) && al_polygon_holds(c, side, r);
    AlMoments M = al_mf_begin(n, v, r, param, real(c.params.w), direct);
    real diffuse = al_polygon_stream(c, side, n, n, false, param, M);
    rvec2 sn = al_mf_end(M);
    return vec4(diffuse, sn.x, sn.y, AL_R(0.0));
}
#endif

#ifdef AL_SPECULAR_SG
// Lecocq et al. 2016 section 7.1 (eq. 19-22): (r.w)^N (n.w) as one lobe mu (r_p.w)^n_p. Each
// cosine lobe maps to the spherical Gaussian of the same half width,
// lambda = ln 2 / (1 - 2^(-1/n)) (eq. 22 prints the denominator as 2^(1/n) - 1,
// which makes lambda negative); the Gaussians multiply exactly, and the product
// maps back by the inverse, n_p = -ln 2 / log1p(-ln 2 / lambda_p), with
// mu_p = (r.r_p)^N (n.r_p) so that the lobe is exact on its axis. n_p is kept in
// [1, 1e5] (lambda_p <= ln 2 has no half width: lobes nearly opposite). Costs a
// second clip and boundary pass about r_p. Error: the lobe-shape mismatch, largest
// for low N and r far from n (docs/methods.md, arealight report).
real al_specular_sg(AlCase c, real side, rvec3 r, rvec3 n, real N) {
    const real ln2 = AL_R(0.69314718055994530942);
    real l1 = ln2 / -al_expm1(-ln2 / N);
    real l2 = AL_R(2.0) * ln2;  // n = 1
    rvec3 pm = (l1 * r + l2 * n) / (l1 + l2);
    real len = length(pm);
    if (!(len > AL_R(1e-6))) return AL_R(0.0);
    rvec3 rp = pm / len;
    real lp = (l1 + l2) * len;
    real np = lp > AL_R(1.0001) * ln2 ? -ln2 / al_log1p(-ln2 / lp) : AL_R(1e5);
    np = clamp(np, AL_R(1.0), AL_R(1e5));
    real rr = dot(r, rp), nr = dot(n, rp);
    if (!(rr > AL_R(0.0)) || !(nr > AL_R(0.0))) return AL_R(0.0);
    // (r.rp)^N without the cancellation of 1 - r.rp (dist/phong.glsl): at N = 1e5 the
    // plain power lost 0.8% to fp32 rounding of the frame.
    real mu = al_phong_power(r, rp, N) * nr;
    // int mu (rp.w)^np = mu 2 pi moment / (np + 1); specular = (N+2)/(2 pi) times that.
    real unused;
    real moment = al_polygon_moments(c, side, n, rp, np, unused).y;
    return (N + AL_R(2.0)) / (np + AL_R(1.0)) * mu * moment;
}
#endif

#if defined(AL_DIST_PHONG) && !defined(AL_METHOD_POINT)
// Diffuse, specular and moment (CONTRACT.md 2) for Phong: clip by the horizon of n
// (diffuse, exact) and by r's hemisphere ((r.w)_+ vanishes beyond), streaming the
// arcs into the method's boundary moments (light/polygon.glsl).
vec4 al_shade(AlCase c) {
    rvec3 n = rvec3(c.n);
    real side = al_polygon_side(c);
    if (side == AL_R(0.0)) return vec4(AL_R(0.0));
    real N = real(c.params.x);
    rvec3 r = rvec3(c.r);
    real diffuse;
    rvec2 sm = al_polygon_moments(c, side, n, r, N, diffuse);
    real specular = sm.x;
#ifdef AL_SPECULAR_SG
    specular = al_specular_sg(c, side, r, n, N);
#endif
    return vec4(diffuse, specular, sm.y, AL_R(0.0));
}
#endif
