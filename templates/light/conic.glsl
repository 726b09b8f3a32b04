// The curved light's boundary as a curve of the exact methods: u(psi) =
// normalize(P(psi)), P = C + U cos psi + V sin psi (light/ellipse_clip.glsl), with the
// derivatives its boundary integrals and its node placement need. P'' = C - P.

// (sin, cos) of any real angle: reduced to [-pi, pi] for al_sincos.
rvec2 al_cis(real x) {
    return al_sincos(x - AL_TWO_PI * floor(x / AL_TWO_PI + AL_R(0.5)));
}

// P at the parameter whose (sin, cos) is sc.
rvec3 al_conic_point(rvec3 C, rvec3 U, rvec3 V, rvec2 sc) {
    return C + U * sc.y + V * sc.x;
}

// Where a piece [psi0, psi1] (at most pi/2 long) of the curve comes closest to an
// axis a in the map w -> h = normalize(w + b) (b = 0: the curve itself, Phong's lobe
// about r; b = v: the half vector, a microfacet lobe about n): the maximum of
// f = a.h. psi, f there, h there, and the rate at which the distance s from a grows
// away from it: s^2 - s0^2 ~ -f f'' psi^2 at an interior maximum (|dh/dpsi|^2 for a
// great circle, less where the curve bends round a), ~ |2 f f'| psi at an end.
// A rule whose width is (distance scale) / rate then resolves the peak also where
// the curve stays near a over a long stretch.
struct AlConicPeak {
    real psi, f, rate;
    rvec3 h;
};

// f, f', f'' at psi (x, y, z), and h there. With
// L = |P|, u = P / L: P' = u' L + u L' and P'' = u'' L + 2 u' L' + u L'' give u'
// and u''; then s = u + b, S = |s|, a.s = f S likewise give f' and f''.
rvec3 al_conic_peak_f(rvec3 C, rvec3 U, rvec3 V, real psi, rvec3 a, rvec3 b,
                      AL_INOUT(rvec3) h) {
    rvec2 sc = al_cis(psi);
    rvec3 P = al_conic_point(C, U, V, sc);
    rvec3 dP = V * sc.y - U * sc.x;
    rvec3 ddP = C - P;
    real L = length(P);
    rvec3 u = P / L;
    real dL = dot(u, dP);
    real ddL = (dot(dP, dP) + dot(P, ddP)) / L - dL * dL / L;
    rvec3 du = (dP - u * dL) / L;
    rvec3 ddu = (ddP - AL_R(2.0) * du * dL - u * ddL) / L;
    rvec3 s = u + b;
    real S = length(s);
    h = s / S;
    real dS = dot(h, du);
    real ddS = (dot(du, du) + dot(s, ddu)) / S - dS * dS / S;
    real f = dot(a, h);
    real df = (dot(a, du) - f * dS) / S;
    real ddf = (dot(a, ddu) - AL_R(2.0) * df * dS - f * ddS) / S;
    return rvec3(f, df, ddf);
}

// The maximum of f on [psi0, psi1]: the best of five samples, then six safeguarded
// Newton steps, each at most an eighth of the piece (where f is not concave, that
// far uphill), kept inside the piece. f is smooth and has at most one interior
// maximum on a piece this short, except for lights seen nearly edge-on.
AlConicPeak al_conic_peak(rvec3 C, rvec3 U, rvec3 V, real psi0, real psi1, rvec3 a, rvec3 b) {
    rvec3 h;
    real best = psi0, best_f = -AL_R(2.0);
    for (int i = 0; i < 5; ++i) {
        real psi = mix(psi0, psi1, real(i) * AL_R(0.25));
        real f = al_conic_peak_f(C, U, V, psi, a, b, h).x;
        if (f > best_f) {
            best_f = f;
            best = psi;
        }
    }
    real step_max = AL_R(0.125) * (psi1 - psi0);
    for (int it = 0; it < 6; ++it) {
        rvec3 f = al_conic_peak_f(C, U, V, best, a, b, h);
        real step = f.z < AL_R(0.0) ? -f.y / f.z : (f.y >= AL_R(0.0) ? step_max : -step_max);
        best = clamp(best + clamp(step, -step_max, step_max), psi0, psi1);
    }
    AlConicPeak pk;
    pk.psi = best;
    rvec3 f = al_conic_peak_f(C, U, V, best, a, b, h);
    pk.f = f.x;
    pk.h = h;
    pk.rate = sqrt(max(-f.x * f.z, f.y * f.y));
    return pk;
}

