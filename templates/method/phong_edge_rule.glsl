// The Gauss-Legendre rule along one Phong edge arc (derivation and error: the header
// of method/exact_phong.glsl). Substituting tan(tau) = sigma tan(xi), sigma^2 =
// s^2 + 4/N, maps the azimuth's Lorentzian core (width s) and the lobe (width
// N^-1/2) to width ~1 in xi, so AL_NODES points resolve the arc whatever s and N are.
// Domain: any arc of E (al_edge_frame), real N >= 1. Error: that of AL_NODES-point
// Gauss-Legendre on a smooth integrand; on the public phong polygon cases in double,
// 1e-8 at 16 nodes, 3e-5 relL2 at 8.

// (sin^2 x, cos^2 x) for |x| <= pi / 2 from the one cosine cos 2x (half-angle forms). sin^2 x
// is off by ~1 ulp of 1 in absolute terms (relative error large where sin x ~ 1e-4 at fp32),
// which the rule's 1 - x^2 tolerates (it shifts the node's x by ~1 ulp).
// One cosine a node where sin and cos were two (phong lorentz -108 cycles a wave, navi21).
rvec2 al_sincos_sq(real x) {
    real c2x = al_sincos(AL_R(2.0) * x).y;
    return rvec2(AL_R(0.5) - AL_R(0.5) * c2x, AL_R(0.5) + AL_R(0.5) * c2x);
}

// The moment's two integrands at one node from y = 1 - x^2 > 0, log x and x^N: far form
// (x^(N+1), x^N) / y, near form (1 - x^(N+1), 1 - x^N) / y (-> (N+1, N) / 2 as y -> 0). The
// x^(N+1) terms come from the x^N ones, 1 - x^(N+1) = x (1 - x^N) + (1 - x) with
// (1 - x) / (1 - x^2) = 1 / (1 + x), a sum of non-negative terms: one exp and one expm1 fewer
// a node than forming each power (with al_expm1_of: phong lorentz 7 716 -> 7 511 cycles a
// wave, navi21).
rvec2 al_lobe_integrands(real y, real lx, real xn, real N, bool far_edge) {
    real x = al_exp(lx);
    real inv_y = AL_R(1.0) / y;
    real g0 = far_edge ? xn * inv_y
                       : (y > AL_R(1e-30) ? -al_expm1_of(N * lx, xn) * inv_y : AL_R(0.5) * N);
    return rvec2(x * g0 + (far_edge ? AL_R(0.0) : AL_R(1.0) / (AL_R(1.0) + x)), g0);
}

// The arc's three integrals over tau: far form (x^(N+1) / (1 - x^2), x^N / (1 - x^2),
// x^N) or near form ((1 - x^(N+1)) / (1 - x^2), (1 - x^N) / (1 - x^2), x^N).
rvec3 al_lobe_rule(AlEdgeFrame E, real N) {
    real s = E.s;
    real sigma = sqrt(s * s + AL_R(4.0) / N);
    // xi = atan(tan(tau) / sigma) at the ends, straight from the components.
    real xa = al_atan2(E.ag, sigma * E.af);
    real xb = al_atan2(E.bg, sigma * E.bf);
    real half_width = AL_R(0.5) * (xb - xa), mid = AL_R(0.5) * (xa + xb);
    rvec3 acc = rvec3(AL_R(0.0));
    for (int j = 0; j < AL_NODES; ++j) {
        rvec2 sq = al_sincos_sq(mid + half_width * AL_GL_X[j]);
        real s2 = sq.x, c2 = sq.y;
        real q2 = c2 + sigma * sigma * s2;
        real dtau = AL_GL_W[j] * sigma / q2;
        // 1 - x^2 at this node, and log x.
        real y = (sigma * sigma * s2 + s * s * c2) / q2;
        real lx = y < AL_R(1.0) ? AL_R(0.5) * al_log1p(-y) : AL_R(-1.0e30);
        real xn = al_exp(N * lx);
        rvec2 g = al_lobe_integrands(y, lx, xn, N, E.far_edge);
        acc += dtau * rvec3(g.x, g.y, xn);
    }
    return acc * half_width;
}

// The arc's share of the boundary sums (AlLobeEdge) from its three integrals.
AlLobeEdge al_lobe_sums(AlEdgeFrame E, rvec3 integrals, rvec3 n, rvec3 m) {
    AlLobeEdge e;
    e.near_edge = !E.far_edge;
    real sgn = E.far_edge ? AL_R(1.0) : AL_R(-1.0);
    e.sums = rvec3(sgn * E.rm * integrals.x, sgn * E.rm * integrals.y, dot(n, m) * integrals.z);
    return e;
}
