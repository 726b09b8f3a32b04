// The cone from the origin over an ellipse (centre C, conjugate semi-diameters U, V,
// (U x V).C > 0: light/ellipse_record.glsl's convention), in closed form: its vector form
// factor F = (1/pi) int omega d omega, and its form factor about any unit n clipped by
// n's horizon. Heitz & Hill 2017 ("Real-Time Line- and Disk-Light Shading with Linearly
// Transformed Cosines") diagonalise the cone's quadratic form and solve a cubic; the
// forms here are our own derivation, checked against quadrature of 1/2 oint u x du in
// double (relative 1e-13) before use.
//
// In the ellipse's plane (unit normal N away from p, at distance h) with principal
// semi-axes s1 >= s2 along e1, e2, a_i = h / s_i and q_i = (C.e_i) / s_i, the cone is
// omega^T Q omega <= 0 with Q = L1 L1^T + L2 L2^T - N N^T, L_i = a_i e_i - q_i N. Q has
// one negative eigenvalue -mu; mu is the root in (0, 1] of the secular equation
//   g(mu) = mu (1 + q1^2 / (a1^2 + mu) + q2^2 / (a2^2 + mu)) = 1
// (g increasing), its eigenvector (the cone's axis) is
//   w = N + a1 q1 / (a1^2 + mu) e1 + a2 q2 / (a2^2 + mu) e2,
// and about that axis the cone has half-angle tangents t_i with t_i^2 = mu / lambda_i
// (lambda_1,2 > 0 the other eigenvalues). By symmetry F lies along w; its length, the
// area of the spherical ellipse projected on the plane normal to w over pi, is
//   |F| = t1 t2 / sqrt((1 + t1^2)(1 + t2^2)) = mu / (|w| sqrt((a1^2 + mu)(a2^2 + mu))).
// The clipped form factor is 1/(2 pi) of the boundary integral oint n.(u x du) over the
// ellipse's arc above the horizon plus the horizon's arc between the two crossings. In
// the axis' frame, boundary v3 + t1 cos(phi) v1 + t2 sin(phi) v2, the arc's integrand
// n.(P x P') / |P|^2 = (t1 t2 n3 - t2 n1 cos - t1 n2 sin) / (1 + t1^2 cos^2 + t2^2 sin^2)
// has elementary antiderivatives (an angle, and atan / atanh of sin(phi) and cos(phi)).
//
// Domain: any ellipse not through p (h > 0), any size and eccentricity; h is floored at
// 1e-9 |C| (p within 1e-9 of the light's plane, relative: the form factor changes by
// less than that). Error, fp32, against the double-precision closed form on 2e4 seeded
// ellipses (random centres, radii 1e-4..30, axis ratios 1..10), as given and through a
// fitted GGX LTC's Minv: |F| relL2 2e-7 (4e-7 through Minv); clipped form factor relL2
// 1.1e-6, largest 3.5e-5 (relative, floor 1e-3; the largest are nearly hemispherical
// cones and heavily clipped slivers, where the arc and the horizon terms cancel).
// Through the shaders: diffuse relL2 <= 4.5e-6 on every public set
// (tests/test_ltc_curved.cpp). fp64 (no variant uses it yet): the root's 6 steps reach
// relL2 3e-16 of |F| on the same ellipses in double.

// The cone of one ellipse: what al_ellipse_clipped_ff needs besides n.
struct AlEllipseCone {
    rvec3 N;     // the ellipse's plane normal, away from p
    rvec3 e1;    // principal axes in the plane (semi-axes s1 >= s2)
    rvec3 e2;
    real a1;     // h / s_i
    real a2;
    real q1;     // (C.e_i) / s_i
    real q2;
    real mu;     // minus Q's negative eigenvalue
    rvec3 axis;  // unit: the cone's axis and F's direction
    real ff;     // |F|, the unclipped form factor about the axis; 0 when no cone
};

// Root-finding steps for mu (al_ellipse_cone): enough for the precision's rounding on
// the measured sets above (fp32 4: relL2 of |F| 9e-9 in exact arithmetic; fp64 6: 3e-16).
// An ellipse or a cone whose two axes differ by less than AL_ELLIPSE_ROUND (relative) is
// round to the precision: any axis serves.
#if AL_PRECISION_FP64
const int AL_ELLIPSE_STEPS = 6;
const real AL_ELLIPSE_ROUND = AL_R(1e-15);
#else
const int AL_ELLIPSE_STEPS = 4;
const real AL_ELLIPSE_ROUND = AL_R(1e-7);
#endif

