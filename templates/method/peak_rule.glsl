// The peak-aware Gauss-Legendre rule of the exact methods along a boundary piece
// parametrised by an angle psi about its centre psi = 0 (the point closest to the
// lobe's axis), over [psi_a, psi_b] with psi_a <= 0 <= psi_b, |psi| < pi: piece 0
// the core, tan(psi) = sigma tan(xi), xi in [c0, c1] (|tan psi| <= R sigma, half
// the nodes within sigma of the centre); pieces 1 and 2 the outer parts, beyond the
// core on the left and right, in u = -log tan(|psi| / 2), u in [u_end, u1]: as
// many nodes per decade of psi near the core as far from it (the integrands decay
// like powers of psi away from the peak, or not at all). Exact for the integrand's
// smooth part; the error is that of AL_NODES-point Gauss-Legendre on each piece.

struct AlPeakRule {
    real sigma, k;  // the core's width and its reach R sigma in tan(psi)
    real c0, c1;    // the core's xi range
    real ua, ub, u1;
    bool left, right;  // whether the piece reaches beyond the core on each side
};

// The rule for width sigma > 0 and ends whose (sin, cos) are (sa, ca), (sb, cb) up
// to a positive factor.
AlPeakRule al_peak_rule(real sigma, real sa, real ca, real sb, real cb) {
    const real R = AL_R(3.0);
    AlPeakRule P;
    P.sigma = sigma;
    P.k = R * sigma;
    real xa = al_atan2(sa, sigma * ca), xb = al_atan2(sb, sigma * cb);
    real xr = al_atan2(R, AL_R(1.0));
    P.c0 = max(xa, -xr);
    P.c1 = min(xb, xr);
    P.left = xa < -xr;
    P.right = xb > xr;
    P.u1 = -al_log(P.k / (AL_R(1.0) + sqrt(AL_R(1.0) + P.k * P.k)));
    P.ua = P.left ? -al_log(abs(sa) / max(AL_R(1.0) + ca, AL_R(1e-30))) : P.u1;
    P.ub = P.right ? -al_log(abs(sb) / max(AL_R(1.0) + cb, AL_R(1e-30))) : P.u1;
    return P;
}

// Piece 0, 1 or 2's variable range (x0, x1); empty (x0 = x1) where the piece is absent.
rvec2 al_peak_range(AlPeakRule P, int piece) {
    if (piece == 0) return rvec2(P.c0, P.c1);
    if (piece == 1) return rvec2(P.left ? P.ua : P.u1, P.u1);
    return rvec2(P.right ? P.ub : P.u1, P.u1);
}

// At the variable x of a piece: (cos psi, sin psi) up to a positive factor, and
// |dpsi/dx|, so that every piece's sum over its range (x0 < x1) integrates in the
// direction of increasing psi.
rvec3 al_peak_node(AlPeakRule P, int piece, real x) {
    if (piece == 0) {
        rvec2 sc = al_sincos(x);
        real wc = sc.y, wsn = P.sigma * sc.x;
        return rvec3(wc, wsn, P.sigma / (wc * wc + wsn * wsn));
    }
    // tan(|psi| / 2) = e^-x: (cos, sin) ~ (1 - T^2, 2 T), |dpsi/dx| = sin |psi|.
    real T = al_exp(-x);
    return rvec3((AL_R(1.0) - T) * (AL_R(1.0) + T), piece == 1 ? -AL_R(2.0) * T : AL_R(2.0) * T,
                 AL_R(2.0) * T / (AL_R(1.0) + T * T));
}
