// Curved lights (CONTRACT.md 1: disk, sphere, ellipsoid) for the exact boundary
// methods. The light's boundary on the sphere of directions is the image of one
// ellipse (the record of light/ellipse_record.glsl): u(psi) = normalize(P(psi)),
// P = C + U cos psi + V sin psi, with (U x V).C > 0 so that u x du/dpsi =
// (P x P') / |P|^2 points into the light. Clipping by the hemispheres of n and of
// the lobe axis is closed form (al_ellipse_cut); the clipped region is convex and
// its boundary is at most two pieces of the curve and one great arc on each clip
// circle. The arcs are streamed into the method's accumulator through
// al_moments_arc (as light/polygon.glsl does), the curve's pieces through al_moments_conic.
//
// Boundary forms (ROADMAP.md identity; checked against the oracle to 1e-8 with the
// case in double): on any piecewise smooth boundary of a region D, oriented with
// u x u' inward,
//   irradiance / pi = (1/2 pi) closed int n.(u x u') dpsi,
//   dphi_a = a.(u x u') / (1 - (a.u)^2) dpsi   (azimuth about an axis a),
// and a great arc with inward normal m has u x u' = m per unit length: the
// polygon's sum arc_i (n.m_i) is the special case. The methods' per-arc forms
// (method/exact_phong.glsl, method/exact_microfacet.glsl) carry over with (n.m) dtau
// replaced by n.(u x u') dpsi.
//
// The curve's pieces are integrated in parts of at most pi/2 of psi, each cut
// (light/conic.glsl, al_conic_plan) at the features where its integrand turns fast, each
// sub-part by the peak-aware rule of method/peak_rule.glsl about its feature: the lobe's
// approaches to its axis (up to two per part), the fold of the half-vector map
// near w = -v (microfacets at grazing views), and the point of the rim nearest p
// (which sees the near rim sweep almost pi in a sliver of psi). Cost: at most 5
// parts x 4 sub-parts x 3 pieces x AL_NODES nodes for the lobe, 4 parts x 3 pieces
// x AL_NODES for the diffuse, AL_NODES (x 4 pieces, microfacets) per great arc,
// whatever N or alpha.

// The arc of the parameter circle where d.P(psi) >= 0, as (start, length), length
// in [0, 2 pi] (0: none, 2 pi: all). d.P = k + A cos(psi - psi_d), A = |(d.U, d.V)|;
// the half length is atan2(sqrt(A^2 - k^2), -k) (no acos near +-1). Exact to rounding.
rvec2 al_ellipse_cut(rvec3 C, rvec3 U, rvec3 V, rvec3 d) {
    real k = dot(d, C), a = dot(d, U), b = dot(d, V);
    real A2 = a * a + b * b;
    if (k * k >= A2) return rvec2(AL_R(0.0), k > AL_R(0.0) ? AL_TWO_PI : AL_R(0.0));
    real half_len = al_atan2(sqrt(A2 - k * k), -k);
    return rvec2(al_atan2(b, a) - half_len, AL_R(2.0) * half_len);
}

// Where the curve leaves (exit) or enters d's hemisphere, the ends of al_ellipse_cut's
// arc, without trigonometry: P = C - (k / A^2)(a U + b V) +- (sqrt(A^2 - k^2) / A^2)
// (a V - b U), on d's great circle to rounding. Only for a proper cut (k^2 < A^2).
rvec3 al_ellipse_crossing(rvec3 C, rvec3 U, rvec3 V, rvec3 d, bool exit_point) {
    real k = dot(d, C), a = dot(d, U), b = dot(d, V);
    real A2 = a * a + b * b;
    real t = sqrt(max(A2 - k * k, AL_R(0.0))) / A2;
    if (!exit_point) t = -t;
    return normalize(C - (k / A2) * (a * U + b * V) + t * (a * V - b * U));
}

