#include "sphere_domain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace arealight::ref {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Boundary function of a cone along w(t) = cos(t) A + sin(t) B in its w-space:
// q(t) = tan^2 (w.k)^2 - |w_perp|^2 = H0 + Hc cos 2t + Hs sin 2t (> 0 inside).
struct ConeTrig {
    double H0, Hc, Hs;
};

ConeTrig cone_trig(const EllipticCone& c, const Vec3& a, const Vec3& e) {
    const Vec3 A = c.M * a, B = c.M * e;
    const double ak = dot(A, c.k), bk = dot(B, c.k);
    // Perpendicular parts are formed explicitly so that thin cones lose no digits.
    const Vec3 Ap = A - ak * c.k, Bp = B - bk * c.k;
    const double t2 = c.tan_alpha * c.tan_alpha;
    const double P = t2 * ak * ak - norm2(Ap);
    const double Q = t2 * ak * bk - dot(Ap, Bp);
    const double R = t2 * bk * bk - norm2(Bp);
    return {0.5 * (P + R), 0.5 * (P - R), Q};
}

// All t in [0, 2 pi) with q(t) = 0.
std::vector<double> cone_roots(const ConeTrig& q) {
    std::vector<double> roots;
    const double H1 = std::hypot(q.Hc, q.Hs);
    if (!(H1 > 0.0) || std::abs(q.H0) > H1) return roots;
    const double g = std::atan2(q.Hs, q.Hc);
    const double d = std::acos(std::clamp(-q.H0 / H1, -1.0, 1.0));
    for (double s : {g + d, g - d}) {
        for (int j = -2; j <= 2; ++j) {
            double t = 0.5 * (s + 2 * kPi * j);
            if (t >= 0.0 && t < 2 * kPi) roots.push_back(t);
        }
    }
    return roots;
}

// Positive inside, roughly the angular distance to the cone's boundary.
double cone_slack(const EllipticCone& c, const Vec3& w) {
    if (c.kind == EllipticCone::Kind::Ball) {
        const Vec3 y = c.M * w;
        if (!(dot(y, c.q) < 0.0)) return -1.0;  // the ray moves away from the ball
        // Distance of the ray's line from the centre is |q x y^|; the ray hits
        // the unit ball when it is below 1.
        const double ql = norm(c.q);
        return (1.0 - norm(cross(c.q, normalize(y)))) / ql;
    }
    const Vec3 m = cross(c.u, c.v);
    const double denom = dot(m, w);
    const double tau = dot(m, c.d) / denom;
    if (!(tau > 0.0) || !std::isfinite(tau)) return -1.0;
    const Vec3 x = tau * w - c.d;  // hit point relative to the centre
    const double s = dot(x, c.u) / norm2(c.u), t = dot(x, c.v) / norm2(c.v);
    return (1.0 - std::hypot(s, t)) * std::min(norm(c.u), norm(c.v)) / tau;
}

// Angle, along cos(t) a + sin(t) e, of the point where the great circle leaves
// the cone, from the light's geometry (well conditioned for thin and flat cones).
double cone_exit(const EllipticCone& c, const Vec3& a, const Vec3& e) {
    auto angle = [&](const Vec3& w) {
        double t = std::atan2(dot(w, e), dot(w, a));
        return t;
    };
    double first = kPi;
    if (c.kind == EllipticCone::Kind::Ball) {
        // The rays in the great circle's plane form, in the ball frame, a plane
        // through q; it cuts the ball in a circle, and the exit ray is tangent to it.
        const Vec3 ya = c.M * a, ye = c.M * e;
        const Vec3 g = normalize(cross(ya, ye));
        const double sigma = dot(g, c.q);
        const double rho = std::sqrt(std::max(0.0, (1.0 - sigma) * (1.0 + sigma)));
        const Vec3 q_in = c.q - sigma * g;
        const double L = norm(q_in);
        const Vec3 b1 = (-1.0 / L) * q_in, b2 = cross(g, b1);
        const double ql = norm(c.q);
        // L^2 - rho^2 = |q|^2 - 1 exactly: no cancellation in cos(beta).
        const double cb = std::sqrt((ql - 1.0) * (ql + 1.0)) / L, sb = rho / L;
        for (double sgn : {1.0, -1.0}) {
            const double t = angle(c.M_inv * (cb * b1 + sgn * sb * b2));
            if (t > 0.0 && t < first) first = t;
        }
        return first;
    }
    // Disk: the great circle's plane meets the light's plane in a line; the exit
    // ray goes through that line's far intersection with the ellipse.
    const Vec3 g = cross(a, e);
    const double gu = dot(g, c.u), gv = dot(g, c.v), g0 = dot(g, c.d);
    const double gg = gu * gu + gv * gv;
    if (!(gg > 0.0)) return first;
    const double s0 = -g0 * gu / gg, t0 = -g0 * gv / gg;
    const double lam2 = 1.0 - (s0 * s0 + t0 * t0);
    if (!(lam2 > 0.0)) return first;
    const double lam = std::sqrt(lam2 / gg);
    for (double sgn : {1.0, -1.0}) {
        const Vec3 x = c.d + (s0 + sgn * lam * gv) * c.u + (t0 - sgn * lam * gu) * c.v;
        const double t = angle(x);
        if (t > 0.0 && t < first) first = t;
    }
    return first;
}

}  // namespace

