// Renders scene.json headless on Vulkan with render.comp (which includes the arealight library
// generated from the same scene) and writes a PNG. The host uploads the camera, lights,
// materials and objects as they are in the file, and the library's tables as its manifest
// says: everything per pixel happens in the shader.
//   consumer [OUT.png] [--scene FILE] [--spirv FILE] [--tables DIR] [--size W H]
// Exit codes: 0 ok, 1 bad scene, tables or arguments, 3 Vulkan or write failure, 4 a uniform image.
#include <png.h>
#include <vulkan/vulkan.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "tables.hpp"

namespace {

// The shader's std430 records (render.comp), vec3 values padded to vec4.
struct Vec4 {
    float x = 0, y = 0, z = 0, w = 0;
};
struct Frame {
    Vec4 eye, forward, right, up;
    int32_t width = 0, height = 0, light_count = 0, object_count = 0;
};
struct Light {
    Vec4 data[8];  // render.comp's Light: polygon vertices, or centre and axes / radius
    float intensity = 1;
    int32_t type = 0, count = 0, two_sided = 0;
};
struct Material {
    int32_t dist = 0;
    float param = 0, f0 = 1, pad0 = 0;
};
struct Object {
    Vec4 a, b, albedo;
    int32_t type = 0, material = 0, pad0 = 0, pad1 = 0;
};
static_assert(sizeof(Light) == 144 && sizeof(Material) == 16 && sizeof(Object) == 64,
              "records must match render.comp's std430 layout");

struct BadScene : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Scene {
    Frame frame;
    std::vector<Light> lights;
    std::vector<Material> materials;
    std::vector<Object> objects;
};

using json = nlohmann::json;

Vec4 vec(const json& j, const std::string& where, float w = 0) {
    if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() ||
        !j[2].is_number())
        throw BadScene(where + ": expected [x, y, z]");
    return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>(), w};
}

const json& field(const json& j, const char* name, const std::string& where) {
    if (!j.contains(name)) throw BadScene(where + ": field '" + name + "' is missing");
    return j.at(name);
}

Vec4 normalized(Vec4 a) {
    const float l = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    return {a.x / l, a.y / l, a.z / l, 0};
}
Vec4 cross(Vec4 a, Vec4 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x, 0};
}
Vec4 scaled(Vec4 a, float s) {
    return {a.x * s, a.y * s, a.z * s, 0};
}

