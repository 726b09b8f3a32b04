// Small double-precision vector helpers for the oracle (independent of the shader math).
#pragma once

#include <cmath>

#include "arealight/case.hpp"

namespace arealight::ref {

inline Vec3 operator+(const Vec3& a, const Vec3& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3 operator*(double s, const Vec3& a) {
    return {s * a[0], s * a[1], s * a[2]};
}
inline Vec3 operator-(const Vec3& a) {
    return {-a[0], -a[1], -a[2]};
}
inline double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm2(const Vec3& a) {
    return dot(a, a);
}
inline double norm(const Vec3& a) {
    return std::sqrt(dot(a, a));
}
inline Vec3 normalize(const Vec3& a) {
    return (1.0 / norm(a)) * a;
}

// Any unit vector orthogonal to the unit vector a (branch-free basis of Duff et al. 2017).
inline void orthonormal_basis(const Vec3& a, Vec3& t1, Vec3& t2) {
    const double s = std::copysign(1.0, a[2]);
    const double p = -1.0 / (s + a[2]);
    const double q = a[0] * a[1] * p;
    t1 = {1.0 + s * a[0] * a[0] * p, s * q, -s * a[0]};
    t2 = {q, s + a[1] * a[1] * p, -a[1]};
}

// Row-major 3x3 matrix.
struct Mat3 {
    Vec3 r0{}, r1{}, r2{};
    Vec3 operator*(const Vec3& x) const { return {dot(r0, x), dot(r1, x), dot(r2, x)}; }
};

// Inverse of the matrix whose columns are c0, c1, c2 (rows of the inverse are
// the reciprocal basis, built from cross products to keep cancellation local).
inline Mat3 inverse_of_columns(const Vec3& c0, const Vec3& c1, const Vec3& c2) {
    const Vec3 x0 = cross(c1, c2), x1 = cross(c2, c0), x2 = cross(c0, c1);
    const double det = dot(c0, x0);
    return {(1.0 / det) * x0, (1.0 / det) * x1, (1.0 / det) * x2};
}

// Matrix whose columns are c0, c1, c2.
inline Mat3 from_columns(const Vec3& c0, const Vec3& c1, const Vec3& c2) {
    return {{c0[0], c1[0], c2[0]}, {c0[1], c1[1], c2[1]}, {c0[2], c1[2], c2[2]}};
}

}  // namespace arealight::ref
