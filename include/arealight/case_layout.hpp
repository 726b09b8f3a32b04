// The validation kernel's case record (templates/library/kernel.glsl, AlKernelCase)
// and result record, shared by the packer (runtime/evaluator.cpp), the Vulkan
// runner and the CPU mirror's loop (generator/mirror_tool.cpp).
#pragma once

#include <cstddef>

namespace arealight {

// Floats per case, std430: p, n, v (xyz, w unused), material = (param, f0,
// two_sided, vertex count), then 8 slots (xyz, w unused): a polygon's vertices; a
// disk's centre, u, v; a sphere's centre, then its radius in x; an ellipsoid's
// centre and three axes. The case file's values rounded to fp32, nothing derived.
constexpr std::size_t kFloatsPerCase = 48;
// diffuse, specular, then ndf or moment where the variant has one, 0.
constexpr std::size_t kFloatsPerResult = 4;

}  // namespace arealight
