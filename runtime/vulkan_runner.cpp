// Headless compute on Vulkan 1.1 (lavapipe in CI). Every VkResult is checked and every handle is
// owned by an RAII wrapper, so an early return releases exactly what was created.
#include "arealight/vulkan_runner.hpp"
#include "arealight/fnv_hash.hpp"

#include <vulkan/vulkan.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <unordered_map>
#include <utility>

namespace arealight {
namespace {

constexpr uint64_t kFenceTimeoutNs = 60ull * 1000 * 1000 * 1000;
constexpr uint32_t kSpirvMagic = 0x07230203;
constexpr uint32_t kOpCapability = 17;       // SPIR-V spec 3.42.2
constexpr uint32_t kOpDecorate = 71;         // SPIR-V spec 3.42.3
constexpr uint32_t kCapabilityFloat16 = 9;   // SPIR-V spec 3.31
constexpr uint32_t kCapabilityFloat64 = 10;  // SPIR-V spec 3.31
constexpr uint32_t kDecorationBinding = 33;  // SPIR-V spec 3.20
constexpr uint32_t kFirstTextureBinding = 2;
constexpr VkFormat kTextureFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
// Cached texture images beyond this are dropped (those the current run needs excepted).
constexpr std::size_t kMaxCachedImages = 32;

// What run() needs to know about a module before binding it: the capabilities that need a
// device feature, and the largest descriptor binding it declares (-1: none).
struct SpirvFacts {
    bool float16 = false, float64 = false;
    int64_t max_binding = -1;
};

// One pass over the instructions after the 5-word header (SPIR-V spec 2.3, 2.4); a
// malformed word count ends the scan (the driver rejects such a module anyway).
SpirvFacts scan_spirv(const std::vector<uint32_t>& words) {
    SpirvFacts facts;
    for (std::size_t i = 5; i < words.size();) {
        const uint32_t count = words[i] >> 16, opcode = words[i] & 0xffffu;
        if (count == 0 || i + count > words.size()) break;
        if (opcode == kOpCapability && count >= 2) {
            facts.float16 |= words[i + 1] == kCapabilityFloat16;
            facts.float64 |= words[i + 1] == kCapabilityFloat64;
        } else if (opcode == kOpDecorate && count >= 4 && words[i + 2] == kDecorationBinding) {
            facts.max_binding = std::max<int64_t>(facts.max_binding, words[i + 3]);
        }
        i += count;
    }
    return facts;
}
// Push constant block of the shader contract: uint count (offset 0), uint base (offset 4).
struct PushConstants {
    uint32_t count;
    uint32_t base;
};

const char* vk_result_name(VkResult r) {
    switch (r) {
#define AREALIGHT_VK_RESULT(name) \
    case name:                    \
        return #name;
        AREALIGHT_VK_RESULT(VK_SUCCESS)
        AREALIGHT_VK_RESULT(VK_NOT_READY)
        AREALIGHT_VK_RESULT(VK_TIMEOUT)
        AREALIGHT_VK_RESULT(VK_EVENT_SET)
        AREALIGHT_VK_RESULT(VK_EVENT_RESET)
        AREALIGHT_VK_RESULT(VK_INCOMPLETE)
        AREALIGHT_VK_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
        AREALIGHT_VK_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        AREALIGHT_VK_RESULT(VK_ERROR_INITIALIZATION_FAILED)
        AREALIGHT_VK_RESULT(VK_ERROR_DEVICE_LOST)
        AREALIGHT_VK_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
        AREALIGHT_VK_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        AREALIGHT_VK_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
        AREALIGHT_VK_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        AREALIGHT_VK_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
        AREALIGHT_VK_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        AREALIGHT_VK_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
        AREALIGHT_VK_RESULT(VK_ERROR_FRAGMENTED_POOL)
        AREALIGHT_VK_RESULT(VK_ERROR_UNKNOWN)
        AREALIGHT_VK_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
        AREALIGHT_VK_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        AREALIGHT_VK_RESULT(VK_ERROR_FRAGMENTATION)
        AREALIGHT_VK_RESULT(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        AREALIGHT_VK_RESULT(VK_PIPELINE_COMPILE_REQUIRED)
        AREALIGHT_VK_RESULT(VK_ERROR_INVALID_SHADER_NV)
#undef AREALIGHT_VK_RESULT
        default:
            break;
    }
    return "unknown VkResult";
}

// Zero-initialized create-info with its sType: every optional member off, pNext null.
template <typename T>
T vk_struct(VkStructureType type) {
    T value{};
    value.sType = type;
    return value;
}

// Emits errors to an optional consumer (an empty DiagnosticConsumer drops them).
class Reporter {
  public:
    explicit Reporter(const DiagnosticConsumer& consumer) : consumer_(consumer) {}

    bool error(std::string message) const {
        if (consumer_) consumer_(Diagnostic{Severity::Error, "", 0, std::move(message)});
        return false;
    }
    // Returns whether `result` is VK_SUCCESS, reporting "<call> failed: <VkResult>" otherwise.
    bool check(VkResult result, const char* call) const {
        if (result == VK_SUCCESS) return true;
        std::string name = vk_result_name(result);
        if (name == "unknown VkResult") name += " " + std::to_string(static_cast<int>(result));
        return error(std::string(call) + " failed: " + name);
    }

  private:
    const DiagnosticConsumer& consumer_;
};

// Owns one device-level handle; every vkDestroy*/vkFreeMemory used here has this shape.
template <typename H>
class DeviceHandle {
  public:
    using Destroy = void(VKAPI_PTR*)(VkDevice, H, const VkAllocationCallbacks*);

    DeviceHandle() = default;
    DeviceHandle(VkDevice device, H handle, Destroy destroy)
        : device_(device), handle_(handle), destroy_(destroy) {}
    DeviceHandle(DeviceHandle&& other) noexcept { *this = std::move(other); }
    DeviceHandle& operator=(DeviceHandle&& other) noexcept {
        if (this != &other) {
            reset();
            device_ = other.device_;
            destroy_ = other.destroy_;
            handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
        }
        return *this;
    }
    DeviceHandle(const DeviceHandle&) = delete;
    DeviceHandle& operator=(const DeviceHandle&) = delete;
    ~DeviceHandle() { reset(); }

    H get() const { return handle_; }
    // Gives up ownership without destroying: for handles the device may still be using.
    void abandon() { handle_ = VK_NULL_HANDLE; }
    void reset() {
        if (handle_ != VK_NULL_HANDLE) destroy_(device_, handle_, nullptr);
        handle_ = VK_NULL_HANDLE;
    }

  private:
    VkDevice device_ = VK_NULL_HANDLE;
    H handle_ = VK_NULL_HANDLE;
    Destroy destroy_ = nullptr;
};

// A transient command pool on the queue family and one primary command buffer from it
// (freed with the pool), for one recording and submit.
bool one_time_commands(VkDevice dev, uint32_t queue_family, const Reporter& report,
                       DeviceHandle<VkCommandPool>& pool, VkCommandBuffer& commands) {
    auto pool_info = vk_struct<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool_info.queueFamilyIndex = queue_family;
    VkCommandPool raw = VK_NULL_HANDLE;
    if (!report.check(vkCreateCommandPool(dev, &pool_info, nullptr, &raw), "vkCreateCommandPool"))
        return false;
    pool = DeviceHandle<VkCommandPool>(dev, raw, vkDestroyCommandPool);
    auto info =
        vk_struct<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    info.commandPool = pool.get();
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    return report.check(vkAllocateCommandBuffers(dev, &info, &commands), "vkAllocateCommandBuffers");
}

struct InstanceOwner {
    VkInstance handle = VK_NULL_HANDLE;
    InstanceOwner() = default;
    InstanceOwner(const InstanceOwner&) = delete;
    InstanceOwner& operator=(const InstanceOwner&) = delete;
    ~InstanceOwner() {
        if (handle != VK_NULL_HANDLE) vkDestroyInstance(handle, nullptr);
    }
};

struct DeviceOwner {
    VkDevice handle = VK_NULL_HANDLE;
    DeviceOwner() = default;
    DeviceOwner(const DeviceOwner&) = delete;
    DeviceOwner& operator=(const DeviceOwner&) = delete;
    ~DeviceOwner() {
        if (handle != VK_NULL_HANDLE) vkDestroyDevice(handle, nullptr);
    }
};

// Buffer declared after its memory, so it is destroyed first.
struct HostBuffer {
    DeviceHandle<VkDeviceMemory> memory;
    DeviceHandle<VkBuffer> buffer;
    VkDeviceSize size = 0;

    void abandon() {
        buffer.abandon();
        memory.abandon();
    }
};

// The pipeline cache key (entries also keep the words to rule out clashes).
uint64_t hash_words(const std::vector<uint32_t>& words) {
    return fnv1a(words);
}

// The texture cache key: size and texel bits, a word at a time (entries keep the texels to
// rule out clashes). Bits, not values: -0 and 0, or two NaNs, are different tables.
uint64_t hash_texture(const Texture2D& t) {
    uint64_t h = kFnvOffset;
    auto mix = [&h](uint64_t w) {
        h ^= w;
        h *= 1099511628211ull;
        h ^= h >> 29;
    };
    mix((static_cast<uint64_t>(t.width) << 32) | t.height);
    for (float f : t.rgba) {
        uint32_t bits;
        std::memcpy(&bits, &f, sizeof bits);
        mix(bits);
    }
    return h;
}

bool same_texels(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

std::string icd_hint() {
    const char* icd = std::getenv("VK_ICD_FILENAMES");
    return std::string(
               "no Vulkan device found (is mesa-vulkan-drivers installed? VK_ICD_FILENAMES=") +
           (icd ? icd : "unset; lavapipe is /usr/share/vulkan/icd.d/lvp_icd.x86_64.json") + ")";
}

}  // namespace

struct VulkanRunner::Impl {
    struct CachedPipeline {
        std::vector<uint32_t> words;
        uint32_t textures = 0;  // the layout it was created with
        DeviceHandle<VkPipeline> pipeline;
    };
    // Set 0 with bindings 0, 1 (storage buffers) and 2 .. 1 + textures (combined image samplers).
    struct Layout {
        DeviceHandle<VkDescriptorSetLayout> set;
        DeviceHandle<VkPipelineLayout> pipeline;
    };
    // An uploaded table; memory declared first, so the view and image are destroyed before it.
    struct CachedImage {
        uint32_t width = 0, height = 0;
        std::vector<float> rgba;  // the texels uploaded, to rule out hash clashes
        DeviceHandle<VkDeviceMemory> memory;
        DeviceHandle<VkImage> image;
        DeviceHandle<VkImageView> view;

        void abandon() {
            view.abandon();
            image.abandon();
            memory.abandon();
        }
    };

    // Declaration order is destruction order reversed: images, sampler, pipelines, layouts,
    // device, instance.
    InstanceOwner instance;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memory_properties{};
    DeviceOwner device;
    uint32_t queue_family = 0;
    bool float64 = false;  // shaderFloat64 supported and enabled
    bool float16 = false;  // shaderFloat16 supported and enabled
    VkQueue queue = VK_NULL_HANDLE;
    std::map<uint32_t, Layout> layouts;  // by texture count; 0 made at device creation
    std::unordered_map<uint64_t, CachedPipeline> pipelines;
    DeviceHandle<VkSampler> sampler;  // the one sampler of every texture, made at first use
    std::unordered_map<uint64_t, std::vector<std::unique_ptr<CachedImage>>> images;  // by content
    std::size_t image_count = 0;
    // Set when a fence wait timed out: work may still be pending on the device, and destroying
    // objects in use is undefined (vkDestroy* valid usage), so everything is leaked instead.
    bool lost = false;

    ~Impl() {
        if (!lost) return;
        for (auto& bucket : images)
            for (auto& image : bucket.second) image->abandon();
        sampler.abandon();
        for (auto& entry : pipelines) entry.second.pipeline.abandon();
        for (auto& entry : layouts) {
            entry.second.pipeline.abandon();
            entry.second.set.abandon();
        }
        device.handle = VK_NULL_HANDLE;
        instance.handle = VK_NULL_HANDLE;
    }

    bool init_device(const Reporter& report);
    const Layout* layout_for(uint32_t textures, const Reporter& report);
    const CachedPipeline* pipeline_for(const std::vector<uint32_t>& spirv, uint32_t textures,
                                       const Reporter& report);
    bool create_buffer(VkDeviceSize size, VkBufferUsageFlags usage, HostBuffer& out,
                       const Reporter& report) const;
    bool make_sampler(const Reporter& report);
    const CachedImage* image_for(const Texture2D& texture, const Reporter& report);
    bool upload(const Texture2D& texture, CachedImage& image, const Reporter& report);
    void trim_images(const std::vector<const CachedImage*>& keep);
};

namespace {

struct Candidate {
    VkPhysicalDevice device;
    VkPhysicalDeviceProperties properties;
    uint32_t queue_family;
};

// Usable: Vulkan 1.1 (SPIR-V 1.3 modules) and a queue family with compute.
bool usable(VkPhysicalDevice device, const VkPhysicalDeviceProperties& properties,
            uint32_t& queue_family) {
    if (properties.apiVersion < VK_API_VERSION_1_1) return false;
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (uint32_t i = 0; i < count; ++i) {
        if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
            queue_family = i;
            return true;
        }
    }
    return false;
}

}  // namespace

std::unique_ptr<VulkanRunner> VulkanRunner::create(const std::string& device_name_substring,
                                                   const DiagnosticConsumer& diag) {
    const Reporter report(diag);
    auto impl = std::make_unique<Impl>();

    auto app = vk_struct<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = "arealight";
    app.apiVersion = VK_API_VERSION_1_1;
    auto instance_info = vk_struct<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    instance_info.pApplicationInfo = &app;
    // The loader answers VK_ERROR_INCOMPATIBLE_DRIVER when it finds no ICD at all.
    const VkResult created = vkCreateInstance(&instance_info, nullptr, &impl->instance.handle);
    if (created != VK_SUCCESS) {
        report.error(icd_hint() + ": vkCreateInstance failed: " + vk_result_name(created));
        return nullptr;
    }

    uint32_t count = 0;
    if (!report.check(vkEnumeratePhysicalDevices(impl->instance.handle, &count, nullptr),
                      "vkEnumeratePhysicalDevices")) {
        return nullptr;
    }
    std::vector<VkPhysicalDevice> devices(count);
    // VK_INCOMPLETE only if devices appeared between the calls; the first `count` are still valid.
    const VkResult listed =
        vkEnumeratePhysicalDevices(impl->instance.handle, &count, devices.data());
    if (listed != VK_INCOMPLETE && !report.check(listed, "vkEnumeratePhysicalDevices")) {
        return nullptr;
    }
    devices.resize(count);
    if (devices.empty()) {
        report.error(icd_hint());
        return nullptr;
    }

    std::string available;
    bool chosen = false;
    for (VkPhysicalDevice device : devices) {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(device, &properties);
        uint32_t family = 0;
        const bool ok = usable(device, properties, family);
        const std::string name = properties.deviceName;
        available +=
            (available.empty() ? "'" : ", '") + name + "'" + (ok ? "" : " (no Vulkan 1.1 compute)");
        if (chosen || !ok) continue;
        if (name.find(device_name_substring) == std::string::npos) continue;
        impl->physical = device;
        impl->properties = properties;
        impl->queue_family = family;
        chosen = true;
    }
    if (!chosen) {
        if (device_name_substring.empty()) {
            report.error(icd_hint() + "; devices present: " + available);
        } else {
            report.error("no Vulkan device name contains '" + device_name_substring +
                         "'; available: " + available);
        }
        return nullptr;
    }
    if (!impl->init_device(report)) return nullptr;
    return std::unique_ptr<VulkanRunner>(new VulkanRunner(std::move(impl)));
}

bool VulkanRunner::Impl::init_device(const Reporter& report) {
    vkGetPhysicalDeviceMemoryProperties(physical, &memory_properties);

    const float priority = 1.0f;
    auto queue_info =
        vk_struct<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    queue_info.queueFamilyIndex = queue_family;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    // fp64 variants (precision=fp64) need shaderFloat64; enable it wherever it exists.
    VkPhysicalDeviceFeatures supported{};
    vkGetPhysicalDeviceFeatures(physical, &supported);
    VkPhysicalDeviceFeatures enabled{};
    enabled.shaderFloat64 = supported.shaderFloat64;
    float64 = supported.shaderFloat64 == VK_TRUE;
    auto device_info = vk_struct<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue_info;
    device_info.pEnabledFeatures = &enabled;

    // fp16 variants (precision=fp16) need shaderFloat16: through VK_KHR_shader_float16_int8
    // (the instance asks for Vulkan 1.1, where the feature is that extension's), enabled
    // wherever the device offers it.
    uint32_t extension_count = 0;
    std::vector<VkExtensionProperties> extensions;
    if (vkEnumerateDeviceExtensionProperties(physical, nullptr, &extension_count, nullptr) ==
        VK_SUCCESS) {
        extensions.resize(extension_count);
        if (vkEnumerateDeviceExtensionProperties(physical, nullptr, &extension_count,
                                                 extensions.data()) != VK_SUCCESS) {
            extension_count = 0;
        }
        extensions.resize(extension_count);
    }
    const bool has_float16_extension =
        std::any_of(extensions.begin(), extensions.end(), [](const VkExtensionProperties& e) {
            return std::strcmp(e.extensionName, VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME) == 0;
        });
    auto float16_supported = vk_struct<VkPhysicalDeviceShaderFloat16Int8FeaturesKHR>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES_KHR);
    if (has_float16_extension) {
        auto features2 =
            vk_struct<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
        features2.pNext = &float16_supported;
        vkGetPhysicalDeviceFeatures2(physical, &features2);
    }
    float16 = has_float16_extension && float16_supported.shaderFloat16 == VK_TRUE;
    auto float16_enabled = vk_struct<VkPhysicalDeviceShaderFloat16Int8FeaturesKHR>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES_KHR);
    const char* const float16_extension = VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME;
    if (float16) {
        float16_enabled.shaderFloat16 = VK_TRUE;
        device_info.pNext = &float16_enabled;
        device_info.enabledExtensionCount = 1;
        device_info.ppEnabledExtensionNames = &float16_extension;
    }

