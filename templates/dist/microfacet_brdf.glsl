// The microfacet BRDF times cosine at one direction, for the point-light baseline.

// f(w, v) (n.w) of CONTRACT.md 2 at unit w: D(h) G2(w, v) F(h.v) / (4 n.v); 0 when
// n.v <= 0 or n.w <= 0. Error: that of the distribution's al_ndf and al_smith_lambda.
real al_microfacet_brdf_cos(rvec3 n, rvec3 v, rvec3 w, real param, real f0) {
    n = normalize(n);
    v = normalize(v);
    real nv = dot(n, v), nw = dot(n, w);
    if (!(nv > AL_R(0.0)) || !(nw > AL_R(0.0))) return AL_R(0.0);
    AlDist d = al_dist_make(param);
    rvec3 h = normalize(w + v);
    rvec3 nxh = cross(n, h), nxw = cross(n, w), nxv = cross(n, v);
    real D = al_ndf(d, dot(n, h), dot(nxh, nxh));
    real g2 = al_smith_g2(al_smith_lambda(d, nw, dot(nxw, nxw)),
                          al_smith_lambda(d, nv, dot(nxv, nxv)));
    return D * g2 * al_schlick(f0, dot(h, v)) / (AL_R(4.0) * nv);
}
