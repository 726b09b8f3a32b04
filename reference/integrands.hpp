// CONTRACT.md section 2 integrands, written for accuracy rather than speed:
// powers through log1p of half the squared chord, sin^2 through |a x b|^2,
// the Beckmann Smith term through erfc. Independent of templates/.
#pragma once

#include "arealight/case.hpp"
#include "vec.hpp"

namespace arealight::ref {

// cos(angle(a, b))^N for unit a, b with a.b > 0, accurate for N up to 1e5:
// 1 - cos = |a - b|^2 / 2 has no cancellation.
double cos_power(const Vec3& a, const Vec3& b, double N);

// Isotropic microfacet distribution D(h) of the material about n (0 when n.h <= 0).
double ndf_value(const Material& m, const Vec3& n, const Vec3& h);

// Smith Lambda(w) of the material for a unit direction w with n.w > 0.
double smith_lambda(const Material& m, const Vec3& n, const Vec3& w);

// Schlick's F = f0 + (1 - f0)(1 - h.v)^5 with h = normalize(w + v), for unit w and v.
// 1 - h.v = 1 - |w + v| / 2 = |w - v|^2 / (2 (2 + |w + v|)) has no cancellation.
double schlick_fresnel(double f0, const Vec3& w, const Vec3& v);

}  // namespace arealight::ref