float dot(Vec4 a, Vec4 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// Reads the contract's fields (lights, materials) and the ones `arealight render` reads too
// (camera, objects, light intensity; include/arealight/render_scene.hpp), which arealight
// generate ignores.
Scene read_scene(const std::string& path, int width, int height) {
    std::ifstream in(path);
    if (!in) throw BadScene(path + ": cannot read");
    json j;
    try {
        j = json::parse(in);
    } catch (const json::exception& e) {
        throw BadScene(path + ": " + e.what());
    }
    Scene s;
    for (std::size_t i = 0; i < field(j, "lights", path).size(); ++i) {
        const json& l = j["lights"][i];
        const std::string where = path + ": lights[" + std::to_string(i) + "]";
        const std::string type = field(l, "type", where);
        Light light;
        if (type == "polygon") {
            const json& vs = field(l, "vertices", where);
            if (!vs.is_array() || vs.size() < 3 || vs.size() > 8)
                throw BadScene(where + ": field 'vertices': 3 to 8 points");
            light.type = 0;
            light.count = static_cast<int32_t>(vs.size());
            for (std::size_t k = 0; k < vs.size(); ++k)
                light.data[k] = vec(vs[k], where + ".vertices[" + std::to_string(k) + "]");
        } else if (type == "disk") {
            light.type = 1;
            light.data[0] = vec(field(l, "center", where), where + ".center");
            light.data[1] = vec(field(l, "u", where), where + ".u");
            light.data[2] = vec(field(l, "v", where), where + ".v");
        } else if (type == "sphere") {
            light.type = 2;
            const json& radius = field(l, "radius", where);
            if (!radius.is_number() || !(radius.get<float>() > 0))
                throw BadScene(where + ": field 'radius': a positive number");
            light.data[0] = vec(field(l, "center", where), where + ".center", radius.get<float>());
        } else if (type == "ellipsoid") {
            light.type = 3;
            light.data[0] = vec(field(l, "center", where), where + ".center");
            const json& axes = field(l, "axes", where);
            if (!axes.is_array() || axes.size() != 3)
                throw BadScene(where + ": field 'axes': three semi-axis vectors");
            for (std::size_t k = 0; k < 3; ++k)
                light.data[k + 1] = vec(axes[k], where + ".axes[" + std::to_string(k) + "]");
        } else {
            throw BadScene(where + ": field 'type': '" + type +
                           "' is not polygon, disk, sphere or ellipsoid");
        }
        light.two_sided = l.value("two_sided", false) ? 1 : 0;
        light.intensity = l.value("intensity", 1.0f);
        s.lights.push_back(light);
    }
    for (std::size_t i = 0; i < field(j, "materials", path).size(); ++i) {
        const json& m = j["materials"][i];
        const std::string where = path + ": materials[" + std::to_string(i) + "]";
        Material mat;
        const std::string dist = field(m, "distribution", where);
        // render.comp's kGgx, kPhong, kBeckmann, kBlinn; the parameter as CONTRACT.md 7 names it.
        const char* const names[] = {"ggx", "phong", "beckmann", "blinn"};
        const char* const params[] = {"alpha", "exponent", "alpha", "exponent"};
        int k = 0;
        while (k < 4 && dist != names[k]) ++k;
        if (k == 4)
            throw BadScene(where + ": field 'distribution': '" + dist +
                           "' is not ggx, phong, beckmann or blinn");
        mat.dist = k;
        mat.param = field(m, params[k], where).get<float>();
        mat.f0 = m.value("f0", 1.0f);
        s.materials.push_back(mat);
    }
    for (std::size_t i = 0; i < field(j, "objects", path).size(); ++i) {
        const json& o = j["objects"][i];
        const std::string where = path + ": objects[" + std::to_string(i) + "]";
        Object ob;
        const std::string type = field(o, "type", where);
        if (type == "plane") {
            ob.type = 0;
            ob.a = normalized(vec(field(o, "normal", where), where + ".normal"));
            ob.a.w = dot(ob.a, vec(field(o, "point", where), where + ".point"));
        } else if (type == "sphere") {
            ob.type = 1;
            ob.a = vec(field(o, "center", where), where + ".center",
                       field(o, "radius", where).get<float>());
        } else if (type == "box") {
            ob.type = 2;
            ob.a = vec(field(o, "min", where), where + ".min");
            ob.b = vec(field(o, "max", where), where + ".max");
        } else {
            throw BadScene(where + ": field 'type': plane, sphere or box");
        }
        ob.albedo = vec(field(o, "albedo", where), where + ".albedo");
        ob.material = field(o, "material", where).get<int32_t>();
        if (ob.material < 0 || ob.material >= static_cast<int32_t>(s.materials.size()))
            throw BadScene(where + ": field 'material': no such material");
        s.objects.push_back(ob);
    }
    // The camera's image plane at distance 1: the shader adds ndc-scaled right and up.
    const json& cam = field(j, "camera", path);
    const Vec4 eye = vec(field(cam, "eye", path + ": camera"), path + ": camera.eye");
    const Vec4 target = vec(field(cam, "target", path + ": camera"), path + ": camera.target");
    const Vec4 up = vec(field(cam, "up", path + ": camera"), path + ": camera.up");
    const float half =
        std::tan(field(cam, "fov_deg", path + ": camera").get<float>() * 3.14159265f / 360.0f);
    const Vec4 forward = normalized({target.x - eye.x, target.y - eye.y, target.z - eye.z, 0});
    const Vec4 right = normalized(cross(forward, up));
    s.frame.eye = eye;
    s.frame.forward = forward;
    s.frame.right = scaled(right, half * static_cast<float>(width) / static_cast<float>(height));
    s.frame.up = scaled(cross(right, forward), half);
    s.frame.width = width;
    s.frame.height = height;
    s.frame.light_count = static_cast<int32_t>(s.lights.size());
    s.frame.object_count = static_cast<int32_t>(s.objects.size());
    return s;
}

void check(VkResult r, const char* what) {
    if (r != VK_SUCCESS)
        throw std::runtime_error(std::string(what) + ": VkResult " + std::to_string(r));
}

// The device and everything created on it; destroyed in reverse order of creation.
class Gpu {
  public:
    Gpu() {
        VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
        app.pApplicationName = "arealight consumer";
        app.apiVersion = VK_API_VERSION_1_1;
        VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
        ici.pApplicationInfo = &app;
        check(vkCreateInstance(&ici, nullptr, &instance_), "vkCreateInstance");
        uint32_t count = 1;
        VkResult r = vkEnumeratePhysicalDevices(instance_, &count, &physical_);
        if ((r != VK_SUCCESS && r != VK_INCOMPLETE) || count == 0)
            throw std::runtime_error("no Vulkan device (set VK_ICD_FILENAMES to lavapipe's ICD?)");
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(physical_, &props);
        device_name_ = props.deviceName;
        uint32_t families = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(physical_, &families, nullptr);
        std::vector<VkQueueFamilyProperties> fam(families);
        vkGetPhysicalDeviceQueueFamilyProperties(physical_, &families, fam.data());
        family_ = families;
        for (uint32_t i = 0; i < families; ++i)
            if (fam[i].queueFlags & VK_QUEUE_COMPUTE_BIT) family_ = std::min(family_, i);
        if (family_ == families) throw std::runtime_error("no compute queue");
        const float priority = 1;
        VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        qci.queueFamilyIndex = family_;
        qci.queueCount = 1;
        qci.pQueuePriorities = &priority;
        // The library's exact methods compute in fp64 where the device has it.
        VkPhysicalDeviceFeatures supported, enabled{};
        vkGetPhysicalDeviceFeatures(physical_, &supported);
        enabled.shaderFloat64 = supported.shaderFloat64;
        enabled.shaderInt64 = supported.shaderInt64;
        VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        dci.queueCreateInfoCount = 1;
        dci.pQueueCreateInfos = &qci;
        dci.pEnabledFeatures = &enabled;
        check(vkCreateDevice(physical_, &dci, nullptr, &device_), "vkCreateDevice");
        vkGetDeviceQueue(device_, family_, 0, &queue_);
    }
    ~Gpu() {
        if (device_) vkDestroyDevice(device_, nullptr);
        if (instance_) vkDestroyInstance(instance_, nullptr);
    }
    Gpu(const Gpu&) = delete;
    Gpu& operator=(const Gpu&) = delete;

    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t family() const { return family_; }
    const std::string& name() const { return device_name_; }
    VkPhysicalDevice physical() const { return physical_; }

    // The first memory type of `allowed` with every flag of `want`. Host-visible and
    // host-coherent memory: writes are seen by the device at submit and the device's writes
    // by the host after the fence, without flush or invalidate calls.
    uint32_t memory_type(uint32_t allowed, VkMemoryPropertyFlags want) const {
        VkPhysicalDeviceMemoryProperties mp;
        vkGetPhysicalDeviceMemoryProperties(physical_, &mp);
        for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
            if ((allowed & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
        throw std::runtime_error("no memory type with flags " + std::to_string(want));
    }
    uint32_t host_memory_type(uint32_t allowed) const {
        return memory_type(
            allowed, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    }

  private:
    VkInstance instance_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t family_ = 0;
    std::string device_name_;
};

// A storage buffer in mapped host-coherent memory.
class Buffer {
  public:
    Buffer(const Gpu& gpu, VkDeviceSize size) : device_(gpu.device()), size_(size) {
        VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        bci.size = size;
        // Storage for the shader, transfer source for the table uploads.
        bci.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
        check(vkCreateBuffer(device_, &bci, nullptr, &buffer_), "vkCreateBuffer");
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(device_, buffer_, &req);
        VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        mai.allocationSize = req.size;
        mai.memoryTypeIndex = gpu.host_memory_type(req.memoryTypeBits);
        check(vkAllocateMemory(device_, &mai, nullptr, &memory_), "vkAllocateMemory");
        check(vkBindBufferMemory(device_, buffer_, memory_, 0), "vkBindBufferMemory");
        check(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
    }
    template <class T>
    Buffer(const Gpu& gpu, const std::vector<T>& data)
        : Buffer(gpu, std::max<VkDeviceSize>(sizeof(T), sizeof(T) * data.size())) {
        std::memcpy(mapped_, data.data(), sizeof(T) * data.size());
    }
    ~Buffer() {
        if (memory_) vkFreeMemory(device_, memory_, nullptr);  // unmaps too
        if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    }
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    const void* data() const { return mapped_; }

  private:
    VkDevice device_;
    VkDeviceSize size_;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    void* mapped_ = nullptr;
};

// One of the library's tables as the manifest says to sample it: an R32G32B32A32_SFLOAT image
// of one level in device memory, uploaded through a staging buffer, with a sampler that
// filters linearly and clamps to the edge in normalized coordinates.
class SampledImage {
  public:
    SampledImage(const Gpu& gpu, const Table& table) : device_(gpu.device()) {
        const VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
        VkFormatProperties fp;
        vkGetPhysicalDeviceFormatProperties(gpu.physical(), format, &fp);
        if (!(fp.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
            throw std::runtime_error(table.sampler + ": the device cannot filter RGBA32F linearly");
        const VkExtent3D extent{uint32_t(table.width), uint32_t(table.height), 1};
        VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        ici.imageType = VK_IMAGE_TYPE_2D;
        ici.format = format;
        ici.extent = extent;
        ici.mipLevels = 1;
        ici.arrayLayers = 1;
        ici.samples = VK_SAMPLE_COUNT_1_BIT;
        ici.tiling = VK_IMAGE_TILING_OPTIMAL;
        ici.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        check(vkCreateImage(device_, &ici, nullptr, &image_), "vkCreateImage");
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(device_, image_, &req);
        VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        mai.allocationSize = req.size;
        mai.memoryTypeIndex =
            gpu.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        check(vkAllocateMemory(device_, &mai, nullptr, &memory_), "vkAllocateMemory");
        check(vkBindImageMemory(device_, image_, memory_, 0), "vkBindImageMemory");
        upload(gpu, table, extent);

        VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vci.image = image_;
        vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vci.format = format;
        vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        check(vkCreateImageView(device_, &vci, nullptr, &view_), "vkCreateImageView");
        VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        sci.magFilter = VK_FILTER_LINEAR;
        sci.minFilter = VK_FILTER_LINEAR;
        sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        sci.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        sci.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        sci.maxLod = 0;
        check(vkCreateSampler(device_, &sci, nullptr, &sampler_), "vkCreateSampler");
    }
    ~SampledImage() {
        if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
        if (view_) vkDestroyImageView(device_, view_, nullptr);
        if (image_) vkDestroyImage(device_, image_, nullptr);
        if (memory_) vkFreeMemory(device_, memory_, nullptr);
    }
    SampledImage(const SampledImage&) = delete;
    SampledImage& operator=(const SampledImage&) = delete;

    VkDescriptorImageInfo descriptor() const {
        return {sampler_, view_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    }

  private:
    // Staging buffer -> image, then the layout the shader samples in; waits for the queue.
    void upload(const Gpu& gpu, const Table& table, VkExtent3D extent) {
        const Buffer staging(gpu, table.rgba);
        VkCommandPool pool = VK_NULL_HANDLE;
        VkCommandPoolCreateInfo cpci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        cpci.queueFamilyIndex = gpu.family();
        check(vkCreateCommandPool(device_, &cpci, nullptr, &pool), "vkCreateCommandPool");
        VkCommandBuffer cb = VK_NULL_HANDLE;
        VkCommandBufferAllocateInfo cbai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        cbai.commandPool = pool;
        cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        cbai.commandBufferCount = 1;
        VkResult r = vkAllocateCommandBuffers(device_, &cbai, &cb);
        if (r == VK_SUCCESS) {
            VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
            begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
            vkBeginCommandBuffer(cb, &begin);
            VkImageMemoryBarrier to_copy{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
            to_copy.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            to_copy.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
            to_copy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            to_copy.srcQueueFamilyIndex = to_copy.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            to_copy.image = image_;
            to_copy.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                                 VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1,
                                 &to_copy);
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = extent;
            vkCmdCopyBufferToImage(cb, staging.handle(), image_,
                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            VkImageMemoryBarrier to_read = to_copy;
            to_read.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            to_read.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
            to_read.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            to_read.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
            vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT,
                                 VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0, nullptr, 1,
                                 &to_read);
            r = vkEndCommandBuffer(cb);
            if (r == VK_SUCCESS) {
                VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
                submit.commandBufferCount = 1;
                submit.pCommandBuffers = &cb;
                r = vkQueueSubmit(gpu.queue(), 1, &submit, VK_NULL_HANDLE);
                if (r == VK_SUCCESS) r = vkQueueWaitIdle(gpu.queue());
            }
        }
        vkDestroyCommandPool(device_, pool, nullptr);  // frees cb
        check(r, "uploading a table");
    }

    VkDevice device_;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

// A table's image at its binding in set 0.
struct ImageBinding {
    uint32_t binding;
    const SampledImage* image;
};

// The compute pipeline over N storage buffers at set 0, bindings 0..N-1, and the sampled
// images at their bindings, with one command buffer to record its dispatch into.
class ComputePipeline {
  public:
    ComputePipeline(const Gpu& gpu, const std::vector<uint32_t>& spirv,
                    const std::vector<const Buffer*>& buffers,
                    const std::vector<ImageBinding>& images)
        : device_(gpu.device()) {
        VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        smci.codeSize = spirv.size() * sizeof(uint32_t);
        smci.pCode = spirv.data();
        check(vkCreateShaderModule(device_, &smci, nullptr, &module_), "vkCreateShaderModule");

        std::vector<VkDescriptorSetLayoutBinding> bindings(buffers.size());
        for (uint32_t i = 0; i < bindings.size(); ++i)
            bindings[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
                           nullptr};
        for (const ImageBinding& image : images)
            bindings.push_back({image.binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
        VkDescriptorSetLayoutCreateInfo dslci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        dslci.bindingCount = static_cast<uint32_t>(bindings.size());
        dslci.pBindings = bindings.data();
        check(vkCreateDescriptorSetLayout(device_, &dslci, nullptr, &set_layout_),
              "vkCreateDescriptorSetLayout");
        VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        plci.setLayoutCount = 1;
        plci.pSetLayouts = &set_layout_;
        check(vkCreatePipelineLayout(device_, &plci, nullptr, &layout_), "vkCreatePipelineLayout");
        VkComputePipelineCreateInfo cpci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        cpci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        cpci.stage.module = module_;
        cpci.stage.pName = "main";
        cpci.layout = layout_;
        check(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &cpci, nullptr, &pipeline_),
              "vkCreateComputePipelines");

        const VkDescriptorPoolSize pool_sizes[2] = {
            {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, static_cast<uint32_t>(buffers.size())},
            {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, static_cast<uint32_t>(images.size())}};
        VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        dpci.maxSets = 1;
        dpci.poolSizeCount = images.empty() ? 1 : 2;
        dpci.pPoolSizes = pool_sizes;
        check(vkCreateDescriptorPool(device_, &dpci, nullptr, &pool_), "vkCreateDescriptorPool");
        VkDescriptorSetAllocateInfo dsai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        dsai.descriptorPool = pool_;
        dsai.descriptorSetCount = 1;
        dsai.pSetLayouts = &set_layout_;
        check(vkAllocateDescriptorSets(device_, &dsai, &set_), "vkAllocateDescriptorSets");
        std::vector<VkDescriptorBufferInfo> infos;
        for (const Buffer* b : buffers) infos.push_back({b->handle(), 0, VK_WHOLE_SIZE});
        std::vector<VkWriteDescriptorSet> writes(buffers.size());
        for (uint32_t i = 0; i < writes.size(); ++i) {
            writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
            writes[i].dstSet = set_;
            writes[i].dstBinding = i;
            writes[i].descriptorCount = 1;
            writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
            writes[i].pBufferInfo = &infos[i];
        }
        std::vector<VkDescriptorImageInfo> image_infos;
        for (const ImageBinding& image : images) image_infos.push_back(image.image->descriptor());
        for (std::size_t k = 0; k < images.size(); ++k) {
            VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
            w.dstSet = set_;
            w.dstBinding = images[k].binding;
            w.descriptorCount = 1;
            w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
            w.pImageInfo = &image_infos[k];
            writes.push_back(w);
        }
        vkUpdateDescriptorSets(device_, static_cast<uint32_t>(writes.size()), writes.data(), 0,
                               nullptr);

        VkCommandPoolCreateInfo cpoci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        cpoci.queueFamilyIndex = gpu.family();
        check(vkCreateCommandPool(device_, &cpoci, nullptr, &commands_), "vkCreateCommandPool");
        VkCommandBufferAllocateInfo cbai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        cbai.commandPool = commands_;
        cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        cbai.commandBufferCount = 1;
        check(vkAllocateCommandBuffers(device_, &cbai, &command_buffer_),
              "vkAllocateCommandBuffers");
        VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        check(vkCreateFence(device_, &fci, nullptr, &fence_), "vkCreateFence");
    }
    ~ComputePipeline() {
        if (fence_) vkDestroyFence(device_, fence_, nullptr);
        if (commands_) vkDestroyCommandPool(device_, commands_, nullptr);
        if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);
        if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
        if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
        if (set_layout_) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
        if (module_) vkDestroyShaderModule(device_, module_, nullptr);
    }
    ComputePipeline(const ComputePipeline&) = delete;
    ComputePipeline& operator=(const ComputePipeline&) = delete;

    // Records and runs one dispatch of groups_x * groups_y workgroups and waits for it.
    void run(VkQueue queue, uint32_t groups_x, uint32_t groups_y) {
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        check(vkBeginCommandBuffer(command_buffer_, &begin), "vkBeginCommandBuffer");
        // Upload: the host wrote the scene into coherent memory before the submit, which
        // makes those writes visible to the device (no barrier needed on this side).
        vkCmdBindPipeline(command_buffer_, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
        vkCmdBindDescriptorSets(command_buffer_, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1,
                                &set_, 0, nullptr);
        // Dispatch: one invocation per pixel.
        vkCmdDispatch(command_buffer_, groups_x, groups_y, 1);
        // Barrier: the shader's pixel writes made available to host reads.
        VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        to_host.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(command_buffer_, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                             VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr, 0, nullptr);
        check(vkEndCommandBuffer(command_buffer_), "vkEndCommandBuffer");
        // Submit and wait on the fence; the memory is coherent, so no invalidate before reading.
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &command_buffer_;
        check(vkQueueSubmit(queue, 1, &submit, fence_), "vkQueueSubmit");
        check(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    }

  private:
    VkDevice device_;
    VkShaderModule module_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    VkCommandPool commands_ = VK_NULL_HANDLE;
    VkCommandBuffer command_buffer_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
};

std::vector<uint32_t> read_spirv(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) throw std::runtime_error(path + ": cannot read");
    if (bytes.empty() || bytes.size() % 4 != 0) throw std::runtime_error(path + ": not SPIR-V");
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    return words;
}

// The bindings of the module's UniformConstant variables (its sampled images): what the
// tables folder must provide, read from the SPIR-V's OpVariable and OpDecorate Binding.
std::set<uint32_t> sampler_bindings(const std::vector<uint32_t>& words) {
    constexpr uint32_t kOpDecorate = 71, kOpVariable = 59, kBinding = 33, kUniformConstant = 0;
    std::set<uint32_t> uniform_constants;
    std::vector<std::pair<uint32_t, uint32_t>> bindings;  // (id, binding)
    for (std::size_t i = 5; i < words.size();) {
        const uint32_t count = words[i] >> 16, op = words[i] & 0xffff;
        if (count == 0 || i + count > words.size()) throw std::runtime_error("malformed SPIR-V");
        if (op == kOpVariable && count >= 4 && words[i + 3] == kUniformConstant)
            uniform_constants.insert(words[i + 2]);
        if (op == kOpDecorate && count >= 4 && words[i + 2] == kBinding)
            bindings.emplace_back(words[i + 1], words[i + 3]);
        i += count;
    }
    std::set<uint32_t> out;
    for (const auto& [id, binding] : bindings)
        if (uniform_constants.count(id)) out.insert(binding);
    return out;
}

// RGBA8 pixels (alpha ignored) to an 8-bit RGB PNG, through a temporary file renamed over
// `path` so that a failed write leaves no partial image.
void write_png(const std::string& path, const uint32_t* rgba, int width, int height) {
    const std::string temp = path + ".tmp";
    FILE* file = std::fopen(temp.c_str(), "wb");
    if (!file) throw std::runtime_error(path + ": cannot write");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    std::vector<png_byte> row(static_cast<std::size_t>(width) * 3);
    // libpng reports errors by longjmp: nothing with a destructor may be created below.
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        std::fclose(file);
        std::remove(temp.c_str());
        throw std::runtime_error(path + ": libpng failed");
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const uint32_t p = rgba[y * width + x];
            for (int c = 0; c < 3; ++c) row[x * 3 + c] = static_cast<png_byte>(p >> (8 * c));
        }
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    const bool flushed = std::fclose(file) == 0;
    if (!flushed || std::rename(temp.c_str(), path.c_str()) != 0) {
        std::remove(temp.c_str());
        throw std::runtime_error(path + ": cannot write");
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::string out = "consumer.png", scene_path = CONSUMER_SCENE, spirv_path = CONSUMER_SPIRV,
                tables_dir = CONSUMER_TABLES;
    int width = 320, height = 240;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--scene" && i + 1 < argc) {
            scene_path = argv[++i];
        } else if (a == "--spirv" && i + 1 < argc) {
            spirv_path = argv[++i];
        } else if (a == "--tables" && i + 1 < argc) {
            tables_dir = argv[++i];
        } else if (a == "--size" && i + 2 < argc) {
            width = std::atoi(argv[++i]);
            height = std::atoi(argv[++i]);
        } else if (!a.empty() && a[0] != '-') {
            out = a;
        } else {
            std::fprintf(stderr,
                         "usage: consumer [OUT.png] [--scene FILE] [--spirv FILE] "
                         "[--tables DIR] [--size W H]\n");
            return a == "--help" ? 0 : 1;
        }
    }
    if (width < 1 || height < 1 || width > 8192 || height > 8192) {
        std::fprintf(stderr, "consumer: --size: 1 to 8192 pixels each way\n");
        return 1;
    }
    try {
        const Scene scene = read_scene(scene_path, width, height);
        const std::vector<Table> tables = read_tables(tables_dir);
        Gpu gpu;
        // Upload: every record as the shader declares it, in host-coherent buffers.
        const Buffer frame(gpu, std::vector<Frame>{scene.frame});
        const Buffer lights(gpu, scene.lights);
        const Buffer materials(gpu, scene.materials);
        const Buffer objects(gpu, scene.objects);
        const Buffer pixels(gpu, VkDeviceSize(width) * height * sizeof(uint32_t));
        // The library's tables where its manifest puts them: binding AREALIGHT_BINDING +
        // binding_offset, render.comp defining AREALIGHT_BINDING after its five buffers.
        constexpr uint32_t kArealightBinding = 5;
        std::vector<std::unique_ptr<SampledImage>> images;
        std::vector<ImageBinding> image_bindings;
        for (const Table& t : tables) {
            images.push_back(std::make_unique<SampledImage>(gpu, t));
            image_bindings.push_back(
                {kArealightBinding + static_cast<uint32_t>(t.binding_offset), images.back().get()});
        }
        // Every table the shader samples must come from the folder, and nothing else: a
        // folder of another scene's library would leave a sampler unbound.
        const std::vector<uint32_t> spirv = read_spirv(spirv_path);
        std::set<uint32_t> given;
        for (const ImageBinding& b : image_bindings) given.insert(b.binding);
        const std::set<uint32_t> wanted = sampler_bindings(spirv);
        for (uint32_t b : wanted)
            if (!given.count(b))
                throw BadTables(tables_dir + "/tables.json: " + spirv_path + " samples binding " +
                                std::to_string(b) + ", which no table of the folder takes (binding_offset " +
                                std::to_string(b - kArealightBinding) +
                                "); is it the tables folder of this shader's library?");
        for (uint32_t b : given)
            if (!wanted.count(b))
                throw BadTables(tables_dir + "/tables.json: a table takes binding " +
                                std::to_string(b) + ", which " + spirv_path +
                                " does not sample; is it the tables folder of this shader's library?");
        ComputePipeline pipeline(gpu, spirv, {&frame, &lights, &materials, &objects, &pixels},
                                 image_bindings);
        constexpr uint32_t kGroup = 8;  // render.comp's local_size_x and _y
        pipeline.run(gpu.queue(), (width + kGroup - 1) / kGroup, (height + kGroup - 1) / kGroup);
        // Read back: the fence has signalled and the memory is coherent.
        const auto* rgba = static_cast<const uint32_t*>(pixels.data());
        write_png(out, rgba, width, height);
        const std::set<uint32_t> colours(rgba, rgba + std::size_t(width) * height);
        std::printf("consumer: %s, %dx%d on %s, %zu lights, %zu tables, %zu distinct colours\n",
                    out.c_str(), width, height, gpu.name().c_str(), scene.lights.size(),
                    tables.size(), colours.size());
        // A shader that returned NaN or nothing gives one colour (or a handful): not an image.
        if (colours.size() < 64) {
            std::fprintf(stderr, "consumer: only %zu distinct colours: the render is broken\n",
                         colours.size());
            return 4;
        }
    } catch (const BadScene& e) {
        std::fprintf(stderr, "consumer: error: %s\n", e.what());
        return 1;
    } catch (const BadTables& e) {
        std::fprintf(stderr, "consumer: error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "consumer: error: %s\n", e.what());
        return 3;
    }
    return 0;
}
