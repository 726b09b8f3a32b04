// The validation kernel in HLSL (not part of the library): templates/library/kernel.glsl's
// twin for the HLSL library, so that the HLSL text a renderer includes is run on the same
// cases, bindings and push constants (runtime/vulkan_runner.hpp): cases at binding 0,
// results at binding 1, the library's tables from binding 2 (each table's _REGISTER
// macro, defined by the stitcher before the library), the case layout of
// include/arealight/case_layout.hpp. The stitcher defines AL_KERNEL_SHADE,
// AL_KERNEL_EVALUATE and AL_KERNEL_ARGS as for GLSL.

struct AlKernelCase {
    float4 p;
    float4 n;
    float4 v;
    float4 material;
    float4 slots[8];
};

[[vk::binding(0, 0)]] StructuredBuffer<AlKernelCase> al_cases;
[[vk::binding(1, 0)]] RWStructuredBuffer<float4> al_results;
struct AlPush {
    uint count;
    uint base;
};
[[vk::push_constant]] AlPush al_push;

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint i = al_push.base + id.x;
    if (i >= al_push.count) return;
    AlKernelCase c = al_cases[i];
    ArealightSurface s;
    s.p = c.p.xyz;
    s.n = c.n.xyz;
    s.v = c.v.xyz;
    s.param = c.material.x;
    s.f0 = c.material.y;
    float3 vertices[8];
    for (int k = 0; k < 8; ++k) vertices[k] = c.slots[k].xyz;
    float3 axes[3] = {vertices[1], vertices[2], vertices[3]};
    int count = int(c.material.w);
    bool two_sided = c.material.z != 0.0;
#ifdef AL_KERNEL_SECOND
    float4 result = AL_KERNEL_EVALUATE(s, AL_KERNEL_ARGS);
#else
    ArealightShading shading = AL_KERNEL_SHADE(s, AL_KERNEL_ARGS);
    float4 result = float4(shading.diffuse, shading.specular, 0.0, 0.0);
#endif
    al_results[i] = result;
}
