// Compute entry point (GLSL only): one invocation per case, the VulkanRunner
// contract (runtime/vulkan_runner.hpp): binding 0 cases, binding 1 results,
// push constants (count, base).

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer AlInputs { AlCase al_cases[]; };
layout(std430, binding = 1) writeonly buffer AlOutputs { vec4 al_results[]; };
layout(push_constant) uniform AlPush {
    uint count;
    uint base;
} al_push;

void main() {
    uint i = al_push.base + gl_GlobalInvocationID.x;
    if (i >= al_push.count) return;
    al_results[i] = al_clean(al_shade(al_cases[i]));
}