// Whether the unit direction w lies inside the light's cone: w = a U + b V + c C
// with c > 0 and a^2 + b^2 <= c^2, the bound widened by slack (|C| + max(|U|, |V|)),
// about slack radians for a light of moderate size (a margin, not a distance).
bool al_ellipse_holds(rvec3 C, rvec3 U, rvec3 V, rvec3 w, real slack) {
    rvec3 uv = cross(U, V);
    real det = dot(C, uv);
    real a = dot(w, cross(V, C)) / det, b = dot(w, cross(C, U)) / det, c = dot(w, uv) / det;
    real scale = length(C) + max(length(U), length(V));
    return c > AL_R(0.0) && sqrt(a * a + b * b) <= c + slack * scale;
}

// int n.(u x u') dpsi over [psi0, psi0 + len], len <= 2 pi: the curve's share of
// 2 pi irradiance / pi, u x u' = (P x P') / |P|^2. In parts of at most pi/2, each
// by al_peak_rule about p's nearest point where that approach is sharp
// (al_conic_plan), else plain Gauss-Legendre: the integrand is smooth but for it.
real al_conic_flux(rvec3 C, rvec3 U, rvec3 V, real psi0, real len, rvec3 n) {
    int parts = int(ceil(len / AL_HALF_PI - AL_R(1e-9)));
    real h = len / real(max(parts, 1));
    real sum = AL_R(0.0);
    for (int part = 0; part < 4; ++part) {
        if (part >= parts) break;
        real p0 = psi0 + real(part) * h;
        AlConicPlan plan = al_conic_plan(C, U, V, p0, p0 + h, n, rvec3(AL_R(0.0)), AL_R(0.0), false);
        for (int k = 0; k < 4; ++k) {
            if (k >= plan.count) break;
            AlConicFrame f = al_conic_frame(U, V, plan.sub[k]);
            AlPeakRule rule = al_peak_rule(plan.sub[k].w, f.ends.x, f.ends.y, f.ends.z, f.ends.w);
            for (int piece = 0; piece < 3; ++piece) {
                rvec2 range = al_peak_range(rule, piece);
                real half_width = AL_R(0.5) * (range.y - range.x);
                real mid = AL_R(0.5) * (range.x + range.y);
                if (!(half_width > AL_R(0.0))) continue;
                real acc = AL_R(0.0);
                for (int j = 0; j < AL_NODES; ++j) {
                    rvec3 node = al_peak_node(rule, piece, mid + half_width * AL_GL_X[j]);
                    real l = inversesqrt(node.x * node.x + node.y * node.y);
                    rvec3 P = C + f.Us * (node.x * l) + f.Vs * (node.y * l);
                    rvec3 dP = f.Vs * (node.x * l) - f.Us * (node.y * l);
                    acc += AL_GL_W[j] * node.z * dot(n, cross(P, dP)) / dot(P, P);
                }
                sum += acc * half_width;
            }
        }
    }
    return sum;
}

