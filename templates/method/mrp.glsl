// Representative-point shading: the cheap anchors real-time engines ship, with their
// real error. Specular is the BRDF times the cosine at one direction l* of the light,
// as a point light (light/point_light.glsl) of the light's solid angle times an energy
// normalisation; diffuse is exact, in closed form.
//
// Specular, three choices:
// - The lobe's representative direction d: r for Phong; for the microfacets the
//   dominant direction of the BRDF-cosine lobe, normalize(mix(n, r, s (sqrt(s) + a))),
//   s = 1 - a (Lagarde & de Rousiers 2014, "Moving Frostbite to Physically Based
//   Rendering", the specular dominant direction), which leans towards n as the lobe
//   widens (Smith's G2 and the cosine cut its far side).
// - l*, the light's point nearest that direction's ray: for a sphere the point of the
//   sphere closest to the ray (Karis 2013, "Real Shading in Unreal Engine 4", sphere
//   lights); for a polygon, a disk and an ellipsoid's silhouette ellipse the ray's hit
//   on the light's plane clamped into the light (Drobot 2014, GPU Pro 5, "Physically
//   Based Area Lights", the most representative point): a polygon's nearest point, an
//   ellipse radially in its own coordinates. A ray that misses the plane takes the
//   plane's far point in d's direction, so that l* moves continuously as the ray tilts
//   off the light.
// - The energy: f(l*, v) (n.l*) omega (a / a')^2, a' = min(a + sin(sigma) / 2, 1): Karis
//   2013's sphere normalisation (sourceRadius / distance = sin(sigma)), which widens
//   the lobe by the light's angular radius seen through the half vector. a is the
//   lobe's width as a microfacet alpha: AlDist's width for the microfacets (Blinn's
//   sqrt(2 / (N + 2)), CONTRACT.md 2); for Phong sqrt(2 / (4 N + 2)), since (r.w)^N
//   about r is near its peak Blinn's lobe of exponent 4 N (half-vector angles are half
//   as large). The light's size comes from its form factor |F| = sin^2(sigma) and
//   omega = 2 pi (1 - cos(sigma)): exact for a sphere (a circular cone), the cone of
//   the same form factor for every other light. Polygons take the horizon-clipped F
//   that the diffuse pass forms anyway; curved lights the unclipped |F| of their cone.
//
// Diffuse, exact (fp32 rounding only): a polygon's vector form factor clipped by the
// horizon (Lambert's formula; common/vector_form_factor.glsl over light/polygon.glsl's arc stream);
// a disk's, sphere's or ellipsoid's the clipped form factor of the ellipse record's
// cone (light/ellipse_cone.glsl), which for a sphere is Snyder's closed form (Snyder 1996,
// "Area Light Sources for Real-Time Graphics"; tests/test_mrp.cpp checks it against it).
//
// ndf and moment (CONTRACT.md 2) are not computed (the family's second_quantity is
// false, as for method=point and method=ltc): a renderer consumes diffuse and specular
// (CONTRACT.md 5), and the representative point would give ndf as the same one sample
// with other weights (D / (4 h.v) for D G2 / (4 n.v)), so its error would repeat the
// specular's rather than measure anything of its own.
//
// Domain: every case of CONTRACT.md 2. A light behind p, edge-on, or around p gives 0;
// microfacet specular is 0 for n.v <= 0 (al_microfacet_brdf_cos). No tangent frame is
// built: v = n exactly is an ordinary case. Error (public sets together, specular
// relL2): Phong 0.26-0.34 for every light; the microfacets 0.85-40, often worse than
// the point light: a narrow lobe inside a light comes out as G2 / (n.v) instead of about
// G2 (the widening ignores the half-vector map's Jacobian 4 h.v), so grazing views are
// up to 100x too bright. Diffuse relL2 <= 2.7e-6. Cost: one pass over the edges plus one
// BRDF evaluation; lavapipe time 1.5-5x the point light's, x86-64 2.2-3.3x (docs/mrp.md,
// `arealight report`). GPU cost (navi21, `arealight gpu-cost`, the validation kernel,
// polygon): 2 027-2 195, 3.8-4.4x the point light's (72 VGPRs).