// The cone over the ellipse (C, U, V). A degenerate ellipse (U x V = 0) or one through
// or behind p gives ff = 0 and is not clipped.
AlEllipseCone al_ellipse_cone(rvec3 C, rvec3 U, rvec3 V) {
    AlEllipseCone k;
    // U, V scaled to the larger's length keep U x V clear of underflow for tiny lights.
    real s = max(length(U), length(V));
    rvec3 U1 = U / s, V1 = V / s;
    rvec3 c1 = cross(U1, V1);
    real lc = length(c1);
    k.N = c1 / lc;
    real h0 = dot(k.N, C);
    bool ok = s > AL_R(0.0) && lc > AL_R(0.0) && h0 > AL_R(0.0);
    real h = max(h0, AL_R(1e-9) * length(C));
    // Principal axes from the Gram matrix of (U1, V1): s1 = sigma1^2 / s^2, its
    // eigenvector taken from the column without cancellation. A circle to rounding has
    // every axis (and g's squares would underflow).
    real uu = dot(U1, U1), vv = dot(V1, V1), uv = dot(U1, V1);
    real disc = sqrt((uu - vv) * (uu - vv) + AL_R(4.0) * uv * uv);
    real s1 = AL_R(0.5) * (uu + vv + disc);
    rvec3 g = uu >= vv ? AL_R(0.5) * (uu - vv + disc) * U1 + uv * V1
                       : uv * U1 + AL_R(0.5) * (vv - uu + disc) * V1;
    k.e1 = disc > AL_ELLIPSE_ROUND * (uu + vv) ? normalize(g) : U1 / sqrt(uu);
    k.e2 = cross(k.N, k.e1);
    real sig1 = s * sqrt(s1), sig2 = s * lc / sqrt(s1);  // sigma1 sigma2 = s^2 lc
    real ce1 = dot(C, k.e1), ce2 = dot(C, k.e2);
    k.a1 = h / sig1;
    k.a2 = h / sig2;
    k.q1 = ce1 / sig1;
    k.q2 = ce2 / sig2;
    real A1 = k.a1 * k.a1, A2 = k.a2 * k.a2, Q1 = k.q1 * k.q1, Q2 = k.q2 * k.q2;
    // Start at the largest of four lower bounds of the root: g <= mu + sum min(mu
    // q_i^2 / a_i^2, q_i^2), which is tight for small lights (mu -> h^2 / |C|^2) and for
    // the planes through p's neighbourhood (mu -> 1 - q1^2 - q2^2).
    real x0 = ce1 / h, y0 = ce2 / h;
    real mu = max(max(AL_R(1.0) / (AL_R(1.0) + x0 * x0 + y0 * y0), AL_R(1.0) - Q1 - Q2),
                  max((AL_R(1.0) - Q2) / (AL_R(1.0) + x0 * x0),
                      (AL_R(1.0) - Q1) / (AL_R(1.0) + y0 * y0)));
    // Each step solves g = 1 with the two poles' sum replaced by one pole qm / (am + mu)
    // of the same value and slope at mu (a quadratic; secular-equation solvers' rational
    // model): exact when a1 = a2 or a q_i is 0. On the distorted ellipses above, 4 steps
    // reach |F| relL2 6e-7 in fp32, where Newton's method on g from the same start
    // leaves 9e-3 (it crawls past the knees of g at mu ~ a_i^2).
    for (int i = 0; i < AL_ELLIPSE_STEPS; ++i) {
        real d1 = A1 + mu, d2 = A2 + mu;
        real t1 = Q1 / d1, t2 = Q2 / d2;
        real w1 = t1 / d1, w2 = t2 / d2;
        real sd = w1 + w2;
        if (!(sd > AL_R(0.0))) break;  // q1 = q2 = 0: mu = 1, the start
        real am = (w1 * A1 + w2 * A2) / sd;  // the pole: a weighted mean of the a_i^2
        real sum = t1 + t2;
        real b = am + sum * sum / sd - AL_R(1.0);
        real dq = sqrt(b * b + AL_R(4.0) * am);
        mu = b > AL_R(1e18) ? am / b : (b >= AL_R(0.0) ? AL_R(2.0) * am / (b + dq)
                                                       : AL_R(0.5) * (dq - b));
        mu = max(mu, AL_R(1e-30));
    }
    k.mu = mu;
    real d1 = A1 + mu, d2 = A2 + mu;
    rvec3 w = k.N + (k.a1 * k.q1 / d1) * k.e1 + (k.a2 * k.q2 / d2) * k.e2;
    real wl = length(w);
    k.axis = w / wl;
    // Square roots taken apart: d1 d2 overflows fp32 for lights below 1e-10 of d.
    k.ff = ok ? mu / (wl * sqrt(d1) * sqrt(d2)) : AL_R(0.0);
    return k;
}

