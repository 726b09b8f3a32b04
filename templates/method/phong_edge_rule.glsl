// The Gauss-Legendre rule along one Phong edge arc (derivation and error: the header
// of method/exact_phong.glsl). Substituting tan(tau) = sigma tan(xi), sigma^2 =
// s^2 + 4/N, maps the azimuth's Lorentzian core (width s) and the lobe (width
// N^-1/2) to width ~1 in xi, so AL_NODES points resolve the arc whatever s and N are.
// Domain: any arc of E (al_edge_frame), real N >= 1. Error: that of AL_NODES-point
// Gauss-Legendre on a smooth integrand; on the public phong polygon cases in double,
// 1e-8 at 16 nodes, 3e-5 relL2 at 8.

// The arc's three integrals over tau: far form (x^(N+1) / (1 - x^2), x^N / (1 - x^2),
// x^N) or near form ((1 - x^(N+1)) / (1 - x^2), (1 - x^N) / (1 - x^2), x^N);
// z_only: only the third (the first two are 0).
rvec3 al_lobe_rule(AlEdgeFrame E, real N, bool z_only) {
    real s = E.s;
    real sigma = sqrt(s * s + AL_R(4.0) / N);
    // xi = atan(tan(tau) / sigma) at the ends, straight from the components.
    real xa = al_atan2(E.ag, sigma * E.af);
    real xb = al_atan2(E.bg, sigma * E.bf);
    real half_width = AL_R(0.5) * (xb - xa), mid = AL_R(0.5) * (xa + xb);
    real k1 = N + AL_R(1.0);
    rvec3 acc = rvec3(AL_R(0.0));
    for (int j = 0; j < AL_NODES; ++j) {
        rvec2 sc = al_sincos(mid + half_width * AL_GL_X[j]);
        real s2 = sc.x * sc.x, c2 = sc.y * sc.y;
        real q2 = c2 + sigma * sigma * s2;
        real dtau = AL_GL_W[j] * sigma / q2;
        // 1 - x^2 at this node, and log x.
        real y = (sigma * sigma * s2 + s * s * c2) / q2;
        real lx = y < AL_R(1.0) ? AL_R(0.5) * al_log1p(-y) : AL_R(-1.0e30);
        real xn = al_exp(N * lx);
        if (z_only) {
            acc.z += dtau * xn;
        } else if (E.far_edge) {
            acc += dtau * rvec3(xn * al_exp(lx) / y, xn / y, xn);
        } else {
            // (1 - x^k) / (1 - x^2) -> k / 2 as x -> 1.
            real g1 = y > AL_R(1e-30) ? -al_expm1(k1 * lx) / y : AL_R(0.5) * k1;
            real g0 = y > AL_R(1e-30) ? -al_expm1(N * lx) / y : AL_R(0.5) * N;
            acc += dtau * rvec3(g1, g0, xn);
        }
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