    if (!report.check(vkCreateDevice(physical, &device_info, nullptr, &device.handle),
                      "vkCreateDevice")) {
        return false;
    }
    vkGetDeviceQueue(device.handle, queue_family, 0, &queue);
    return layout_for(0, report) != nullptr;
}

const VulkanRunner::Impl::Layout* VulkanRunner::Impl::layout_for(uint32_t textures,
                                                                 const Reporter& report) {
    auto found = layouts.find(textures);
    if (found != layouts.end()) return &found->second;

    std::vector<VkDescriptorSetLayoutBinding> bindings(kFirstTextureBinding + textures);
    for (uint32_t i = 0; i < bindings.size(); ++i) {
        bindings[i].binding = i;
        bindings[i].descriptorType = i < kFirstTextureBinding
                                         ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER
                                         : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        bindings[i].descriptorCount = 1;
        bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    auto set_info = vk_struct<VkDescriptorSetLayoutCreateInfo>(
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    set_info.bindingCount = static_cast<uint32_t>(bindings.size());
    set_info.pBindings = bindings.data();
    VkDescriptorSetLayout set = VK_NULL_HANDLE;
    if (!report.check(vkCreateDescriptorSetLayout(device.handle, &set_info, nullptr, &set),
                      "vkCreateDescriptorSetLayout")) {
        return nullptr;
    }
    Layout layout;
    layout.set = {device.handle, set, vkDestroyDescriptorSetLayout};

    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(PushConstants)};
    auto layout_info =
        vk_struct<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set;
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &push;
    VkPipelineLayout raw_layout = VK_NULL_HANDLE;
    if (!report.check(vkCreatePipelineLayout(device.handle, &layout_info, nullptr, &raw_layout),
                      "vkCreatePipelineLayout")) {
        return nullptr;
    }
    layout.pipeline = {device.handle, raw_layout, vkDestroyPipelineLayout};
    return &(layouts[textures] = std::move(layout));
}

const VulkanRunner::Impl::CachedPipeline* VulkanRunner::Impl::pipeline_for(
    const std::vector<uint32_t>& spirv, uint32_t textures, const Reporter& report) {
    // One entry per (module, texture count): the layout is part of the pipeline.
    const uint64_t key = hash_words(spirv) ^ (0x9e3779b97f4a7c15ull * (textures + 1ull));
    auto found = pipelines.find(key);
    if (found != pipelines.end() && found->second.textures == textures &&
        found->second.words == spirv) {
        return &found->second;
    }
    const Layout* layout = layout_for(textures, report);
    if (!layout) return nullptr;

    auto module_info =
        vk_struct<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    module_info.codeSize = spirv.size() * sizeof(uint32_t);
    module_info.pCode = spirv.data();
    VkShaderModule raw_module = VK_NULL_HANDLE;
    if (!report.check(vkCreateShaderModule(device.handle, &module_info, nullptr, &raw_module),
                      "vkCreateShaderModule")) {
        return nullptr;
    }
    // A module may be destroyed once pipelines are created from it (vkDestroyShaderModule).
    const DeviceHandle<VkShaderModule> module(device.handle, raw_module, vkDestroyShaderModule);

    auto pipeline_info =
        vk_struct<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
    pipeline_info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    pipeline_info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipeline_info.stage.module = module.get();
    pipeline_info.stage.pName = "main";
    pipeline_info.layout = layout->pipeline.get();
    VkPipeline raw_pipeline = VK_NULL_HANDLE;
    if (!report.check(vkCreateComputePipelines(device.handle, VK_NULL_HANDLE, 1, &pipeline_info,
                                               nullptr, &raw_pipeline),
                      "vkCreateComputePipelines")) {
        return nullptr;
    }
    CachedPipeline& entry = pipelines[key];
    entry.words = spirv;
    entry.textures = textures;
    entry.pipeline = {device.handle, raw_pipeline, vkDestroyPipeline};
    return &entry;
}

bool VulkanRunner::Impl::create_buffer(VkDeviceSize size, VkBufferUsageFlags usage, HostBuffer& out,
                                       const Reporter& report) const {
    auto buffer_info = vk_struct<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    buffer_info.size = size;
    buffer_info.usage = usage;
    buffer_info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    if (!report.check(vkCreateBuffer(device.handle, &buffer_info, nullptr, &buffer),
                      "vkCreateBuffer")) {
        return false;
    }
    out.buffer = {device.handle, buffer, vkDestroyBuffer};
    out.size = size;

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device.handle, buffer, &requirements);
    // Coherent host memory needs no flush/invalidate; cached makes the readback fast.
    const VkMemoryPropertyFlags required =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    uint32_t type = UINT32_MAX;
    for (const VkMemoryPropertyFlags wanted :
         {required | VK_MEMORY_PROPERTY_HOST_CACHED_BIT, required}) {
        for (uint32_t i = 0; i < memory_properties.memoryTypeCount && type == UINT32_MAX; ++i) {
            if ((requirements.memoryTypeBits & (1u << i)) &&
                (memory_properties.memoryTypes[i].propertyFlags & wanted) == wanted) {
                type = i;
            }
        }
    }
    if (type == UINT32_MAX) {
        return report.error("no HOST_VISIBLE | HOST_COHERENT memory type for a buffer");
    }
    auto alloc_info = vk_struct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    alloc_info.allocationSize = requirements.size;
    alloc_info.memoryTypeIndex = type;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    if (!report.check(vkAllocateMemory(device.handle, &alloc_info, nullptr, &memory),
                      "vkAllocateMemory")) {
        return false;
    }
    out.memory = {device.handle, memory, vkFreeMemory};
    return report.check(vkBindBufferMemory(device.handle, buffer, memory, 0), "vkBindBufferMemory");
}