// c int_x1^x2 ds / (c^2 + kk s^2) for |x1|, |x2| <= 1, c > 0, c^2 + kk > 0, with
// dx = x2 - x1 formed by the caller: (atan(x2 r / c) - atan(x1 r / c)) / r for kk = r^2
// > 0, (atanh(x2 r / c) - atanh(x1 r / c)) / r for kk = -r^2 < 0, each difference as one
// angle or one logarithm (tan and tanh subtraction formulas), and the Taylor series
// in z = kk s^2 / c^2 where |z| < 0.05 for every s (truncation below 3e-8; fp64: 0.001,
// 1e-17). al_log_ratio_series keeps a small atanh difference exact.
real al_ellipse_arc_h(real x1, real x2, real dx, real c, real kk) {
#if AL_PRECISION_FP64
    const real z_series = AL_R(0.001);
#else
    const real z_series = AL_R(0.05);
#endif
    real c2 = c * c;
    if (abs(kk) < z_series * c2) {
        real z1 = kk * x1 * x1 / c2, z2 = kk * x2 * x2 / c2;
        real t1 = AL_R(1.0) / AL_R(9.0), t2 = t1;
        t1 = AL_R(1.0) / AL_R(7.0) - z1 * t1;
        t2 = AL_R(1.0) / AL_R(7.0) - z2 * t2;
        t1 = AL_R(1.0) / AL_R(5.0) - z1 * t1;
        t2 = AL_R(1.0) / AL_R(5.0) - z2 * t2;
        t1 = AL_R(1.0) / AL_R(3.0) - z1 * t1;
        t2 = AL_R(1.0) / AL_R(3.0) - z2 * t2;
        return (dx - (x2 * z2 * t2 - x1 * z1 * t1)) / c;
    }
    real r = sqrt(abs(kk));
    if (kk > AL_R(0.0)) return al_atan2(dx * r * c, c2 + x1 * x2 * kk) / r;
    real w = dx * r * c / (c2 + x1 * x2 * kk);
    if (abs(w) <= AL_R(0.172)) return AL_R(0.5) * al_log_ratio_series(w) / r;
    return AL_R(0.5) * al_log(((c + x2 * r) * (c - x1 * r)) / ((c - x2 * r) * (c + x1 * r))) / r;
}

// The cone's boundary in its principal frame: the directions
// w(phi) ~ ca cb axis + sa cb cos(phi) v1 + ca sb sin(phi) v2 (unit at that scale), tan
// of the half-angles t1 = sa / ca <= t2 = sb / cb.
struct AlConeFrame {
    rvec3 v1;
    rvec3 v2;
    real sa;
    real ca;
    real sb;
    real cb;
};