EllipticCone EllipticCone::ball(const Mat3& A_inv, const Mat3& A, const Vec3& q) {
    const double ql = norm(q);
    EllipticCone c{A_inv, (-1.0 / ql) * q, 1.0 / std::sqrt((ql - 1.0) * (ql + 1.0)), A, Kind::Ball};
    c.q = q;
    return c;
}

EllipticCone EllipticCone::disk(const Vec3& d, const Vec3& u, const Vec3& v) {
    // x - p = T (s, t, 1) with T = [u v d]: the ellipse is the 45-degree cone
    // about z in T^-1 w.
    EllipticCone c{inverse_of_columns(u, v, d), {0, 0, 1}, 1.0, from_columns(u, v, d), Kind::Disk};
    c.d = d;
    c.u = u;
    c.v = v;
    return c;
}

double SphereDomain::slack(const Vec3& w) const {
    double s = std::numeric_limits<double>::infinity();
    for (const auto& m : halfspaces_) s = std::min(s, dot(m, w));
    for (const auto& c : cones_) s = std::min(s, cone_slack(c, w));
    return s;
}

std::vector<Vec3> SphereDomain::inner_polygon() const {
    std::vector<Vec3> poly = outline_;
    if (poly.empty() && !cones_.empty()) {
        // A fine polygon inscribed in the first cone lies inside it; the other
        // constraints clip it below.
        const auto& c = cones_.front();
        Vec3 t1, t2;
        orthonormal_basis(c.k, t1, t2);
        const int K = 512;
        for (int i = 0; i < K; ++i) {
            const double t = 2 * kPi * i / K;
            const Vec3 w = c.k + c.tan_alpha * (std::cos(t) * t1 + std::sin(t) * t2);
            poly.push_back(normalize(c.M_inv * w));
        }
    }
    auto clip = [&](auto&& side) {
        std::vector<Vec3> out;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const Vec3& P = poly[i];
            const Vec3& Q = poly[(i + 1) % poly.size()];
            const double dp = side(P), dq = side(Q);
            if (dp >= 0) out.push_back(P);
            if ((dp >= 0) != (dq >= 0)) {
                // The point of the arc PQ where the constraint vanishes (linear in
                // the chord, exact for half-spaces, a close inner point for cones).
                const Vec3 x = dp * Q - dq * P;
                out.push_back(normalize(dp >= 0 ? x : -x));
            }
        }
        poly.swap(out);
    };
    for (const auto& m : halfspaces_) {
        clip([&](const Vec3& w) { return dot(m, w); });
        if (poly.empty()) return poly;
    }
    for (std::size_t i = outline_.empty() ? 1 : 0; i < cones_.size(); ++i) {
        clip([&](const Vec3& w) { return cone_slack(cones_[i], w); });
        if (poly.empty()) return poly;
    }
    return poly;
}

double SphereDomain::exit_angle(const Vec3& a, const Vec3& e) const {
    double t_exit = kPi;
    for (const auto& m : halfspaces_) {
        // m.w(t) = (m.a) cos t + (m.e) sin t, positive at t = 0: first zero.
        const double ma = dot(m, a), me = dot(m, e);
        t_exit = std::min(t_exit, std::atan2(std::max(ma, 0.0), -me));
    }
    for (const auto& c : cones_) t_exit = std::min(t_exit, cone_exit(c, a, e));
    return std::max(t_exit, 0.0);
}

std::vector<Vec3> SphereDomain::corners() const {
    std::vector<Vec3> out;
    const double tol = 1e-9;
    auto keep = [&](const Vec3& w) {
        if (contains(w, tol)) out.push_back(w);
    };
    for (std::size_t i = 0; i < halfspaces_.size(); ++i) {
        for (std::size_t j = i + 1; j < halfspaces_.size(); ++j) {
            const Vec3 x = cross(halfspaces_[i], halfspaces_[j]);
            if (norm2(x) < 1e-300) continue;
            keep(normalize(x));
            keep(normalize(-x));
        }
        for (const auto& c : cones_) {
            Vec3 b1, b2;
            orthonormal_basis(halfspaces_[i], b1, b2);
            for (double t : cone_roots(cone_trig(c, b1, b2))) {
                keep(std::cos(t) * b1 + std::sin(t) * b2);
            }
        }
    }
    return out;
}

}  // namespace arealight::ref