// The lobe: its representative direction (unit) and its width as a microfacet alpha.
struct AlMrpLobe {
    rvec3 dir;
    real alpha;
};

AlMrpLobe al_mrp_lobe(AlCase c, rvec3 n) {
    AlMrpLobe L;
    rvec3 r = normalize(rvec3(c.r));
    real param = real(c.params.x);
#ifdef AL_DIST_PHONG
    L.dir = r;
    L.alpha = sqrt(AL_R(2.0) / (AL_R(4.0) * param + AL_R(2.0)));
#else
    L.alpha = min(al_dist_make(param).width, AL_R(1.0));
    real s = AL_R(1.0) - L.alpha;
    rvec3 d = mix(n, r, s * (sqrt(s) + L.alpha));
    // n and r unit: d vanishes only for r = -n (v = -n, where nothing is seen).
    real len = length(d);
    L.dir = len > AL_R(1e-6) ? d / len : n;
#endif
    return L;
}

// The light as a point light in the unit direction l with the solid angle of the cone of
// form factor ff = sin^2(sigma), times Karis's (a / a')^2.
real al_mrp_specular(AlCase c, rvec3 n, rvec3 l, real ff, real alpha) {
    real f = clamp(ff, AL_R(0.0), AL_R(1.0));
    real omega = AL_TWO_PI * f / (AL_R(1.0) + sqrt(AL_R(1.0) - f));  // 2 pi (1 - cos), no cancellation
    real e = alpha / min(alpha + AL_R(0.5) * sqrt(f), AL_R(1.0));
    return al_point_light(c, n, l, omega * e * e).y;
}

// The point of a plane (unit normal N away from p, at distance h > 0, C a point of it)
// where the ray along the unit d meets it, as an offset from C in the plane; a ray that
// misses, or meets it beyond `far` from p, gives the plane's point `far` away in d's
// direction (far: well outside the light, so that clamping it finds the light's
// boundary in that direction).
rvec3 al_mrp_plane_hit(rvec3 C, rvec3 N, real h, rvec3 d, real far) {
    real dn = dot(d, N);
    rvec3 dt = d - dn * N;
    real t = dn * far > h ? h / dn : far;
    return t * dt - (C - h * N);
}

#ifndef AL_LIGHT_CURVED
// Drobot 2014's most representative point of a polygon for the direction d: the ray's
// hit on the plane (al_mrp_plane_hit), or the polygon's point nearest it where the hit
// is outside (the nearest point of each edge). Domain: a record with side != 0.
rvec3 al_mrp_polygon_point(AlCase c, rvec3 d) {
    int count = int(c.params.z);
    rvec3 C = rvec3(c.center);
    rvec3 d0 = rvec3(c.verts[0]);
    rvec3 area2 = rvec3(AL_R(0.0));
    real ext = AL_R(0.0);
    for (int i = 1; i < AL_MAX_VERTS; ++i) {
        if (i >= count) break;
        rvec3 di = rvec3(c.verts[i]);
        if (i >= 2) area2 += cross(rvec3(c.verts[i - 1]) - d0, di - d0);
        ext = max(ext, length(di - d0));
    }
    rvec3 N = normalize(area2);
    real orient = AL_R(1.0);
    real h = dot(N, C);
    if (h < AL_R(0.0)) {
        N = -N;
        h = -h;
        orient = -AL_R(1.0);
    }
    real far = AL_R(1e3) * (ext + length(C - h * N));
    rvec3 q = al_mrp_plane_hit(C, N, h, d, far);
    bool inside = true;
    rvec3 best = q;
    real best_d2 = -AL_R(1.0);
    for (int i = 0; i < AL_MAX_VERTS; ++i) {
        if (i >= count) break;
        int j = i + 1 < count ? i + 1 : 0;
        rvec3 a = rvec3(c.verts[i]), e = rvec3(c.verts[j]) - a;
        inside = inside && orient * dot(cross(e, q - a), N) >= AL_R(0.0);
        real t = clamp(dot(q - a, e) / max(dot(e, e), AL_R(1e-30)), AL_R(0.0), AL_R(1.0));
        rvec3 x = a + t * e;
        real d2 = dot(q - x, q - x);
        if (best_d2 < AL_R(0.0) || d2 < best_d2) {
            best_d2 = d2;
            best = x;
        }
    }
    return C + (inside ? q : best);
}

