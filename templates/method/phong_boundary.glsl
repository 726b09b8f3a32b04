// The boundary accumulator of the edge-integral Phong methods (exact quadrature and
// the peak functions): each arc of the clipped polygon D adds its terms
// (al_lobe_edge of the method) and the azimuth it sweeps about the lobe axis r.
// light/polygon.glsl streams the arcs in; no per-vertex arrays.

struct AlMoments {
    rvec3 e1, e2;  // tangent frame of r: azimuth psi = atan2(u.e2, u.e1)
    rvec3 sums;    // sum of the arcs' al_lobe_edge sums
    real wraps;    // sweeps wrapped into (-pi, pi]: their count is the winding number
    real sweep_near, sweep_far, size_near, size_far;
};

AlMoments al_moments_begin(rvec3 r) {
    AlMoments M;
    al_tangent_frame(r, M.e1, M.e2);
    M.sums = rvec3(AL_R(0.0));
    M.wraps = AL_R(0.0);
    M.sweep_near = AL_R(0.0);
    M.sweep_far = AL_R(0.0);
    M.size_near = AL_R(0.0);
    M.size_far = AL_R(0.0);
    return M;
}

// One arc a -> b of D with inward unit normal m. Its sweep is the wrapped
// difference of its ends' azimuths (|sweep| < pi: D lies in r's hemisphere); an
// end shared by two arcs is the same value in both, so the sweeps telescope.
void al_moments_arc(AL_INOUT(AlMoments) M, rvec3 a, rvec3 b, rvec3 m, rvec3 r, rvec3 n,
                    real N) {
    real sweep = al_atan2(dot(b, M.e2), dot(b, M.e1)) - al_atan2(dot(a, M.e2), dot(a, M.e1));
    sweep = al_wrap_sweep(sweep, M.wraps);
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
    // The sweeps total -2 pi wraps (the winding number about r, 0 or 1 for a convex
    // D): so 2 pi winding - (near sweeps) equals the far sweeps. Take whichever group
    // cancels less.
    real winding = M.size_near <= M.size_far ? -AL_TWO_PI * M.wraps - M.sweep_near : M.sweep_far;
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
        real raw = al_atan2(dot(end, M.e2), dot(end, M.e1)) -
                   al_atan2(dot(start, M.e2), dot(start, M.e1));
        real sweep = al_wrap_sweep(raw, M.wraps);
        if (!near_part) {
            real wraps = floor((raw - e.w) / AL_TWO_PI + AL_R(0.5));
            M.wraps += wraps - (raw - sweep) / AL_TWO_PI;
            sweep = raw - AL_TWO_PI * wraps;
        }
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