// Where to cut a part [psi0, psi1] so that each side holds one approach to a: the
// curve can pass near a twice within a part (a small light seen round a lobe
// narrower than itself, or one seen edge-on), and al_conic_peak centres its rule on
// one. From nine samples of f: outward from the highest, the first sample after
// which f rises again is a valley between two approaches; psi1 when there is none
// on either side (the side whose further approach comes closer wins).
real al_conic_split(rvec3 C, rvec3 U, rvec3 V, real psi0, real psi1, rvec3 a, rvec3 b) {
    real f[9];
    rvec3 h;
    int top = 0;
    for (int i = 0; i < 9; ++i) {
        f[i] = al_conic_peak_f(C, U, V, mix(psi0, psi1, real(i) * AL_R(0.125)), a, b, h).x;
        if (f[i] > f[top]) top = i;
    }
    int split = 9;
    real best_rise = -AL_R(2.0);
    for (int side = 0; side < 2; ++side) {
        int step = side == 0 ? -1 : 1;
        int low = top;
        for (int k = 1; k < 9; ++k) {
            int j = top + step * k;
            if (j < 0 || j > 8) break;
            if (f[j] < f[low]) {
                low = j;
            } else if (f[j] > f[low]) {
                // A valley at `low`; the further approach peaks at least at f[j].
                real rise = f[j];
                for (int m = 1; m < 9; ++m) {
                    int q = j + step * m;
                    if (q < 0 || q > 8) break;
                    rise = max(rise, f[q]);
                }
                if (rise > best_rise) {
                    best_rise = rise;
                    split = low;
                }
                break;
            }
        }
    }
    return split < 9 ? mix(psi0, psi1, real(split) * AL_R(0.125)) : psi1;
}

// Where P comes closest to p (the origin) on [psi0, psi1], and the width of that
// approach in psi: the t at which P + P' t + P'' t^2 / 2 can have moved |P|min,
// the root of |P''| t^2 / 2 + |P'| t = |P|min. Past it 1 / |P|^2 and the direction
// u turn slowly (a point near a disk's rim sees the near rim sweep almost pi in
// a sliver of psi, |P|min / |P'|; near a needle's tip, where P' vanishes too, the
// curvature term sets it, sqrt(2 |P|min / |P''|)). Newton on q = |P|^2 (q' = 2 P.P',
// q'' = 2 (|P'|^2 + P.(C - P))) from the best of five samples, as al_conic_peak.
rvec2 al_conic_nearest(rvec3 C, rvec3 U, rvec3 V, real psi0, real psi1) {
    rvec3 P0 = al_conic_point(C, U, V, al_cis(psi0));
    real best = psi0, best_q = dot(P0, P0);
    for (int i = 1; i < 5; ++i) {
        real psi = mix(psi0, psi1, real(i) * AL_R(0.25));
        rvec3 P = al_conic_point(C, U, V, al_cis(psi));
        if (dot(P, P) < best_q) {
            best_q = dot(P, P);
            best = psi;
        }
    }
    real step_max = AL_R(0.125) * (psi1 - psi0);
    for (int it = 0; it < 6; ++it) {
        rvec2 sc = al_cis(best);
        rvec3 P = al_conic_point(C, U, V, sc), dP = V * sc.y - U * sc.x;
        real d1 = dot(P, dP), d2 = dot(dP, dP) + dot(P, C - P);
        real step = d2 > AL_R(0.0) ? -d1 / d2 : (d1 <= AL_R(0.0) ? step_max : -step_max);
        best = clamp(best + clamp(step, -step_max, step_max), psi0, psi1);
    }
    rvec2 sc = al_cis(best);
    rvec3 P = al_conic_point(C, U, V, sc), dP = V * sc.y - U * sc.x;
    real lp = length(P), l1 = length(dP), l2 = length(C - P);
    return rvec2(best, AL_R(2.0) * lp / max(l1 + sqrt(l1 * l1 + AL_R(2.0) * l2 * lp), AL_TINY));
}

// How a part [psi0, psi1] (at most pi/2) is integrated: up to four sub-parts, each
// (lo, hi, centre, sigma) for al_peak_rule, one per feature where the integrand
// turns fast: the lobe's approaches to its axis a in the map h = normalize(w + b)
// (with_lobe; al_conic_split, al_conic_peak; width sqrt(s^2 + lobe^2) / rate), the
// fold near w = -b (b != 0: microfacets; width |w + b| / rate) and p's nearest
// point (al_conic_nearest). A fold or nearest point counts where it is sharper than
// the rule about the closest centre found before it; within half that rule's width
// of it, it replaces that rule (whose peak, twice as wide as their distance, the
// sharper rule's outer pieces still resolve). Sub-parts meet halfway between centres.
// Without a feature: one sub-part, centred, sigma 1 (plain Gauss-Legendre).
struct AlConicPlan {
    rvec4 sub[4];
    int count;
};

