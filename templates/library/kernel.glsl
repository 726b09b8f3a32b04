// The validation kernel (GLSL only, not part of the library): one invocation per
// case, the case's values as its file gives them, in fp32, handed unchanged to the
// library function, as a renderer would. The host does no geometry. VulkanRunner's
// contract (runtime/vulkan_runner.hpp): cases at binding 0, results at binding 1,
// push constants (count, base); the library's tables from binding 2
// (AREALIGHT_BINDING). The stitcher defines AL_KERNEL_ARGS, the light's arguments
// spelled over the locals below (generator/stitcher.cpp, its light table), and the
// CPU mirror's loop (generator/mirror_tool.cpp) declares the same locals.

// One case, 192 bytes std430 (include/arealight/case_layout.hpp): material =
// (param, f0, two_sided, vertex count); slots holds a polygon's vertices, or a
// curved light's centre, then its vectors (disk u, v; ellipsoid axes; sphere
// radius as slots[1].x).
struct AlKernelCase {
    vec4 p;
    vec4 n;
    vec4 v;
    vec4 material;
    vec4 slots[8];
};

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer AlInputs { AlKernelCase al_cases[]; };
layout(std430, binding = 1) writeonly buffer AlOutputs { vec4 al_results[]; };
layout(push_constant) uniform AlPush {
    uint count;
    uint base;
} al_push;

void main() {
    uint i = al_push.base + gl_GlobalInvocationID.x;
    if (i >= al_push.count) return;
    AlKernelCase c = al_cases[i];
    ArealightSurface s = ArealightSurface(c.p.xyz, c.n.xyz, c.v.xyz, c.material.x, c.material.y);
    vec3 vertices[8];
    for (int k = 0; k < 8; ++k) vertices[k] = c.slots[k].xyz;
    vec3 axes[3] = vec3[3](vertices[1], vertices[2], vertices[3]);
    int count = int(c.material.w);
    bool two_sided = c.material.z != 0.0;
    // One call into the library: with every output the kernel takes them all from the
    // evaluation the public function wraps (its .xy), since no compiler merges two
    // copies of a loop and a second call would double the measured GPU cost.
#ifdef AL_KERNEL_SECOND
    vec4 result = AL_KERNEL_EVALUATE(s, AL_KERNEL_ARGS);
#else
    ArealightShading shading = AL_KERNEL_SHADE(s, AL_KERNEL_ARGS);
    vec4 result = vec4(shading.diffuse, shading.specular, 0.0, 0.0);
#endif
    al_results[i] = result;
}