AlConeFrame al_cone_frame(AlEllipseCone k) {
    real mu = k.mu;
    // The cone's other two axes: Q on the plane normal to its axis, in a basis (p, q)
    // with q also normal to N, where Q's qq and pq entries are sums of squares and the
    // pp entry follows from the determinant lambda1 lambda2 = a1^2 a2^2 / mu (det Q =
    // -a1^2 a2^2): no cancellation.
    rvec3 L1 = k.a1 * k.e1 - k.q1 * k.N, L2 = k.a2 * k.e2 - k.q2 * k.N;
    rvec3 q = cross(k.axis, k.N);
    real ql = length(q);
    q = ql > AL_R(1e-7) ? q / ql : k.e2;  // axis along N: any direction of the plane
    rvec3 p = cross(q, k.axis);
    real l1q = dot(L1, q), l2q = dot(L2, q), l1p = dot(L1, p), l2p = dot(L2, p);
    real kqq = l1q * l1q + l2q * l2q, kpq = l1p * l1q + l2p * l2q;
    real det = (k.a1 * k.a1 / mu) * (k.a2 * k.a2);
    real kpp = (det + kpq * kpq) / kqq;
    real half_diff = AL_R(0.5) * (kpp - kqq);
    real rt = sqrt(half_diff * half_diff + kpq * kpq);
    real lb = AL_R(0.5) * (kpp + kqq) + rt, ls = det / lb;
    // lb's eigenvector, from the column without cancellation; a circular cone (to
    // rounding) has every axis, and its tiny column would underflow when squared.
    real ex = kpp >= kqq ? half_diff + rt : kpq, ey = kpp >= kqq ? kpq : rt - half_diff;
    bool round_cone = !(rt > AL_ELLIPSE_ROUND * (kpp + kqq));
    real el = round_cone ? AL_R(1.0) : length(rvec2(ex, ey));
    ex = round_cone ? AL_R(1.0) : ex / el;
    ey = round_cone ? AL_R(0.0) : ey / el;
    AlConeFrame f;
    f.v1 = ex * p + ey * q;
    f.v2 = cross(k.axis, f.v1);
    // Sines and cosines of the half-angles, formed without t itself, which is unbounded
    // near a hemisphere.
    f.sa = sqrt(mu / (mu + lb));
    f.ca = sqrt(lb / (mu + lb));
    f.sb = sqrt(mu / (mu + ls));
    f.cb = max(sqrt(ls / (mu + ls)), AL_R(1e-30));
    return f;
}

// Where the half space m.w >= 0 holds the cone's boundary: m.w(phi) ca cb = al0 + al1
// cos(phi) + al2 sin(phi), all of it (1), none (-1), or phi0 +- delta (0), with
// arc = (cos phi0, sin phi0, cos delta, sin delta).
int al_cone_side(AlConeFrame f, rvec3 axis, rvec3 m, AL_INOUT(rvec4) arc) {
    real al1 = dot(m, f.v1) * f.sa * f.cb, al2 = dot(m, f.v2) * f.sb * f.ca;
    real al0 = dot(m, axis) * f.ca * f.cb;
    real R = sqrt(al1 * al1 + al2 * al2);
    arc = rvec4(AL_R(1.0), AL_R(0.0), AL_R(-1.0), AL_R(0.0));
    if (al0 >= R) return 1;
    if (al0 <= -R) return -1;
    arc = rvec4(al1 / R, al2 / R, -al0 / R,
                sqrt(max((R - al0) * (R + al0), AL_R(0.0))) / R);
    return 0;
}

// A cut plane's entry phi0 - delta and exit phi0 + delta as (cos, sin, cos, sin), from its
// arc (al_cone_side) by the angle-sum products.
rvec4 al_cone_ends(rvec4 A) {
    return rvec4(A.x * A.z + A.y * A.w, A.y * A.z - A.x * A.w,
                 A.x * A.z - A.y * A.w, A.y * A.z + A.x * A.w);
}

// The boundary direction at phi = (cos, sin).
rvec3 al_cone_point(AlConeFrame f, rvec3 axis, real c, real s) {
    return f.ca * f.cb * axis + f.sa * f.cb * c * f.v1 + f.ca * f.sb * s * f.v2;
}

// 2 pi times the form factor about the unit c of the cone's boundary arc from phi at
// (cA, sA) to phi at (cB, sB), counter-clockwise, with d_s = sB - sA and d_c = cB - cA formed
// by the caller; long_arc when it spans more than pi. (Lambert's boundary integral on
// the elliptic boundary: one angle, the change of atan2(ca sin(phi), cb cos(phi)), which
// maps arcs of pi to arcs of pi, and al_ellipse_arc_h's two terms.)
real al_cone_arc(AlConeFrame f, rvec3 axis, rvec3 c, real cA, real sA, real cB, real sB,
                 real d_s, real d_c, bool long_arc) {
    real gx1 = f.cb * cA, gy1 = f.ca * sA, gx2 = f.cb * cB, gy2 = f.ca * sB;
    real turn = al_atan2(gx1 * gy2 - gy1 * gx2, gx1 * gx2 + gy1 * gy2);
    // A short arc turns by [0, pi], a long one by [pi, 2 pi] (a narrow cone's map squeezes
    // every turn toward 0, pi or 2 pi, where rounding picks atan2's sign): put each value
    // on its arc's side.
    if (long_arc) {
        if (turn < AL_HALF_PI) turn += AL_TWO_PI;
    } else {
        turn = turn < -AL_HALF_PI ? turn + AL_TWO_PI : max(turn, AL_R(0.0));
    }
    real kk = f.ca * f.ca - f.cb * f.cb;  // t2^2 - t1^2 over (1 + t1^2)(1 + t2^2), >= 0
    real arc = dot(c, axis) * f.sa * f.sb * turn;
    arc -= dot(c, f.v1) * f.sb * f.ca * f.ca * al_ellipse_arc_h(sA, sB, d_s, f.cb, kk);
    arc += dot(c, f.v2) * f.sa * f.cb * f.cb * al_ellipse_arc_h(cA, cB, d_c, f.ca, -kk);
    return arc;
}

