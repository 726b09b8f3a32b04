// Arvo's recurrence for Phong over a spherical polygon (Arvo 1995; Lecocq et al. 2016 eq. 2-3):
// the paper's reference, exact for integer exponents at O(N) cost per edge. The
// shader rounds N to the nearest integer n >= 1, so a non-integer N is answered for
// round(N) (its error shows in the report); cost grows linearly with n, which is
// the point of comparing it with the O(1) methods. n is also capped at
// AL_ARVO_MAX_ORDER: llvmpipe ends any loop nest after 65535 iterations (measured:
// n = 12000 on a 6-arc polygon came back wrong, 7000 on 8 arcs right), and the
// recurrence runs inside the loop over at most AL_MAX_VERTS + 2 arcs.
//
// Derivation (notation of method/exact_phong.glsl: s = |r.m|, c = sqrt(1 - s^2),
// x = r.u = c cos(tau) on the arc, dphi = (r.m) dtau / (1 - x^2)). For integer k,
// (1 - x^k) / (1 - x^2) is a finite sum of even powers of x when k is even. When
// k is odd it is not a polynomial, but x^k / (1 - x^2) = x / (1 - x^2) -
// (x + x^3 + ... + x^(k-2)), and the boundary
// integral of x dphi is 2 pi [r in D] - Omega (the integral of (1 - cos) dphi is the
// solid angle). So, with E_j = int x^j dtau over the arc,
//   int_boundary (1 - x^k) dphi = [k odd] Omega + sum_edges (r.m) sum_(j = k mod 2, step 2)^(k-2) E_j,
// which is (N+1) M_N for k = N+1 and N M_(N-1) for k = N (the two-axis relation of
// method/exact_phong.glsl adds (n.m) E_N). E_j follows the integration-by-parts
// recurrence of int cos^j:
//   E_j = (x_b^(j-1) c sin(tau_b) - x_a^(j-1) c sin(tau_a)) / j + c^2 (j-1)/j E_(j-2),
// E_0 = dtau, E_1 = c (sin tau_b - sin tau_a), forward-stable (the factor
// c^2 (j-1)/j < 1 damps earlier rounding). Error: exact but for rounding, which fp32
// accumulates over the n terms of the sums and the edges' cancellation.

#define AL_ARVO_MAX_ORDER (65000 / (AL_MAX_VERTS + 2) - 1)

// Per-arc sums: x = (r.m) A(N+1), y = (r.m) A(N), z = (n.m) E_n, A(k) the sum above.
rvec3 al_arvo_edge(rvec3 a, rvec3 b, rvec3 m, rvec3 r, rvec3 n, int order) {
    AlEdgeFrame E = al_edge_frame(a, b, m, r, AL_R(1.0), AL_R(0.0));
    real dtau = max(al_atan2(E.bg, E.bf) - al_atan2(E.ag, E.af), AL_R(0.0));
    real csa = E.c * E.ag, csb = E.c * E.bg;  // c sin(tau) at the ends
    real c2 = E.c * E.c;
    real e_prev = dtau;       // E_(j-2)
    real e_cur = csb - csa;   // E_(j-1)
    real pa = E.xa, pb = E.xb;  // x^(j-1) at the ends
    // Sums of E_j by parity, j <= order - 1.
    real sum_even = dtau, sum_odd = AL_R(0.0);
    if (order >= 2) sum_odd = e_cur;
    real e_n = order == 1 ? e_cur : dtau;
    for (int j = 2; j <= order; ++j) {
        real jr = real(j);
        real e = (pb * csb - pa * csa) / jr + c2 * (jr - AL_R(1.0)) / jr * e_prev;
        pa *= E.xa;
        pb *= E.xb;
        e_prev = e_cur;
        e_cur = e;
        if (j <= order - 1) {
            if ((j & 1) == 0)
                sum_even += e;
            else
                sum_odd += e;
        }
        e_n = e;
    }
    bool odd = (order & 1) == 1;
    real a1 = odd ? sum_even : sum_odd;  // parity of order + 1, up to order - 1
    real a0 = odd ? sum_odd : sum_even;  // parity of order, up to order - 2
    return rvec3(E.rm * a1, E.rm * a0, dot(n, m) * e_n);
}

// The accumulator light/polygon.glsl streams D's arcs into (as method/phong_boundary.glsl's):
// per-arc sums and the solid angle of D, as signed triangles (r, a, b), each by
// tan(Omega/2) = r.(a x b) / (1 + r.a + a.b + b.r) (Van Oosterom and Strackee 1983,
// atan2 form; r is a fine apex: D lies in r's hemisphere).
struct AlMoments {
    rvec3 sums;
    real omega;
    int order;  // n = round(N) >= 1
};

AlMoments al_moments_begin(rvec3 r) {
    AlMoments M;
    M.sums = rvec3(AL_R(0.0));
    M.omega = AL_R(0.0);
    M.order = 0;
    return M;
}

void al_moments_arc(AL_INOUT(AlMoments) M, rvec3 a, rvec3 b, rvec3 m, rvec3 r, rvec3 n,
                    real N) {
    M.order = clamp(int(floor(N + AL_R(0.5))), 1, AL_ARVO_MAX_ORDER);
    M.sums += al_arvo_edge(a, b, m, r, n, M.order);
    real num = dot(r, cross(a, b));
    real den = AL_R(1.0) + dot(r, a) + dot(a, b) + dot(b, r);
    M.omega += AL_R(2.0) * al_atan2(num, den);
}

// Specular and moment of (r.w)^n over D, as in method/phong_boundary.glsl but by the
// recurrence.
rvec2 al_moments_end(AlMoments M, rvec3 r, rvec3 n, real N) {
    bool odd = (M.order & 1) == 1;
    real nm1 = (odd ? AL_R(0.0) : M.omega) + M.sums.x;  // (n+1) M_n
    real nm0 = (odd ? M.omega : AL_R(0.0)) + M.sums.y;  // n M_(n-1)
    return rvec2((dot(r, n) * nm0 + M.sums.z) / AL_TWO_PI, nm1 / AL_TWO_PI);
}