bool VulkanRunner::Impl::make_sampler(const Reporter& report) {
    if (sampler.get() != VK_NULL_HANDLE) return true;
    // Linear filtering of the format is optional (VkFormatProperties): without it the
    // sampler's LINEAR filter would be invalid for these images.
    VkFormatProperties format{};
    vkGetPhysicalDeviceFormatProperties(physical, kTextureFormat, &format);
    const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                        VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT |
                                        VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    if ((format.optimalTilingFeatures & needed) != needed) {
        return report.error(
            "device '" + std::string(properties.deviceName) +
            "' cannot sample R32G32B32A32_SFLOAT textures with linear filtering "
            "(VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | SAMPLED_IMAGE_FILTER_LINEAR_BIT | "
            "TRANSFER_DST_BIT missing for optimal tiling), which the texture-sampling "
            "variants (method=ltc) need");
    }
    auto info = vk_struct<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    info.magFilter = VK_FILTER_LINEAR;
    info.minFilter = VK_FILTER_LINEAR;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.mipLodBias = 0.0f;
    info.anisotropyEnable = VK_FALSE;
    info.maxAnisotropy = 1.0f;
    info.compareEnable = VK_FALSE;
    info.minLod = 0.0f;
    info.maxLod = 0.0f;  // one level
    info.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    info.unnormalizedCoordinates = VK_FALSE;
    VkSampler raw = VK_NULL_HANDLE;
    if (!report.check(vkCreateSampler(device.handle, &info, nullptr, &raw), "vkCreateSampler")) {
        return false;
    }
    sampler = {device.handle, raw, vkDestroySampler};
    return true;
}

