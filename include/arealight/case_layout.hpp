// The validation kernel's case record (templates/kernel_polygon.glsl, AlKernelCase)
// and result record, shared by the packer (runtime/evaluator.cpp), the Vulkan
// runner and the CPU mirror's loop (generator/mirror_tool.cpp).
#pragma once

#include <cstddef>

namespace arealight {

// Floats per case, std430: p, n, v (xyz, w unused), material = (param, f0,
// two_sided, vertex count), then 8 vertices (xyz, w unused): the case file's
// values rounded to fp32, nothing derived from them.
constexpr std::size_t kFloatsPerCase = 48;
// diffuse, specular, then ndf or moment where the variant has one, 0.
constexpr std::size_t kFloatsPerResult = 4;

}  // namespace arealight
