// The shading problem of CONTRACT.md section 1, in world space and double precision.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace arealight {

using Vec3 = std::array<double, 3>;

enum class LightType { Polygon, Disk, Sphere, Ellipsoid };
enum class Distribution { Phong, Blinn, Beckmann, Ggx };

struct Light {
    LightType type = LightType::Polygon;
    std::vector<Vec3> vertices;  // polygon: 3..8 coplanar, convex, in order
    Vec3 center{};               // disk, sphere, ellipsoid
    Vec3 u{}, v{};               // disk: orthogonal semi-axes
    double radius = 0.0;         // sphere
    std::array<Vec3, 3> axes{};  // ellipsoid: orthogonal semi-axes
    bool two_sided = false;      // polygon, disk
};

struct Material {
    Distribution distribution = Distribution::Phong;
    double exponent = 0.0;  // phong, blinn
    double alpha = 0.0;     // beckmann, ggx
    // Schlick's f0 (CONTRACT 2, microfacet `specular` only). has_f0 says whether the case
    // carries it; without it f0 stays 1, where F = f0 + (1 - f0)(1 - h.v)^5 is exactly 1, so
    // code that always applies F (the shaders) agrees with code that skips it (the oracle).
    double f0 = 1.0;
    bool has_f0 = false;
};

struct Case {
    std::string id;
    Vec3 p{}, n{}, v{};  // n and v as read (not normalized)
    Light light;
    Material material;
};

struct CaseSet {
    std::vector<Case> cases;
};

const char* to_string(LightType t);
const char* to_string(Distribution d);
bool is_microfacet(Distribution d);

}  // namespace arealight
