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

// Diffuse and specular (CONTRACT.md 2; no ndf or moment).
vec4 al_shade(AlCase c) {
    if (c.params.z == AL_R(0.0)) return vec4(AL_R(0.0));
    rvec3 C = rvec3(c.center), U = rvec3(c.verts[0]), V = rvec3(c.verts[1]);
    AlLtc L = al_ltc_lookup(c);
    real diffuse = al_ellipse_clipped_ff(al_ellipse_cone(C, U, V), L.n);
    real specular = AL_R(0.0);
    if (L.nv > AL_R(0.0)) {
        rvec3 Ct = rvec3(dot(C, L.row0), dot(C, L.row1), dot(C, L.row2));
        rvec3 Ut = rvec3(dot(U, L.row0), dot(U, L.row1), dot(U, L.row2));
        rvec3 Vt = rvec3(dot(V, L.row0), dot(V, L.row1), dot(V, L.row2));
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
    }
    return vec4(diffuse, specular, AL_R(0.0), AL_R(0.0));
}
#endif