// Puts a before b by their first component.
void al_order(AL_INOUT(rvec2) a, AL_INOUT(rvec2) b) {
    if (b.x < a.x) {
        rvec2 t = a;
        a = b;
        b = t;
    }
}

AlConicPlan al_conic_plan(rvec3 C, rvec3 U, rvec3 V, real psi0, real psi1, rvec3 a, rvec3 b,
                          real lobe, bool with_lobe) {
    // Features as (centre, sigma), the lobe's first.
    rvec2 feat[4];
    for (int i = 0; i < 4; ++i) feat[i] = rvec2(AL_R(0.0));
    int nf = 0;
    if (with_lobe) {
        real cut = al_conic_split(C, U, V, psi0, psi1, a, b);
        for (int k = 0; k < 2; ++k) {
            if (k == 1 && !(cut < psi1)) break;
            AlConicPeak pk = al_conic_peak(C, U, V, k == 0 ? psi0 : cut, k == 0 ? cut : psi1, a, b);
            real s = length(cross(a, pk.h));
            feat[nf++] = rvec2(pk.psi, clamp(sqrt(s * s + lobe * lobe) / max(pk.rate, AL_R(1e-30)),
                                             AL_R(1e-12), AL_R(1.0)));
        }
    }
    for (int k = 0; k < 2; ++k) {
        rvec2 x;
        if (k == 0) {
            if (dot(b, b) == AL_R(0.0)) continue;
            AlConicPeak fold = al_conic_peak(C, U, V, psi0, psi1, -b, rvec3(AL_R(0.0)));
            x = rvec2(fold.psi, length(fold.h + b) / max(fold.rate, AL_R(1e-30)));
        } else {
            x = al_conic_nearest(C, U, V, psi0, psi1);
        }
        x.y = clamp(x.y, AL_R(1e-12), AL_R(1.0));
        int closest = -1;
        // Against every feature so far, the fold included: a nearest point on top
        // of the fold compared with the lobe only would be added beside it, and the
        // two would meet at one centre, leaving the sharper an empty sub-part.
        for (int i = 0; i < 3; ++i)
            if (i < nf && (closest < 0 || abs(x.x - feat[i].x) < abs(x.x - feat[closest].x)))
                closest = i;
        real ref = closest >= 0 ? feat[closest].y : AL_R(1.0);
        if (!(x.y < ref)) continue;
        if (closest >= 0 && abs(x.x - feat[closest].x) <= AL_R(0.5) * ref) {
            feat[closest] = x;
        } else {
            feat[nf++] = x;
        }
    }
    if (nf == 0) feat[nf++] = rvec2(AL_R(0.5) * (psi0 + psi1), AL_R(1.0));
    // Sort by centre: a fixed network of compare-exchanges on constant indices, the
    // unused entries keyed past psi1 so that they stay last. (An insertion sort with
    // swaps at run-time indices came out of lavapipe with one entry duplicated over
    // another: every microfacet variant shaded a sphere 1e-3 of its radius away as 0
    // on lavapipe and right on the CPU mirror.)
    for (int i = 0; i < 4; ++i)
        if (i >= nf) feat[i].x = psi1 + AL_R(1.0);
    al_order(feat[0], feat[1]);
    al_order(feat[2], feat[3]);
    al_order(feat[0], feat[2]);
    al_order(feat[1], feat[3]);
    al_order(feat[1], feat[2]);
    AlConicPlan plan;
    plan.count = nf;
    for (int i = 0; i < 4; ++i) {
        real lo = i == 0 ? psi0 : AL_R(0.5) * (feat[max(i - 1, 0)].x + feat[min(i, 3)].x);
        real hi = i + 1 >= nf ? psi1 : AL_R(0.5) * (feat[min(i, 3)].x + feat[min(i + 1, 3)].x);
        plan.sub[i] = i < nf ? rvec4(lo, hi, feat[i].x, feat[i].y) : rvec4(AL_R(0.0));
    }
    return plan;
}

// A sub-part (lo, hi, centre, sigma) of al_conic_plan in its centre's frame:
// P = C + Us cos(d) + Vs sin(d), d = psi - centre, and the ends' (sin d, cos d) as
// al_peak_rule takes them.
struct AlConicFrame {
    rvec3 Us, Vs;
    rvec4 ends;
};

AlConicFrame al_conic_frame(rvec3 U, rvec3 V, rvec4 sub) {
    rvec2 sc = al_cis(sub.z);
    rvec2 ea = al_cis(sub.x - sub.z), eb = al_cis(sub.y - sub.z);
    AlConicFrame f;
    f.Us = U * sc.y + V * sc.x;
    f.Vs = V * sc.y - U * sc.x;
    f.ends = rvec4(ea.x, ea.y, eb.x, eb.y);
    return f;
}
