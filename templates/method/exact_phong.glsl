// Exact Phong over a spherical polygon: boundary integrals evaluated by a
// peak-aware Gauss-Legendre rule. Domain: real N in [1, 1e5], any convex polygon
// clipped to the hemispheres of n and r. Cost O(AL_NODES) per edge whatever N is.
//
// Derivation (verified against the oracle to 1e-12 in double; ROADMAP.md identity):
// with G(t) = (1 - cos^(N+1) t) / (N+1) about the axis r, the integral of (r.w)^N
// over a region D not containing -r is the boundary integral of G dphi, phi the
// azimuth about r. On a great-circle edge with unit normal m (u x u' = m, polygon
// counter-clockwise seen from outside the sphere, so m points inward), let s = |r.m|,
// c = sqrt(1 - s^2), foot f = (r - (r.m) m) / c, tau the arc angle from f. Then
// r.u = x = c cos(tau), dphi = (r.m) dtau / (1 - x^2), and
//   (N+1) M_N = 2 pi [r in D] - sum_edges (r.m) T_(N+1),   T_k = int x^k / (1 - x^2) dtau,
// because int dtau / (1 - x^2) is the azimuth swept, whose signed sum is 2 pi [r in D].
// The double-axis (specular) moment follows from the surface divergence of
// (r.u)^N P(n), P the tangential projection (Arvo 1995, two-axis moment):
//   (N+2) int (r.w)^N (n.w) = N (r.n) M_(N-1) + sum_edges (n.m) int x^N dtau.
// 1 - x^2 = sin^2 tau + s^2 cos^2 tau is formed without cancellation.
//
// Quadrature: substituting tan(tau) = sigma tan(xi), sigma^2 = s^2 + 4/N, maps both the
// azimuth's Lorentzian core (width s) and the lobe (width N^-1/2) to width ~1 in xi.
// Far edges (N s^2 > 4, or x^(N+1) < 1e-3 all along the arc) integrate x^k / (1 - x^2)
// directly: small terms, no cancellation when r lies outside D. Near edges integrate
// (1 - x^k) / (1 - x^2), bounded by k/2, and add back the swept azimuth.
//
// Error (arealight eval + shared/tools/score, relative with floor 1e-3, on the public
// phong polygon cases): with double inputs and fp64 arithmetic the rule itself is at
// 1e-8 (max 1e-7 horizon; 16 and 24 nodes agree). precision=fp64 (default): max
// 2.8e-6 over typical, horizon, glossy, stress, all of it the fp32 rounding of the
// uploaded case. precision=fp32: max 1.7e-5 (horizon), because a small result is a
// sum of O(1) boundary terms and fp32 holds them to ~6e-8 absolute.
// Cost: O(AL_NODES) per edge, independent of N. GPU cost (navi21, `arealight gpu-cost`,
// the validation kernel, polygon; 2026-12-06): fp64 default 325 744 (713x the point light's
// 457, 208 VGPRs: fp64 runs at 1/16 rate); precision=fp32 9 693 (21.2x); nodes=8 fp32 6 639
// (14.5x; 1 945 instructions, 96 VGPRs), nodes=6 fp32 5 876 (12.9x; specular relL2 within 1e-4
// but 5.6e-3 on the stress set, one glossy case 5.8% off), of which the clip and the diffuse are ~2 300.
// Curved lights (disk, sphere, ellipsoid): al_lobe_conic below integrates the parts
// of their curved boundary with the same forms (light/ellipse_clip.glsl, light/ellipse.glsl).

// Per-arc sums for the arc a -> b with inward unit normal m (method/phong_edge.glsl), by
// the rule of method/phong_edge_rule.glsl.
AlLobeEdge al_lobe_edge(rvec3 a, rvec3 b, rvec3 m, rvec3 r, rvec3 n, real N) {
    AlEdgeFrame E = al_edge_frame(a, b, m, r, N, AL_R(-6.9));  // x^(N+1) >= 1e-3
    return al_lobe_sums(E, al_lobe_rule(E, N), n, m);
}