// Diffuse and specular (CONTRACT.md 2; no ndf or moment).
vec4 al_shade(AlCase c) {
    real side = al_polygon_side(c);
    if (side == AL_R(0.0)) return vec4(AL_R(0.0));
    rvec3 n = normalize(rvec3(c.n));
    AlMoments M = al_vector_ff_begin();
    al_polygon_stream(c, side, n, n, false, AL_R(0.0), M);
    rvec3 F = M.F / AL_TWO_PI;
    real diffuse = max(dot(F, n), AL_R(0.0));
    AlMrpLobe L = al_mrp_lobe(c, n);
    rvec3 l = normalize(al_mrp_polygon_point(c, L.dir));
    real specular = al_mrp_specular(c, n, l, length(F), L.alpha);
    return vec4(diffuse, specular, AL_R(0.0), AL_R(0.0));
}

#else
// The representative point of the ellipse record's light for the direction d. Sphere:
// Karis 2013's point of the sphere closest to the ray, the sphere rebuilt from its
// silhouette record (library/sphere.glsl: tan(sigma) = |U|, centre (1 + tan^2) C, radius
// tan sqrt(1 + tan^2)); a ray through the sphere keeps its own direction. Disk and
// ellipsoid: Drobot 2014's hit on the ellipse's plane, pulled radially onto the ellipse
// in the coordinates of its conjugate semi-diameters U, V where it falls outside.
rvec3 al_mrp_ellipse_point(AlCase c, rvec3 d) {
    rvec3 C = rvec3(c.center), U = rvec3(c.verts[0]), V = rvec3(c.verts[1]);
#ifdef AL_LIGHT_SPHERE
    real t2 = dot(U, U);
    rvec3 S = (AL_R(1.0) + t2) * C;
    real R = sqrt(t2 * (AL_R(1.0) + t2));
    rvec3 to_ray = dot(S, d) * d - S;
    real g = length(to_ray);
    return g > R ? S + to_ray * (R / g) : S + to_ray;
#else
    rvec3 uv = cross(U, V);
    real area = length(uv);
    rvec3 N = uv / area;
    real h = dot(N, C);  // > 0: the record's (U x V).C > 0
    real far = AL_R(1e3) * (max(length(U), length(V)) + length(C - h * N));
    rvec3 q = al_mrp_plane_hit(C, N, h, d, far);
    real x = dot(q, cross(V, N)) / area, y = dot(q, cross(N, U)) / area;
    real rho2 = x * x + y * y;
    real k = rho2 > AL_R(1.0) ? inversesqrt(rho2) : AL_R(1.0);
    return C + k * (x * U + y * V);
#endif
}

// Diffuse and specular (CONTRACT.md 2; no ndf or moment).
vec4 al_shade(AlCase c) {
    if (c.params.z == AL_R(0.0)) return vec4(AL_R(0.0));
    rvec3 n = normalize(rvec3(c.n));
    AlEllipseCone k = al_ellipse_cone(rvec3(c.center), rvec3(c.verts[0]), rvec3(c.verts[1]));
    real diffuse = al_ellipse_clipped_ff(k, n);
    AlMrpLobe L = al_mrp_lobe(c, n);
    rvec3 l = normalize(al_mrp_ellipse_point(c, L.dir));
    real specular = al_mrp_specular(c, n, l, k.ff, L.alpha);
    return vec4(diffuse, specular, AL_R(0.0), AL_R(0.0));
}
#endif
