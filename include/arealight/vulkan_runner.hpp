// Headless Vulkan compute runner: one SPIR-V compute shader over `count` items, results as floats.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "arealight/diagnostics.hpp"
#include "arealight/texture.hpp"

namespace arealight {

// Shader contract for run():
//   layout(local_size_x = 64) in;
//   layout(std430, set = 0, binding = 0) readonly buffer In  { ... };  // the input bytes
//   layout(std430, set = 0, binding = 1) writeonly buffer Out { float out[]; };
//   layout(push_constant) uniform Push { uint count; uint base; };     // offsets 0 and 4
//   entry point "main"; item i = base + gl_GlobalInvocationID.x, skipped when i >= count.
//   Optional tables: layout(set = 0, binding = 2 + k) uniform sampler2D t_k;  // textures[k]
// Large inputs are split into several dispatches that differ only in `base`.
//
// Textures: each is an R32G32B32A32_SFLOAT image of one mip level, sampled with
// linear min/mag filtering, MIPMAP_MODE_NEAREST, CLAMP_TO_EDGE on u and v,
// normalized coordinates and no anisotropy (the CPU mirror's texture(),
// include/arealight/mirror_support.hpp, filters the same way).
class VulkanRunner {
  public:
    static constexpr uint32_t kLocalSizeX = 64;

    // Picks the first Vulkan 1.1 device with a compute queue whose name contains
    // `device_name_substring` (empty: the first such device). Returns nullptr, with a diagnostic,
    // when there is no instance or device, or when no device name matches.
    static std::unique_ptr<VulkanRunner> create(const std::string& device_name_substring,
                                                const DiagnosticConsumer& diag);

    ~VulkanRunner();
    VulkanRunner(const VulkanRunner&) = delete;
    VulkanRunner& operator=(const VulkanRunner&) = delete;

    std::string device_name() const;

    // Whether the device has shaderFloat16 (VK_KHR_shader_float16_int8), which the runner then
    // enables: shaders with the Float16 capability (GL_EXT_shader_explicit_arithmetic_types_
    // float16) run only where this is true.
    bool supports_float16() const;

    // Runs `spirv` on `count` items and stores count * output_floats_per_item floats in `output`.
    // Pipelines are cached per SPIR-V content and texture count, so repeated runs of one shader
    // do not recompile. textures[k] is bound at set 0, binding 2 + k (see above); the shader
    // may use fewer, but a sampler binding the shader declares must have its texture (else a
    // diagnostic). Uploaded images are cached by content (size and texels: an equal table at
    // another address is not uploaded again, and a table changed in place is re-uploaded), so
    // repeated runs upload nothing; the upload is not part of `seconds`. The device must offer
    // SAMPLED_IMAGE_FILTER_LINEAR for R32G32B32A32_SFLOAT when textures are given.
    // `seconds`, when given, receives the wall time of queue submit + fence wait only. On failure
    // returns false with a diagnostic naming the Vulkan call and its VkResult; `output` is then
    // untouched. Not thread-safe: use one runner per thread.
    bool run(const std::vector<uint32_t>& spirv, const void* input, std::size_t input_bytes,
             std::size_t count, std::vector<float>& output, std::size_t output_floats_per_item,
             const DiagnosticConsumer& diag, double* seconds = nullptr,
             const std::vector<const Texture2D*>& textures = {});

  private:
    struct Impl;
    explicit VulkanRunner(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace arealight