const VulkanRunner::Impl::CachedImage* VulkanRunner::Impl::image_for(const Texture2D& texture,
                                                                     const Reporter& report) {
    const uint64_t expected = static_cast<uint64_t>(texture.width) * texture.height * 4;
    if (texture.width == 0 || texture.height == 0 || texture.rgba.size() != expected) {
        report.error("texture of " + std::to_string(texture.width) + " x " +
                     std::to_string(texture.height) + " texels has " +
                     std::to_string(texture.rgba.size()) + " floats, not width * height * 4");
        return nullptr;
    }
    const uint32_t limit = properties.limits.maxImageDimension2D;
    if (texture.width > limit || texture.height > limit) {
        report.error("texture of " + std::to_string(texture.width) + " x " +
                     std::to_string(texture.height) + " texels exceeds maxImageDimension2D (" +
                     std::to_string(limit) + ")");
        return nullptr;
    }
    const uint64_t key = hash_texture(texture);
    auto& bucket = images[key];
    for (const auto& cached : bucket) {
        if (cached->width == texture.width && cached->height == texture.height &&
            same_texels(cached->rgba, texture.rgba)) {
            return cached.get();
        }
    }
    auto image = std::make_unique<CachedImage>();
    if (!upload(texture, *image, report)) {
        if (bucket.empty()) images.erase(key);
        return nullptr;
    }
    bucket.push_back(std::move(image));
    ++image_count;
    return bucket.back().get();
}

