// The per-arc geometry every boundary-integral Phong method shares (exact and peak
// functions): the great circle of an arc about the lobe axis r, and the choice
// between the near and far forms of its edge integral. Notation of
// method/exact_phong.glsl: m the arc's inward unit normal, s = |r.m|,
// c = sqrt(1 - s^2), tau the arc angle from the foot of r, x = r.u = c cos(tau).

// One arc's share of the boundary sums. The azimuth swept about r is not here: the
// drivers form it (method/phong_boundary.glsl, method/peak_microfacet.glsl).
struct AlLobeEdge {
    rvec3 sums;  // far: (r.m) T_(N+1), (r.m) T_N; near: -(r.m) int G_(N+1), -(r.m) int G_N;
                 // z: (n.m) int x^N dtau. Then T_k = [near] sweep + sums.
    bool near_edge;
};

// 2 pi times the winding number of a closed boundary about the axis (r, or n for the h-polygon)
// from its arcs' sweeps: total, their sum, is 2 pi times a whole number to a few ulp of pi an
// arc, so that multiple less the near arcs' sweeps is the far arcs', and the group that cancels
// less is taken. But with the axis exactly on a vertex (r through a corner of the light to the
// bit; h = n at a vertex of the h-polygon) the arcs at it sweep rounding's angle (atan2(0, 0) =
// 0 about r), and the total is the corner's angle, not a whole turn. Those arcs are near ones
// (x = 1 at the axis) and their terms vanish with r.m, so there the far sweeps alone are the
// winding: the corner's angle, the moment angle / (2 pi) of a narrow lobe (rounded to a whole
// turn it had been 0: Phong moment 3.7e-7 for 0.25; microfacet ndf 0 to 4x the oracle's).
real al_winding(real total, real sweep_near, real sweep_far, real size_near, real size_far) {
    real turns = floor(total / AL_TWO_PI + AL_R(0.5));
    bool whole = abs(total - AL_TWO_PI * turns) < AL_R(1e-3);
    return whole && size_near <= size_far ? AL_TWO_PI * turns - sweep_near : sweep_far;
}

struct AlEdgeFrame {
    real rm, s, c;   // r.m, |r.m|, sqrt(1 - s^2)
    real ag, af;     // a.g, a.f: tau_a = atan(ag, af)
    real bg, bf;     // the same for b
    real xa, xb;     // x = r.u at a and b
    bool far_edge;
};

// log of x's maximum on the arc of E (its fields ag, bg, c, xa, xb), independent of the
// exponent: the microfacet peak methods (method/peak_microfacet.glsl) take it once per arc
// and test each lobe's exponent against it.
real al_arc_log_x_max(AlEdgeFrame E) {
    real x_max = E.ag <= AL_R(0.0) && E.bg >= AL_R(0.0) ? E.c : max(E.xa, E.xb);
    return al_log(max(x_max, AL_R(1e-30)));
}

// log c = log sqrt(1 - s^2) of the arc of E, with s^2 capped at 1 (|r.m| may round above 1:
// log c stays a number).
real al_arc_log_c(AlEdgeFrame E) {
    return AL_R(0.5) * al_log1p(-min(E.s * E.s, AL_R(1.0)));
}

// Whether exponent N takes the far form on the arc of E, by the rule al_edge_frame's comment
// states (log_x_max: al_arc_log_x_max).
bool al_arc_far(AlEdgeFrame E, real log_x_max, real N, real log_far) {
    return N * E.s * E.s > AL_R(4.0) || (N + AL_R(1.0)) * log_x_max < log_far;
}

// D lies in r's hemisphere, so x = r.u >= 0 on the arc and tau stays in [-pi/2, pi/2].
// Near form only where the arc meets the lobe: its great circle passes within
// ~2/sqrt(N) of r and x^(N+1) on the arc reaches exp(log_far) (x's maximum is c at the foot
// if the arc holds it, else at an end). Elsewhere the near form's swept azimuth
// would cancel against its smooth part to a tiny T, losing its digits.
AlEdgeFrame al_edge_frame(rvec3 a, rvec3 b, rvec3 m, rvec3 r, real N, real log_far) {
    AlEdgeFrame E;
    E.rm = dot(r, m);
    E.s = abs(E.rm);
    rvec3 foot = r - E.rm * m;
    E.c = length(foot);
    // Edge on r's great circle of horizon: x = 0 everywhere, any foot works.
    rvec3 f = E.c > AL_R(1e-6) ? foot / E.c : a;
    rvec3 g = cross(m, f);  // tau = atan(u.g, u.f), increasing from a to b
    E.ag = dot(a, g);
    E.af = dot(a, f);
    E.bg = dot(b, g);
    E.bf = dot(b, f);
    E.xa = dot(r, a);
    E.xb = dot(r, b);
    E.far_edge = al_arc_far(E, al_arc_log_x_max(E), N, log_far);
    return E;
}
