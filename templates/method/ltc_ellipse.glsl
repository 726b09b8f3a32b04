// Linearly transformed cosines for curved lights (Heitz & Hill 2017, "Real-Time Line-
// and Disk-Light Shading with Linearly Transformed Cosines"): the light's ellipse record
// (light/ellipse_record.glsl; a sphere is its silhouette disc facing p, an ellipsoid its
// silhouette ellipse) goes through the polygon LTC's Minv (method/ltc.glsl: same tables,
// lookup and magnitude). A linear map takes an ellipse with conjugate semi-diameters
// U, V about C to the ellipse with conjugate semi-diameters Minv U, Minv V about Minv C,
// so the transformed light is an ellipse again, and its cosine integral is the form
// factor of its cone (light/ellipse_cone.glsl), in closed form: clipped by the horizon exactly
// (horizon=clip) or through Hill 2016's sphere of the same vector form factor
// (horizon=proxy, the paper's choice). diffuse is the same closed form with M = identity,
// clipped exactly. Domain: CONTRACT.md 2 for disks, spheres and ellipsoids (n.v <= 0
// gives specular 0; a record without light gives 0). Error: the LTC fit's (docs/ltc.md,
// `arealight report`), plus light/ellipse_cone.glsl's fp32 rounding.

#ifdef AL_LIGHT_CURVED
// The LTC-space form factor of a transformed ellipse's cone k (vector form factor
// vector_ff): the proxy sphere's, or the one clipped exactly by the LTC's z >= 0 and by
// n's horizon, whose image is the plane with normal nu (method/ltc.glsl's
// al_ltc_horizon_arc: the integrand is 0 below n's horizon, and the tables are
// normalised to the LTC's mass above it; docs/ltc.md, "True horizon").
real al_ltc_ellipse_form(AlEllipseCone k, hvec3 vector_ff, rvec3 nu) {
#ifdef AL_HORIZON_PROXY
    return al_ltc_proxy_form(vector_ff);
#else
    rvec3 z = rvec3(AL_R(0.0), AL_R(0.0), AL_R(1.0));
    return al_ellipse_clipped_ff2(k, z, z, nu);
#endif
}

#ifdef AL_DIST_PHONG
// A bound on Phong's specular over the ellipse (C, U, V) from its diffuse: with f =
// (N+2)/(2 pi) (r.w)+^N (CONTRACT.md 2), specular <= (N+2)/2 x^N diffuse, x the largest r.w
// over the light, here over the disc of radius a (the ellipse's semi-major axis, from the
// conjugate pair U, V) within its plane about C: the smaller of the ball's cone (sin beta =
// a / |C|) and, with s the sine of C's angle from the plane's normal, tan beta =
// a / (|C| - a s) (exact for a disc facing p, as a sphere's record is). The two-lobe
// LTC's tail is too heavy for a Gaussian lobe: a light far off the lobe's axis got up to
// 250x its specular (public horizon sphere 067: 9.1e-4 against 3.6e-6; docs/ltc.md,
// "Phong's tail bound"). Every light is
// within the bound, so the clamp never moves an estimate away from the truth. Domain: any
// record with |C| > 0; a light whose ball holds p, or meets r, has no bound (x = 1 still
// holds: the min is then with (N+2)/2 diffuse).
real al_ltc_phong_tail_bound(AlCase c, rvec3 C, rvec3 U, rvec3 V, real diffuse) {
    real uu = dot(U, U), vv = dot(V, V), uv = dot(U, V);
    real h = AL_R(0.5) * (uu - vv);
    real a2 = AL_R(0.5) * (uu + vv) + sqrt(h * h + uv * uv);
    real cc = dot(C, C);
    rvec3 r = normalize(rvec3(c.r));
    rvec3 W = cross(U, V);
    real cw = dot(C, W);
    real s = sqrt(max(AL_R(1.0) - cw * cw / (cc * dot(W, W)), AL_R(0.0)));
    real t = sqrt(cc) - sqrt(a2) * s;
    // r.w over the light: cos(max(theta - beta, 0)), theta r's angle from C.
    real sb2 = t > AL_R(0.0) ? min(a2 / cc, a2 / (t * t + a2)) : a2 / cc;
    real x = AL_R(1.0);
    if (sb2 < AL_R(1.0)) {
        real cb = sqrt(AL_R(1.0) - sb2), sb = sqrt(sb2);
        real ct = dot(r, C) * inversesqrt(cc), st = sqrt(max(AL_R(1.0) - ct * ct, AL_R(0.0)));
        if (ct < cb) x = max(ct * cb + st * sb, AL_R(0.0));
    }
    // x raised by 8 fp32 ulps: its rounding, raised to the power N (up to 1e4: 5e-4
    // relative), must not put the bound below a small light's true value.
    real n = real(c.params.x);
    x = min(x * AL_R(1.0000005), AL_R(1.0));
    return AL_R(0.5) * (n + AL_R(2.0)) * pow(x, n) * diffuse;
}
#endif

// Diffuse and specular (CONTRACT.md 2; no ndf or moment).
vec4 al_shade(AlCase c) {
    if (c.params.z == AL_R(0.0)) return vec4(AL_R(0.0));
    rvec3 C = rvec3(c.center), U = rvec3(c.verts[0]), V = rvec3(c.verts[1]);
    AlLtc L = al_ltc_lookup(c);
    real diffuse = al_ellipse_clipped_ff(al_ellipse_cone(C, U, V), L.n);
    real specular = AL_R(0.0);
    if (L.nv > AL_R(0.0)) {
#ifdef AL_DIST_PHONG
        // Formed first, so that one value, not r, stays live through the ellipse's cones.
        real bound = al_ltc_phong_tail_bound(c, C, U, V, diffuse);
#endif
        rvec3 Ct = al_ltc_image(L, C), Ut = al_ltc_image(L, U), Vt = al_ltc_image(L, V);
        // Minv keeps the orientation where det Minv = c (a - b d) > 0; V's sign restores
        // light/ellipse_cone.glsl's (U x V).C > 0 otherwise (the ellipse is the same).
        if (dot(cross(Ut, Vt), Ct) < AL_R(0.0)) Vt = -Vt;
        AlEllipseCone k = al_ellipse_cone(Ct, Ut, Vt);
        hvec3 vector_ff = hvec3(AL_TWO_PI * k.ff * k.axis);
        real form = al_ltc_ellipse_form(k, vector_ff, al_ltc_horizon_normal(L, AL_R(1.0)));
#ifdef AL_LTC_TWO_LOBES
        // The second lobe (method/ltc.glsl): x and y over s, a map of positive determinant.
        AlEllipseCone k2 = al_ellipse_cone(Ct * AL_LTC_SECOND, Ut * AL_LTC_SECOND, Vt * AL_LTC_SECOND);
        form += L.amp.z * al_ltc_ellipse_form(k2, hvec3(AL_TWO_PI * k2.ff * k2.axis),
                                              al_ltc_horizon_normal(L, AL_LTC_SECOND.x));
#endif
        specular = al_ltc_specular(L, form, vector_ff, real(c.params.w));
#ifdef AL_DIST_PHONG
        specular = min(specular, bound);
#endif
    }
    return vec4(diffuse, specular, AL_R(0.0), AL_R(0.0));
}
#endif