bool VulkanRunner::Impl::upload(const Texture2D& texture, CachedImage& out,
                                const Reporter& report) {
    const VkDevice dev = device.handle;
    out.width = texture.width;
    out.height = texture.height;
    out.rgba = texture.rgba;

    auto image_info = vk_struct<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    image_info.imageType = VK_IMAGE_TYPE_2D;
    image_info.format = kTextureFormat;
    image_info.extent = {texture.width, texture.height, 1};
    image_info.mipLevels = 1;
    image_info.arrayLayers = 1;
    image_info.samples = VK_SAMPLE_COUNT_1_BIT;
    image_info.tiling = VK_IMAGE_TILING_OPTIMAL;
    image_info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    image_info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    image_info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImage raw_image = VK_NULL_HANDLE;
    if (!report.check(vkCreateImage(dev, &image_info, nullptr, &raw_image), "vkCreateImage")) {
        return false;
    }
    DeviceHandle<VkImage> image(dev, raw_image, vkDestroyImage);
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(dev, raw_image, &requirements);
    uint32_t type = UINT32_MAX;
    for (const VkMemoryPropertyFlags wanted :
         {VkMemoryPropertyFlags{VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT}, VkMemoryPropertyFlags{0}}) {
        for (uint32_t i = 0; i < memory_properties.memoryTypeCount && type == UINT32_MAX; ++i) {
            if ((requirements.memoryTypeBits & (1u << i)) &&
                (memory_properties.memoryTypes[i].propertyFlags & wanted) == wanted) {
                type = i;
            }
        }
    }
    if (type == UINT32_MAX) return report.error("no memory type for a sampled image");
    auto alloc_info = vk_struct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    alloc_info.allocationSize = requirements.size;
    alloc_info.memoryTypeIndex = type;
    VkDeviceMemory raw_memory = VK_NULL_HANDLE;
    if (!report.check(vkAllocateMemory(dev, &alloc_info, nullptr, &raw_memory),
                      "vkAllocateMemory")) {
        return false;
    }
    out.memory = {dev, raw_memory, vkFreeMemory};
    out.image = std::move(image);
    if (!report.check(vkBindImageMemory(dev, raw_image, raw_memory, 0), "vkBindImageMemory")) {
        return false;
    }

    HostBuffer staging;
    if (!create_buffer(texture.bytes(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, staging, report)) {
        return false;
    }
    void* mapped = nullptr;
    if (!report.check(vkMapMemory(dev, staging.memory.get(), 0, VK_WHOLE_SIZE, 0, &mapped),
                      "vkMapMemory")) {
        return false;
    }
    std::memcpy(mapped, texture.rgba.data(), texture.bytes());
    vkUnmapMemory(dev, staging.memory.get());

    DeviceHandle<VkCommandPool> command_pool;
    VkCommandBuffer commands = VK_NULL_HANDLE;  // freed with its pool
    if (!one_time_commands(dev, queue_family, report, command_pool, commands)) return false;
    auto begin = vk_struct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    if (!report.check(vkBeginCommandBuffer(commands, &begin), "vkBeginCommandBuffer")) return false;
    // UNDEFINED -> TRANSFER_DST, copy, TRANSFER_DST -> SHADER_READ_ONLY for compute reads.
    auto barrier = vk_struct<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = raw_image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    barrier.srcAccessMask = 0;
    barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &barrier);
    VkBufferImageCopy region{};
    region.bufferOffset = 0;
    region.bufferRowLength = 0;  // tightly packed
    region.bufferImageHeight = 0;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageOffset = {0, 0, 0};
    region.imageExtent = {texture.width, texture.height, 1};
    vkCmdCopyBufferToImage(commands, staging.buffer.get(), raw_image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    barrier.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0, nullptr, 1,
                         &barrier);
    if (!report.check(vkEndCommandBuffer(commands), "vkEndCommandBuffer")) return false;

    auto fence_info = vk_struct<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    VkFence raw_fence = VK_NULL_HANDLE;
    if (!report.check(vkCreateFence(dev, &fence_info, nullptr, &raw_fence), "vkCreateFence")) {
        return false;
    }
    DeviceHandle<VkFence> fence(dev, raw_fence, vkDestroyFence);
    auto submit = vk_struct<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    if (!report.check(vkQueueSubmit(queue, 1, &submit, fence.get()), "vkQueueSubmit")) {
        return false;
    }
    const VkResult waited = vkWaitForFences(dev, 1, &raw_fence, VK_TRUE, kFenceTimeoutNs);
    if (waited != VK_SUCCESS) {
        // The copy may still be running: leak rather than destroy objects in use.
        lost = true;
        fence.abandon();
        command_pool.abandon();
        staging.abandon();
        out.abandon();
        if (waited == VK_TIMEOUT) {
            return report.error("vkWaitForFences (texture upload) timed out after " +
                                std::to_string(kFenceTimeoutNs / 1000000000) + " s");
        }
        return report.check(waited, "vkWaitForFences");
    }

    auto view_info = vk_struct<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    view_info.image = raw_image;
    view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view_info.format = kTextureFormat;
    view_info.components = {VK_COMPONENT_SWIZZLE_IDENTITY, VK_COMPONENT_SWIZZLE_IDENTITY,
                            VK_COMPONENT_SWIZZLE_IDENTITY, VK_COMPONENT_SWIZZLE_IDENTITY};
    view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView raw_view = VK_NULL_HANDLE;
    if (!report.check(vkCreateImageView(dev, &view_info, nullptr, &raw_view),
                      "vkCreateImageView")) {
        return false;
    }
    out.view = {dev, raw_view, vkDestroyImageView};
    return true;
}