// The form factor of the cone about the unit direction n, clipped by n's horizon
// (CONTRACT.md 2's diffuse for unit radiance when n is the surface normal), >= 0.
real al_ellipse_clipped_ff(AlEllipseCone k, rvec3 n) {
    if (!(k.ff > AL_R(0.0))) return AL_R(0.0);
    AlConeFrame f = al_cone_frame(k);
    rvec4 A;
    int side = al_cone_side(f, k.axis, n, A);
    if (side > 0) return k.ff * dot(n, k.axis);
    if (side < 0) return AL_R(0.0);
    rvec4 e = al_cone_ends(A);
    real cm = e.x, sm = e.y, cp = e.z, sp = e.w;
    // The arc phi0 - delta -> phi0 + delta; sin and cos of phi at the exit less at the
    // entry: 2 sin(delta) (cos, -sin)(phi0).
    real arc = al_cone_arc(f, k.axis, n, cm, sm, cp, sp, AL_R(2.0) * A.x * A.w,
                           -AL_R(2.0) * A.y * A.w, A.z < AL_R(0.0));
    // The horizon's arc exit -> entry: the angle between the two crossing directions,
    // in [0, pi) (the cone is convex and within the half space axis.omega > 0).
    rvec3 wp = al_cone_point(f, k.axis, cp, sp), wm = al_cone_point(f, k.axis, cm, sm);
    real horizon = al_atan2(length(cross(wp, wm)), dot(wp, wm));
    return max((arc + horizon) / AL_TWO_PI, AL_R(0.0));
}

// The chord of a cut plane m (its arc A, al_cone_side) through the cone, exit -> entry
// (counter-clockwise about m, less than pi), kept where m2.w >= 0 (side2 > 0: all of it):
// its angle. The crossing is the planes' common line, +-(m x m2), on the chord's side, not a
// point of the segment exit-entry: a cone near a hemisphere has the two nearly opposite,
// and that segment passes by the origin (fp32 lost 0.03 rad of a chord so).
real al_cone_chord(AlConeFrame f, rvec3 axis, rvec4 A, rvec3 m, rvec3 m2, int side2) {
    rvec4 e = al_cone_ends(A);
    rvec3 wp = normalize(al_cone_point(f, axis, e.z, e.w));
    rvec3 wm = normalize(al_cone_point(f, axis, e.x, e.y));
    if (side2 <= 0) {
        // A great-circle arc shorter than pi meets a half space in one piece.
        real ep = dot(m2, wp), em = dot(m2, wm);
        if (ep < AL_R(0.0) && em < AL_R(0.0)) return AL_R(0.0);
        if ((ep >= AL_R(0.0)) != (em >= AL_R(0.0))) {
            rvec3 u = normalize(cross(m, m2));
            rvec3 q = dot(cross(wp, u), m) >= AL_R(0.0) ? u : -u;
            if (ep >= AL_R(0.0)) wm = q; else wp = q;
        }
    }
    return al_atan2(max(dot(cross(wp, wm), m), AL_R(0.0)), dot(wp, wm));
}

