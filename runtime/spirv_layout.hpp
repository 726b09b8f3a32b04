// The pipeline layout a compute module declares, read from its own decorations, so
// that a driver can compile any module without being told its interface.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace arealight {

struct SpirvDescriptor {
    uint32_t set = 0, binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    uint32_t count = 1;  // product of the array lengths; 1 for a runtime array
};

struct SpirvLayout {
    std::vector<SpirvDescriptor> descriptors;  // by set, then binding; each once
    uint32_t push_constant_bytes = 0;          // the largest push-constant block's extent
};

// The descriptors (storage and uniform buffers, images, samplers, texel buffers,
// input attachments, acceleration structures) and push-constant size of a module
// with a GLCompute entry point named `entry`; nullopt with `why` set otherwise.
std::optional<SpirvLayout> reflect_spirv_layout(const std::vector<uint32_t>& spirv,
                                                const std::string& entry, std::string& why);

}  // namespace arealight
