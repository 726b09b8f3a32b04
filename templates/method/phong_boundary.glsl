// The boundary accumulator of the edge-integral Phong methods (exact quadrature and
// the peak functions): each arc of the clipped polygon D adds its terms
// (al_lobe_edge of the method) and the azimuth it sweeps about the lobe axis r.
// light/polygon.glsl streams the arcs in; no per-vertex arrays.

struct AlMoments {
    rvec3 sums;    // sum of the arcs' al_lobe_edge sums
    real sweep_near, sweep_far, size_near, size_far;
};

AlMoments al_moments_begin(rvec3 r) {
    AlMoments M;
    M.sums = rvec3(AL_R(0.0));
    M.sweep_near = AL_R(0.0);
    M.sweep_far = AL_R(0.0);
    M.size_near = AL_R(0.0);
    M.size_far = AL_R(0.0);
    return M;
}

// The azimuth swept about r from a to b, in (-pi, pi]: the angle between r x a and r x b
// (their dot product is a.b - (r.a)(r.b), the ends' projections' on r's plane, and
// (r x a).b = r.(a x b) their cross product along r). Formed from the two cross products,
// as a frame's components were, it loses no digits when a and b lie near r (a.b - (r.a)
// (r.b) lost ~1 / |r x a|^2 of them: phong exact nodes=6 fp32 glossy 9.5e-5 -> 1.7e-4).
// One atan2 an arc where the ends' azimuths in a tangent frame took two (phong lorentz
// 7 403 -> 7 239 cycles a wave, navi21). A closed boundary's sweeps total 2 pi times its
// winding number about r to a few ulp of pi each (al_moments_end rounds that total).
real al_sweep_about(rvec3 r, rvec3 a, rvec3 b) {
    rvec3 ra = cross(r, a), rb = cross(r, b);
    return al_atan2(dot(ra, b), dot(ra, rb));
}

// One arc a -> b of D with inward unit normal m (|sweep| < pi: D lies in r's hemisphere).
void al_moments_arc(AL_INOUT(AlMoments) M, rvec3 a, rvec3 b, rvec3 m, rvec3 r, rvec3 n,
                    real N) {
    real sweep = al_sweep_about(r, a, b);
    AlLobeEdge e = al_lobe_edge(a, b, m, r, n, N);
    M.sums += e.sums;
    if (e.near_edge) {
        M.sweep_near += sweep;
        M.size_near += abs(sweep);
    } else {
        M.sweep_far += sweep;
        M.size_far += abs(sweep);
    }
}

// Specular and moment (CONTRACT.md 2) of (r.w)^N over D, with n the normal of the
// double-axis moment: x = (N+2)/(2 pi) int (r.w)^N (n.w), y = (N+1)/(2 pi) int (r.w)^N.
// Domain: real N in [1, 1e5]; error that of the method's edge integrals.
rvec2 al_moments_end(AlMoments M, rvec3 r, rvec3 n, real N) {
    // The winding number about r is 0 or 1 for a convex D (method/phong_edge.glsl).
    real winding = al_winding(M.sweep_near + M.sweep_far, M.sweep_near, M.sweep_far,
                              M.size_near, M.size_far);
    real moment = (winding - M.sums.x) / AL_TWO_PI;
    real specular = (dot(r, n) * (winding - M.sums.y) + M.sums.z) / AL_TWO_PI;
    return rvec2(specular, moment);
}

#if defined(AL_LIGHT_CURVED) && defined(AL_METHOD_EXACT)
// One part [psi0, psi1] of a curved light's boundary in D from a to b (the same
// vectors as the neighbouring pieces' ends, so that the sweeps telescope;
// light/ellipse_clip.glsl), in the sub-parts of al_conic_plan (lobe width 2 / sqrt(N)).
// A sub-part may sweep more than pi about r: its sweep is the ends' azimuth
// difference plus the multiple of 2 pi nearest the rule's estimate. Only far
// sub-parts' multiples count: al_moments_end's two forms both equal the far ones'
// total sweep whatever multiple a near one is given (near ones keep the wrapped
// difference), and away from r (far) the estimate is accurate.
void al_moments_conic(AL_INOUT(AlMoments) M, rvec3 C, rvec3 U, rvec3 V, real psi0, real psi1,
                      rvec3 a, rvec3 b, rvec3 r, rvec3 n, real N) {
    AlConicPlan plan = al_conic_plan(C, U, V, psi0, psi1, r, rvec3(AL_R(0.0)),
                                     AL_R(2.0) * inversesqrt(N), true);
    rvec3 start = a;
    for (int k = 0; k < 4; ++k) {
        if (k >= plan.count) break;
        rvec4 sub = plan.sub[k];
        rvec3 end = k + 1 == plan.count ? b : normalize(al_conic_point(C, U, V, al_cis(sub.y)));
        bool near_part;
        rvec4 e = al_lobe_conic(C, U, V, sub, r, n, N, near_part);
        real sweep = al_sweep_about(r, start, end);
        if (!near_part) sweep -= AL_TWO_PI * floor((sweep - e.w) / AL_TWO_PI + AL_R(0.5));
        M.sums += rvec3(e);
        if (near_part) {
            M.sweep_near += sweep;
            M.size_near += abs(sweep);
        } else {
            M.sweep_far += sweep;
            M.size_far += abs(sweep);
        }
        start = end;
    }
}
#endif
