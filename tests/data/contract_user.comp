#version 450
// A renderer's shader written against CONTRACT.md section 5 alone (ArealightSurface,
// ArealightShading, arealight_polygon_<dist>, AREALIGHT_SET / AREALIGHT_BINDING): it knows
// nothing of arealight's templates or validation kernel and has its own buffer layout.
// tests/test_library.cpp generates "contract_user_library.glsl" with a ggx, a phong, a
// beckmann and a blinn polygon variant and runs this on VulkanRunner, whose contract puts the
// input at binding 0, the output at 1 and the tables from binding 2.
layout(local_size_x = 64) in;

#define AREALIGHT_BINDING 2
#include "contract_user_library.glsl"

// One shading point with its light, std430 (vec3 + float share 16 bytes).
struct ShadingPoint {
    ivec4 info;  // corner count, two-sided (0/1), material model (kGgx...), unused
    vec4 corners[8];
    vec3 position;
    float roughness;  // the contract's param: alpha or exponent
    vec3 normal;
    float fresnel0;
    vec3 to_eye;
    float unused;
};
const int kGgx = 0;
const int kPhong = 1;
const int kBeckmann = 2;
const int kBlinn = 3;

layout(std430, binding = 0) readonly buffer Points { ShadingPoint points[]; };
// Two floats per point: diffuse, specular.
layout(std430, binding = 1) writeonly buffer Shaded { float shaded[]; };
layout(push_constant) uniform Range {
    uint count;
    uint base;
} range;

void main() {
    uint i = range.base + gl_GlobalInvocationID.x;
    if (i >= range.count) return;
    ShadingPoint sp = points[i];
    ArealightSurface s;
    s.p = sp.position;
    s.n = sp.normal;
    s.v = sp.to_eye;
    s.param = sp.roughness;
    s.f0 = sp.fresnel0;
    vec3 polygon[8];
    for (int k = 0; k < 8; ++k) polygon[k] = sp.corners[k].xyz;
    bool two_sided = sp.info.y != 0;
    ArealightShading r;
    switch (sp.info.z) {
        case kGgx: r = arealight_polygon_ggx(s, polygon, sp.info.x, two_sided); break;
        case kPhong: r = arealight_polygon_phong(s, polygon, sp.info.x, two_sided); break;
        case kBeckmann: r = arealight_polygon_beckmann(s, polygon, sp.info.x, two_sided); break;
        default: r = arealight_polygon_blinn(s, polygon, sp.info.x, two_sided); break;
    }
    shaded[2 * i] = r.diffuse;
    shaded[2 * i + 1] = r.specular;
}