// Bounds the cache: past kMaxCachedImages, every image the current run does not bind is
// destroyed (earlier runs have finished: each waits for its fence).
void VulkanRunner::Impl::trim_images(const std::vector<const CachedImage*>& keep) {
    if (image_count <= kMaxCachedImages) return;
    for (auto bucket = images.begin(); bucket != images.end();) {
        auto& list = bucket->second;
        for (auto it = list.begin(); it != list.end();) {
            if (std::find(keep.begin(), keep.end(), it->get()) == keep.end()) {
                it = list.erase(it);
                --image_count;
            } else {
                ++it;
            }
        }
        bucket = list.empty() ? images.erase(bucket) : std::next(bucket);
    }
}

VulkanRunner::VulkanRunner(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
VulkanRunner::~VulkanRunner() = default;

std::string VulkanRunner::device_name() const {
    return impl_->properties.deviceName;
}

bool VulkanRunner::supports_float16() const {
    return impl_->float16;
}

bool VulkanRunner::run(const std::vector<uint32_t>& spirv, const void* input,
                       std::size_t input_bytes, std::size_t count, std::vector<float>& output,
                       std::size_t output_floats_per_item, const DiagnosticConsumer& diag,
                       double* seconds, const std::vector<const Texture2D*>& textures) {
    const Reporter report(diag);
    Impl& m = *impl_;
    const VkDevice device = m.device.handle;
    if (m.lost) return report.error("Vulkan runner unusable: an earlier fence wait timed out");
    if (spirv.size() < 5 || spirv[0] != kSpirvMagic) {
        return report.error("run: not a SPIR-V module (missing magic number)");
    }
    const SpirvFacts facts = scan_spirv(spirv);
    if (facts.float64 && !m.float64) {
        return report.error("device '" + std::string(m.properties.deviceName) +
                            "' lacks shaderFloat64, which this shader needs (an fp64 variant: "
                            "choose precision=fp32)");
    }
    if (facts.float16 && !m.float16) {
        return report.error("device '" + std::string(m.properties.deviceName) +
                            "' lacks shaderFloat16 (VK_KHR_shader_float16_int8), which this "
                            "shader needs (an fp16 variant: choose precision=fp32)");
    }
    if (facts.max_binding >= static_cast<int64_t>(kFirstTextureBinding + textures.size())) {
        return report.error("run: the shader declares binding " +
                            std::to_string(facts.max_binding) + " but " +
                            std::to_string(textures.size()) +
                            " texture(s) were given (texture k is binding 2 + k)");
    }
    if (textures.size() > m.properties.limits.maxPerStageDescriptorSampledImages ||
        textures.size() > m.properties.limits.maxPerStageDescriptorSamplers) {
        return report.error("run: " + std::to_string(textures.size()) +
                            " textures exceed the device's per-stage sampler limit");
    }
    for (std::size_t k = 0; k < textures.size(); ++k) {
        if (!textures[k]) return report.error("run: texture " + std::to_string(k) + " is null");
    }
    if (input_bytes > 0 && input == nullptr) return report.error("run: input is null");
    if (count > std::numeric_limits<uint32_t>::max()) {
        return report.error("run: count " + std::to_string(count) +
                            " exceeds the uint push constant");
    }
    // maxStorageBufferRange bounds what one descriptor can address (VkPhysicalDeviceLimits).
    const uint64_t range_limit = m.properties.limits.maxStorageBufferRange;
    const uint64_t output_floats = static_cast<uint64_t>(count) * output_floats_per_item;
    if (output_floats_per_item != 0 && output_floats / output_floats_per_item != count) {
        return report.error("run: output size overflows");
    }
    if (input_bytes > range_limit || output_floats * sizeof(float) > range_limit) {
        return report.error("run: buffer larger than maxStorageBufferRange (" +
                            std::to_string(range_limit) + " bytes); split the input");
    }

    const uint32_t texture_count = static_cast<uint32_t>(textures.size());
    const Impl::CachedPipeline* pipeline = m.pipeline_for(spirv, texture_count, report);
    if (!pipeline) return false;
    const Impl::Layout* layout = m.layout_for(texture_count, report);
    if (!layout) return false;
    // Tables first (cached, each uploaded once and waited for): not part of `seconds`.
    std::vector<const Impl::CachedImage*> images;
    if (texture_count > 0 && !m.make_sampler(report)) return false;
    for (const Texture2D* t : textures) {
        images.push_back(m.image_for(*t, report));
        if (!images.back()) return false;
    }
    m.trim_images(images);
    if (count == 0) {
        output.clear();
        if (seconds) *seconds = 0.0;
        return true;
    }

    // Zero-sized buffers are invalid (VkBufferCreateInfo valid usage), so keep one word at least.
    HostBuffer in_buffer, out_buffer;
    const VkDeviceSize out_bytes = output_floats * sizeof(float);
    if (!m.create_buffer(std::max<VkDeviceSize>(input_bytes, 4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                         in_buffer, report) ||
        !m.create_buffer(std::max<VkDeviceSize>(out_bytes, 4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                         out_buffer, report)) {
        return false;
    }

    // Upload; host writes before vkQueueSubmit are visible to the device without a barrier
    // (Vulkan spec, "Host Write Ordering Guarantees").
    void* mapped = nullptr;
    if (!report.check(vkMapMemory(device, in_buffer.memory.get(), 0, VK_WHOLE_SIZE, 0, &mapped),
                      "vkMapMemory")) {
        return false;
    }
    if (input_bytes > 0) std::memcpy(mapped, input, input_bytes);
    vkUnmapMemory(device, in_buffer.memory.get());
    // Outputs the shader never writes read back as NaN rather than a plausible 0.
    if (!report.check(vkMapMemory(device, out_buffer.memory.get(), 0, VK_WHOLE_SIZE, 0, &mapped),
                      "vkMapMemory")) {
        return false;
    }
    std::fill_n(static_cast<float*>(mapped), out_bytes / sizeof(float),
                std::numeric_limits<float>::quiet_NaN());
    vkUnmapMemory(device, out_buffer.memory.get());

    // Descriptors: binding 0 = input, binding 1 = output, 2 + k = textures[k].
    VkDescriptorPoolSize pool_sizes[2] = {
        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2},
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, texture_count}};
    auto pool_info =
        vk_struct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = texture_count > 0 ? 2 : 1;
    pool_info.pPoolSizes = pool_sizes;
    VkDescriptorPool raw_pool = VK_NULL_HANDLE;
    if (!report.check(vkCreateDescriptorPool(device, &pool_info, nullptr, &raw_pool),
                      "vkCreateDescriptorPool")) {
        return false;
    }
    DeviceHandle<VkDescriptorPool> descriptor_pool(device, raw_pool, vkDestroyDescriptorPool);
    const VkDescriptorSetLayout set_layout = layout->set.get();
    auto set_info =
        vk_struct<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    set_info.descriptorPool = descriptor_pool.get();
    set_info.descriptorSetCount = 1;
    set_info.pSetLayouts = &set_layout;
    VkDescriptorSet set = VK_NULL_HANDLE;  // freed with its pool
    if (!report.check(vkAllocateDescriptorSets(device, &set_info, &set),
                      "vkAllocateDescriptorSets")) {
        return false;
    }
    const VkDescriptorBufferInfo buffer_infos[2] = {
        {in_buffer.buffer.get(), 0, VK_WHOLE_SIZE},
        {out_buffer.buffer.get(), 0, VK_WHOLE_SIZE},
    };
    std::vector<VkDescriptorImageInfo> image_infos(texture_count);
    for (uint32_t k = 0; k < texture_count; ++k) {
        image_infos[k] = {m.sampler.get(), images[k]->view.get(),
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    }
    std::vector<VkWriteDescriptorSet> writes(kFirstTextureBinding + texture_count);
    for (uint32_t i = 0; i < writes.size(); ++i) {
        writes[i] = vk_struct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        writes[i].dstSet = set;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        if (i < kFirstTextureBinding) {
            writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
            writes[i].pBufferInfo = &buffer_infos[i];
        } else {
            writes[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
            writes[i].pImageInfo = &image_infos[i - kFirstTextureBinding];
        }
    }
    vkUpdateDescriptorSets(device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);

    DeviceHandle<VkCommandPool> command_pool;
    VkCommandBuffer commands = VK_NULL_HANDLE;  // freed with its pool
    if (!one_time_commands(device, m.queue_family, report, command_pool, commands)) return false;

    // Record: one dispatch per batch, each batch told its first item through `base`.
    auto begin = vk_struct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    if (!report.check(vkBeginCommandBuffer(commands, &begin), "vkBeginCommandBuffer")) return false;
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline->pipeline.get());
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout->pipeline.get(), 0, 1,
                            &set, 0, nullptr);
    const uint64_t max_groups =
        std::min<uint64_t>(m.properties.limits.maxComputeWorkGroupCount[0], 65535);
    const uint64_t batch_items = max_groups * kLocalSizeX;
    for (uint64_t base = 0; base < count; base += batch_items) {
        const uint64_t items = std::min<uint64_t>(batch_items, count - base);
        const PushConstants push{static_cast<uint32_t>(count), static_cast<uint32_t>(base)};
        vkCmdPushConstants(commands, layout->pipeline.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                           sizeof(push), &push);
        vkCmdDispatch(commands, static_cast<uint32_t>((items + kLocalSizeX - 1) / kLocalSizeX), 1,
                      1);
    }
    // Shader writes must be made available to host reads after the fence (spec, "Host access").
    auto to_host = vk_struct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    to_host.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                         0, 1, &to_host, 0, nullptr, 0, nullptr);
    if (!report.check(vkEndCommandBuffer(commands), "vkEndCommandBuffer")) return false;

    auto fence_info = vk_struct<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    VkFence raw_fence = VK_NULL_HANDLE;
    if (!report.check(vkCreateFence(device, &fence_info, nullptr, &raw_fence), "vkCreateFence")) {
        return false;
    }
    DeviceHandle<VkFence> fence(device, raw_fence, vkDestroyFence);

    // Submit and wait: the only part that `seconds` measures.
    auto submit = vk_struct<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    const auto start = std::chrono::steady_clock::now();
    if (!report.check(vkQueueSubmit(m.queue, 1, &submit, fence.get()), "vkQueueSubmit")) {
        return false;
    }
    const VkResult waited = vkWaitForFences(device, 1, &raw_fence, VK_TRUE, kFenceTimeoutNs);
    const auto stop = std::chrono::steady_clock::now();
    if (waited != VK_SUCCESS) {
        // Submitted work may still be running: leak rather than destroy objects in use.
        m.lost = true;
        fence.abandon();
        command_pool.abandon();
        descriptor_pool.abandon();
        in_buffer.abandon();
        out_buffer.abandon();
        if (waited == VK_TIMEOUT) {
            return report.error("vkWaitForFences timed out after " +
                                std::to_string(kFenceTimeoutNs / 1000000000) + " s");
        }
        return report.check(waited, "vkWaitForFences");
    }

    // Read back (coherent memory: no vkInvalidateMappedMemoryRanges needed).
    if (!report.check(vkMapMemory(device, out_buffer.memory.get(), 0, VK_WHOLE_SIZE, 0, &mapped),
                      "vkMapMemory")) {
        return false;
    }
    const float* results = static_cast<const float*>(mapped);
    std::vector<float> read(results, results + output_floats);
    vkUnmapMemory(device, out_buffer.memory.get());
    output.swap(read);
    if (seconds) *seconds = std::chrono::duration<double>(stop - start).count();
    return true;
}

}  // namespace arealight
