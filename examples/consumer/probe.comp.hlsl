// The scene's library in HLSL (arealight_add_shaders(... LANG HLSL)), included by an HLSL
// compute shader written against CONTRACT.md section 5 only: every function the library
// holds, found through its AREALIGHT_HAS_<LIGHT>_<DIST> macros, shades one point. Built
// (compiled to SPIR-V) with the consumer, not run: render.comp draws the image.
#define AREALIGHT_SPACE 1
#include "arealight_scene.hlsl"

RWStructuredBuffer<float2> shaded : register(u0, space0);

ArealightShading add(ArealightShading a, ArealightShading b) {
    ArealightShading r;
    r.diffuse = a.diffuse + b.diffuse;
    r.specular = a.specular + b.specular;
    return r;
}

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    ArealightSurface s;
    s.p = float3(0.01 * float(id.x), 0.0, 0.0);
    s.n = float3(0.0, 0.0, 1.0);
    s.v = float3(0.0, -0.6, 0.8);
    s.param = 0.25;
    s.f0 = 0.3;
    float3 quad[8];
    for (int i = 0; i < 8; ++i) quad[i] = float3(0.0, 0.0, 0.0);
    quad[0] = float3(-1.0, -1.0, 2.0);
    quad[1] = float3(-1.0, 1.0, 2.0);
    quad[2] = float3(1.0, 1.0, 2.0);
    quad[3] = float3(1.0, -1.0, 2.0);
    float3 axes[3];
    axes[0] = float3(0.5, 0.0, 0.0);
    axes[1] = float3(0.0, 0.4, 0.0);
    axes[2] = float3(0.0, 0.0, 0.3);
    ArealightShading total;
    total.diffuse = 0.0;
    total.specular = 0.0;
#ifdef AREALIGHT_HAS_POLYGON_GGX
    s.param = 0.25;
    total = add(total, arealight_polygon_ggx(s, quad, 4, false));
#endif
#ifdef AREALIGHT_HAS_POLYGON_BECKMANN
    s.param = 0.3;
    total = add(total, arealight_polygon_beckmann(s, quad, 4, false));
#endif
#ifdef AREALIGHT_HAS_POLYGON_PHONG
    s.param = 60.0;
    total = add(total, arealight_polygon_phong(s, quad, 4, false));
#endif
#ifdef AREALIGHT_HAS_POLYGON_BLINN
    s.param = 80.0;
    total = add(total, arealight_polygon_blinn(s, quad, 4, false));
#endif
#ifdef AREALIGHT_HAS_DISK_GGX
    s.param = 0.25;
    total = add(total, arealight_disk_ggx(s, float3(0.0, 0.0, 2.0), float3(0.5, 0.0, 0.0), float3(0.0, 0.5, 0.0), true));
#endif
#ifdef AREALIGHT_HAS_DISK_BECKMANN
    s.param = 0.3;
    total = add(total, arealight_disk_beckmann(s, float3(0.0, 0.0, 2.0), float3(0.5, 0.0, 0.0), float3(0.0, 0.5, 0.0), true));
#endif
#ifdef AREALIGHT_HAS_DISK_PHONG
    s.param = 60.0;
    total = add(total, arealight_disk_phong(s, float3(0.0, 0.0, 2.0), float3(0.5, 0.0, 0.0), float3(0.0, 0.5, 0.0), true));
#endif
#ifdef AREALIGHT_HAS_DISK_BLINN
    s.param = 80.0;
    total = add(total, arealight_disk_blinn(s, float3(0.0, 0.0, 2.0), float3(0.5, 0.0, 0.0), float3(0.0, 0.5, 0.0), true));
#endif
#ifdef AREALIGHT_HAS_SPHERE_GGX
    s.param = 0.25;
    total = add(total, arealight_sphere_ggx(s, float3(0.0, 1.0, 2.0), 0.4));
#endif
#ifdef AREALIGHT_HAS_SPHERE_BECKMANN
    s.param = 0.3;
    total = add(total, arealight_sphere_beckmann(s, float3(0.0, 1.0, 2.0), 0.4));
#endif
#ifdef AREALIGHT_HAS_SPHERE_PHONG
    s.param = 60.0;
    total = add(total, arealight_sphere_phong(s, float3(0.0, 1.0, 2.0), 0.4));
#endif
#ifdef AREALIGHT_HAS_SPHERE_BLINN
    s.param = 80.0;
    total = add(total, arealight_sphere_blinn(s, float3(0.0, 1.0, 2.0), 0.4));
#endif
#ifdef AREALIGHT_HAS_ELLIPSOID_GGX
    s.param = 0.25;
    total = add(total, arealight_ellipsoid_ggx(s, float3(0.0, 1.0, 2.0), axes));
#endif
#ifdef AREALIGHT_HAS_ELLIPSOID_BECKMANN
    s.param = 0.3;
    total = add(total, arealight_ellipsoid_beckmann(s, float3(0.0, 1.0, 2.0), axes));
#endif
#ifdef AREALIGHT_HAS_ELLIPSOID_PHONG
    s.param = 60.0;
    total = add(total, arealight_ellipsoid_phong(s, float3(0.0, 1.0, 2.0), axes));
#endif
#ifdef AREALIGHT_HAS_ELLIPSOID_BLINN
    s.param = 80.0;
    total = add(total, arealight_ellipsoid_blinn(s, float3(0.0, 1.0, 2.0), axes));
#endif
    shaded[id.x] = float2(total.diffuse, total.specular);
}