#if !defined(AL_METHOD_POINT) && !defined(AL_METHOD_LTC)
// Streams the boundary of D = light ∩ {n.w >= 0} ∩ {axis.w >= 0} (without clip_axis,
// light ∩ {n.w >= 0}) into the method's accumulator M and returns the irradiance / pi
// of light ∩ {n.w >= 0}. The curve's pieces in D are the overlaps of the two cuts'
// parameter arcs, each handed on in parts of at most pi/2 (al_moments_conic cuts
// them further at their features); the arc on n's circle runs from where the
// curve leaves n's hemisphere to where it re-enters, clipped by the axis as in
// light/polygon.glsl; the arc on the axis's circle from D's exit to its entry.
real al_ellipse_stream(AlCase c, rvec3 n, rvec3 axis, bool clip_axis, real N,
                       AL_INOUT(AlMoments) M) {
    rvec3 C = rvec3(c.center), U = rvec3(c.verts[0]), V = rvec3(c.verts[1]);
    clip_axis = clip_axis && al_axis_clips(n, axis);  // light/polygon.glsl
    rvec2 cut_n = al_ellipse_cut(C, U, V, n);
    rvec2 cut_a = clip_axis ? al_ellipse_cut(C, U, V, axis) : rvec2(cut_n.x, AL_TWO_PI);
    bool cross_n = cut_n.y > AL_R(0.0) && cut_n.y < AL_TWO_PI;
    bool cross_a = cut_a.y > AL_R(0.0) && cut_a.y < AL_TWO_PI;
    // A whole cut starts where the other does, so that no piece is split at an
    // arbitrary point.
    if (!cross_n) cut_n.x = cut_a.x;
    if (!cross_a) cut_a.x = cut_n.x;
    rvec3 en = cross_n ? al_ellipse_crossing(C, U, V, n, false) : C;
    rvec3 xn = cross_n ? al_ellipse_crossing(C, U, V, n, true) : C;
    rvec3 ea = cross_a ? al_ellipse_crossing(C, U, V, axis, false) : C;
    rvec3 xa = cross_a ? al_ellipse_crossing(C, U, V, axis, true) : C;

    real lit_sum = cut_n.y > AL_R(0.0) ? al_conic_flux(C, U, V, cut_n.x, cut_n.y, n) : AL_R(0.0);
    if (cross_n) lit_sum += al_arc(xn, en, n);

    // The curve inside both cuts: in coordinates from cut_n's start, [0, Ln] against
    // [t, t + La] and [t - 2 pi, t - 2 pi + La]. An end at 0 or Ln is n's crossing,
    // elsewhere the axis's; with neither cut proper the piece is the closed curve.
    real t = cut_a.x - cut_n.x;
    t -= AL_TWO_PI * floor(t / AL_TWO_PI);
    for (int piece = 0; piece < 2; ++piece) {
        real shift = piece == 0 ? t : t - AL_TWO_PI;
        real lo = max(AL_R(0.0), shift), hi = min(cut_n.y, shift + cut_a.y);
        if (!(hi > lo)) continue;
        bool lo_n = lo == AL_R(0.0) && cross_n, hi_n = hi == cut_n.y && cross_n;
        real psi_lo = cut_n.x + lo, psi_hi = cut_n.x + hi;
        rvec3 a = lo_n ? en : (cross_a ? ea : normalize(al_conic_point(C, U, V, al_cis(psi_lo))));
        rvec3 b = hi_n ? xn : (cross_a ? xa : a);
        int parts = int(ceil((psi_hi - psi_lo) / AL_HALF_PI - AL_R(1e-9)));
        parts = clamp(parts, 1, 4);
        real h = (psi_hi - psi_lo) / real(parts);
        rvec3 start = a;
        for (int k = 0; k < 4; ++k) {
            if (k >= parts) break;
            real p0 = psi_lo + real(k) * h;
            real p1 = k + 1 == parts ? psi_hi : p0 + h;
            rvec3 end = k + 1 == parts ? b : normalize(al_conic_point(C, U, V, al_cis(p1)));
            al_moments_conic(M, C, U, V, p0, p1, start, end, axis, n, N);
            start = end;
        }
    }

    // Along n's circle (normal n), clipped by the axis.
    rvec3 yo = rvec3(AL_R(0.0)), yi = rvec3(AL_R(0.0));
    bool has_yo = cross_a && dot(n, xa) >= AL_R(0.0), has_yi = cross_a && dot(n, ea) >= AL_R(0.0);
    if (has_yo) yo = xa;
    if (has_yi) yi = ea;
    rvec3 arc_a = xn, arc_b = en;
    if (cross_n && al_horizon_arc(xn, en, axis, clip_axis, arc_a, arc_b, yo, has_yo, yi, has_yi))
        al_moments_arc(M, arc_a, arc_b, n, axis, n, N);
    // Along the axis's circle (normal axis), from D's exit to its entry.
    if (clip_axis && has_yo && has_yi) al_moments_arc(M, yo, yi, axis, axis, n, N);
    return lit_sum / AL_TWO_PI;
}
#endif
