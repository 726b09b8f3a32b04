// A spherically convex set of directions: the intersection of half-spaces
// {w : m.w >= 0} and elliptic cones {w : |(Mw)_perp| <= tan(a) (Mw).k}. Every light of
// the contract, clipped by the horizon (and by the mirror hemisphere for Phong),
// is one of these; the oracle integrates over it in polar coordinates.
#pragma once

#include <optional>
#include <vector>

#include "vec.hpp"

namespace arealight::ref {

// The directions from p that reach a convex curved light. Two descriptions:
// the quadric {w : |Mw - ((Mw).k)k| <= tan_alpha (Mw).k} (a circular cone about
// the unit axis k in the frame Mw, mapped back by M_inv), used for corners and
// inscribed polygons, and the light's own geometry, used for exit angles and
// slack because the quadric loses digits for thin or nearly flat cones.
struct EllipticCone {
    enum class Kind { Ball, Disk };
    Mat3 M;
    Vec3 k;
    double tan_alpha;
    Mat3 M_inv;
    Kind kind;
    // Ball: the unit ball seen from apex q in the frame y = M w (|q| > 1).
    Vec3 q{};
    // Disk: the ellipse c + s u + t v (s^2 + t^2 <= 1) seen from p; d = c - p.
    Vec3 d{}, u{}, v{};

    // The ellipsoid (or sphere, or cap) x = c + A y, |y| <= 1, seen from p.
    static EllipticCone ball(const Mat3& A_inv, const Mat3& A, const Vec3& q);
    // The ellipse c + s u + t v seen from p, with d = c - p.
    static EllipticCone disk(const Vec3& d, const Vec3& u, const Vec3& v);
};

class SphereDomain {
  public:
    void add_halfspace(const Vec3& m) { halfspaces_.push_back(normalize(m)); }
    void add_cone(const EllipticCone& c) { cones_.push_back(c); }
    // Seeds the interior search with the outline of a polygonal light (unit
    // directions, convex, either orientation).
    void set_outline(std::vector<Vec3> outline) { outline_ = std::move(outline); }

    // Signed slack of the tightest constraint at unit direction w (> 0 inside).
    double slack(const Vec3& w) const;
    bool contains(const Vec3& w, double tol = 0.0) const { return slack(w) > -tol; }

    // A polygon of unit directions inside the domain (clipped outline or an
    // inscribed polygon of the cone); empty when the domain is (numerically) empty.
    std::vector<Vec3> inner_polygon() const;

    // Angle at which the great circle cos(t) a + sin(t) e (a inside, e unit and
    // orthogonal to a) leaves the domain; pi if it never does before -a.
    double exit_angle(const Vec3& a, const Vec3& e) const;

    // Corners of the domain: pairwise intersections of constraint boundaries
    // that lie on the domain (kinks of exit_angle as the azimuth turns).
    std::vector<Vec3> corners() const;

  private:
    std::vector<Vec3> halfspaces_;
    std::vector<EllipticCone> cones_;
    std::vector<Vec3> outline_;
};

}  // namespace arealight::ref