#ifdef AL_LIGHT_CURVED
// One sub-part (lo, hi, centre, sigma) of a curved light's boundary in D
// (al_conic_plan, light/ellipse_clip.glsl): al_lobe_edge's sums with the arc's (r.m) dtau
// and (n.m) dtau replaced by r.(u x u') dpsi and n.(u x u') dpsi (the derivation
// above holds on any piecewise smooth boundary), and in .w the rule's own estimate
// of the azimuth swept about r, int r.(u x u') / (1 - x^2) dpsi (reliable on far
// parts, the only ones whose sweep counts: al_moments_conic). Nodes: al_peak_rule
// about the sub-part's centre. Far form where x^(N+1) < 1e-3 or N s^2 > 4 at the
// sub-part's closest point to r among its centre and ends (the plan puts any
// interior approach to r at a centre).
rvec4 al_lobe_conic(rvec3 C, rvec3 U, rvec3 V, rvec4 sub, rvec3 r, rvec3 n, real N,
                    AL_INOUT(bool) near_part) {
    AlConicFrame f = al_conic_frame(U, V, sub);
    rvec3 Us = f.Us, Vs = f.Vs;
    real x_max = max(dot(r, normalize(C + Us)),
                     max(dot(r, normalize(al_conic_point(C, Us, Vs, rvec2(f.ends.x, f.ends.y)))),
                         dot(r, normalize(al_conic_point(C, Us, Vs, rvec2(f.ends.z, f.ends.w))))));
    bool far_part = N * (AL_R(1.0) - x_max * x_max) > AL_R(4.0) ||
                    (N + AL_R(1.0)) * al_log(max(x_max, AL_R(1e-30))) < AL_R(-6.9);
    AlPeakRule rule = al_peak_rule(sub.w, f.ends.x, f.ends.y, f.ends.z, f.ends.w);
    rvec4 acc = rvec4(AL_R(0.0));
    for (int piece = 0; piece < 3; ++piece) {
        rvec2 range = al_peak_range(rule, piece);
        real half_width = AL_R(0.5) * (range.y - range.x), mid = AL_R(0.5) * (range.x + range.y);
        if (!(half_width > AL_R(0.0))) continue;
        rvec4 sum = rvec4(AL_R(0.0));
        for (int j = 0; j < AL_NODES; ++j) {
            rvec3 node = al_peak_node(rule, piece, mid + half_width * AL_GL_X[j]);
            real l = inversesqrt(node.x * node.x + node.y * node.y);
            real cd = node.x * l, sd = node.y * l;
            rvec3 P = C + Us * cd + Vs * sd;
            rvec3 dP = Vs * cd - Us * sd;
            real q = dot(P, P);
            rvec3 w = P * inversesqrt(q);
            rvec3 J = cross(P, dP) / q;  // u x du/dpsi
            real wt = AL_GL_W[j] * node.z;
            real rJ = dot(r, J), nJ = dot(n, J);
            rvec3 rxw = cross(r, w);
            real y = dot(rxw, rxw);  // 1 - x^2
            real lx = y < AL_R(1.0) && dot(r, w) > AL_R(0.0) ? AL_R(0.5) * al_log1p(-y)
                                                            : AL_R(-1.0e30);
            real xn = al_exp(N * lx);
            rvec2 g = al_lobe_integrands(y, lx, xn, N, far_part);
            sum += wt * rvec4(rJ * g.x, rJ * g.y, nJ * xn, AL_R(0.0));
            if (y > AL_TINY) sum.w += wt * rJ / y;
        }
        acc += sum * half_width;
    }
    near_part = !far_part;
    real sgn = far_part ? AL_R(1.0) : AL_R(-1.0);
    return rvec4(sgn * acc.x, sgn * acc.y, acc.z, acc.w);
}
#endif