// The form factor about the unit c of the cone clipped by two half spaces, m1.w >= 0 and
// m2.w >= 0 (method/ltc_ellipse.glsl: the LTC's z >= 0 and n's horizon): the boundary of a
// convex region, taken piece by piece (Lambert's boundary integral): the parts of the
// elliptic boundary inside both (up to two arcs, where the planes' common line is outside
// the cone) and the part of each plane's chord inside the other half space, weighted by
// that plane's m.c; planes within 1e-6 rad of each other are one. Domain: any cone of
// al_ellipse_cone, unit c, m1, m2. Error: fp32 rounding; against the polygon LTC over the
// light's 1024-gon, horizon-crossing lights included, relL2 8e-6 (tests/test_ltc_curved.cpp);
// al_ellipse_clipped_ff's value where only one plane cuts the cone and c is its normal.
real al_ellipse_clipped_ff2(AlEllipseCone k, rvec3 c, rvec3 m1, rvec3 m2) {
    if (!(k.ff > AL_R(0.0))) return AL_R(0.0);
    AlConeFrame f = al_cone_frame(k);
    rvec4 A1, A2;
    int side1 = al_cone_side(f, k.axis, m1, A1), side2 = al_cone_side(f, k.axis, m2, A2);
    // Planes that coincide to 1e-6 rad are one (a view along n makes the LTC's z >= 0 n's
    // horizon): each chord would lie on the other plane, rounding deciding which side, and
    // the two would count it twice.
    if (length(cross(m1, m2)) < AL_R(1e-6) && dot(m1, m2) > AL_R(0.0)) side2 = 1;
    if (side1 < 0 || side2 < 0) return AL_R(0.0);
    if (side1 > 0 && side2 > 0) return k.ff * dot(c, k.axis);
    // Each plane's arc of phi as (start, length), to order the ends (a plane that holds the
    // whole boundary: the whole circle); the ends themselves are each plane's entry and
    // exit (al_cone_ends), not the cosines of these angles: where the
    // cone nears a hemisphere its map's angles are that of a step (a near-plane light,
    // ca ~ cb ~ 3e-7 in the LTC's space), and an fp32 angle's last bit moved a turn by pi.
    real d1 = al_atan2(A1.w, A1.z), d2 = al_atan2(A2.w, A2.z);
    real start1 = side1 > 0 ? AL_R(0.0) : al_atan2(A1.y, A1.x) - d1;
    real start2 = side2 > 0 ? AL_R(0.0) : al_atan2(A2.y, A2.x) - d2;
    real len1 = side1 > 0 ? AL_TWO_PI : AL_R(2.0) * d1;
    real len2 = side2 > 0 ? AL_TWO_PI : AL_R(2.0) * d2;
    rvec4 ends1 = al_cone_ends(A1), ends2 = al_cone_ends(A2);
    real t = start2 - start1;
    t -= AL_TWO_PI * floor(t / AL_TWO_PI);
    real sum = AL_R(0.0);
    // In the first arc's coordinates the second is [t, t + len2]: it meets [0, len1] in
    // [t, min(t + len2, len1)] and, past 2 pi, in [0, min(t + len2 - 2 pi, len1)]. One plane
    // whole: the other's arc alone.
    for (int piece = 0; piece < 2; ++piece) {
        real lo = piece == 0 ? t : AL_R(0.0);
        real hi = piece == 0 ? t + len2 : t + len2 - AL_TWO_PI;
        bool end2 = hi <= len1;  // the piece ends at the second plane's exit
        hi = min(hi, len1);
        if (side1 > 0) {  // the second plane's arc, once
            lo = AL_R(0.0);
            hi = piece == 0 ? len2 : AL_R(0.0);
        }
        if (side2 > 0) {  // the first plane's arc, once
            lo = AL_R(0.0);
            hi = piece == 0 ? len1 : AL_R(0.0);
        }
        if (!(hi > lo)) continue;
        // (No swizzles: the CPU mirror's vectors have none.)
        bool from2 = side1 > 0 || (piece == 0 && side2 <= 0), to2 = side1 > 0 || (side2 <= 0 && end2);
        rvec2 a = from2 ? rvec2(ends2.x, ends2.y) : rvec2(ends1.x, ends1.y);
        rvec2 b = to2 ? rvec2(ends2.z, ends2.w) : rvec2(ends1.z, ends1.w);
        sum += al_cone_arc(f, k.axis, c, a.x, a.y, b.x, b.y, b.y - a.y, b.x - a.x,
                           hi - lo > AL_PI);
    }
    if (side1 == 0) sum += dot(m1, c) * al_cone_chord(f, k.axis, A1, m1, m2, side2);
    if (side2 == 0) sum += dot(m2, c) * al_cone_chord(f, k.axis, A2, m2, m1, side1);
    return max(sum / AL_TWO_PI, AL_R(0.0));
}
