// Renders scene.json headless on Vulkan with render.comp (which includes the arealight library
// generated from the same scene) and writes a PNG. The host uploads the camera, lights,
// materials and objects as they are in the file: everything per pixel happens in the shader.
//   consumer [OUT.png] [--scene FILE] [--spirv FILE] [--size W H]
// Exit codes: 0 ok, 1 bad scene or arguments, 3 Vulkan or write failure, 4 a uniform image.
#include <png.h>
#include <vulkan/vulkan.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

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
    Vec4 vertices[8];
    float intensity = 1;
    int32_t count = 0, two_sided = 0, pad0 = 0;
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
Vec4 scaled(Vec4 a, float s) { return {a.x * s, a.y * s, a.z * s, 0}; }

float dot(Vec4 a, Vec4 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

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
        if (field(l, "type", where) != "polygon")
            throw BadScene(where + ": field 'type': this example renders polygon lights only");
        const json& vs = field(l, "vertices", where);
        if (!vs.is_array() || vs.size() < 3 || vs.size() > 8)
            throw BadScene(where + ": field 'vertices': 3 to 8 points");
        Light light;
        light.count = static_cast<int32_t>(vs.size());
        for (std::size_t k = 0; k < vs.size(); ++k)
            light.vertices[k] = vec(vs[k], where + ".vertices[" + std::to_string(k) + "]");
        light.two_sided = l.value("two_sided", false) ? 1 : 0;
        light.intensity = l.value("intensity", 1.0f);
        s.lights.push_back(light);
    }
    for (std::size_t i = 0; i < field(j, "materials", path).size(); ++i) {
        const json& m = j["materials"][i];
        const std::string where = path + ": materials[" + std::to_string(i) + "]";
        Material mat;
        const std::string dist = field(m, "distribution", where);
        if (dist == "ggx") {
            mat.dist = 0;
            mat.param = field(m, "alpha", where).get<float>();
        } else if (dist == "phong") {
            mat.dist = 1;
            mat.param = field(m, "exponent", where).get<float>();
        } else {
            throw BadScene(where + ": field 'distribution': render.comp calls ggx and phong only");
        }
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
    const float half = std::tan(field(cam, "fov_deg", path + ": camera").get<float>() *
                                3.14159265f / 360.0f);
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
    if (r != VK_SUCCESS) throw std::runtime_error(std::string(what) + ": VkResult " + std::to_string(r));
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

    // Host-visible, host-coherent memory: writes are seen by the device at submit and the
    // device's writes by the host after the fence, without flush or invalidate calls.
    uint32_t host_memory_type(uint32_t allowed) const {
        VkPhysicalDeviceMemoryProperties mp;
        vkGetPhysicalDeviceMemoryProperties(physical_, &mp);
        const VkMemoryPropertyFlags want =
            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
            if ((allowed & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
        throw std::runtime_error("no host-visible coherent memory type");
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
        bci.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
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

// The compute pipeline over N storage buffers at set 0, bindings 0..N-1, and one command
// buffer to record its dispatch into.
class ComputePipeline {
  public:
    ComputePipeline(const Gpu& gpu, const std::vector<uint32_t>& spirv,
                    const std::vector<const Buffer*>& buffers)
        : device_(gpu.device()) {
        VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        smci.codeSize = spirv.size() * sizeof(uint32_t);
        smci.pCode = spirv.data();
        check(vkCreateShaderModule(device_, &smci, nullptr, &module_), "vkCreateShaderModule");

        std::vector<VkDescriptorSetLayoutBinding> bindings(buffers.size());
        for (uint32_t i = 0; i < bindings.size(); ++i)
            bindings[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
                           nullptr};
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

        const VkDescriptorPoolSize pool_size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                             static_cast<uint32_t>(buffers.size())};
        VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        dpci.maxSets = 1;
        dpci.poolSizeCount = 1;
        dpci.pPoolSizes = &pool_size;
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
    std::string out = "consumer.png", scene_path = CONSUMER_SCENE, spirv_path = CONSUMER_SPIRV;
    int width = 320, height = 240;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--scene" && i + 1 < argc) {
            scene_path = argv[++i];
        } else if (a == "--spirv" && i + 1 < argc) {
            spirv_path = argv[++i];
        } else if (a == "--size" && i + 2 < argc) {
            width = std::atoi(argv[++i]);
            height = std::atoi(argv[++i]);
        } else if (!a.empty() && a[0] != '-') {
            out = a;
        } else {
            std::fprintf(stderr,
                         "usage: consumer [OUT.png] [--scene FILE] [--spirv FILE] [--size W H]\n");
            return a == "--help" ? 0 : 1;
        }
    }
    if (width < 1 || height < 1 || width > 8192 || height > 8192) {
        std::fprintf(stderr, "consumer: --size: 1 to 8192 pixels each way\n");
        return 1;
    }
    try {
        const Scene scene = read_scene(scene_path, width, height);
        Gpu gpu;
        // Upload: every record as the shader declares it, in host-coherent buffers.
        const Buffer frame(gpu, std::vector<Frame>{scene.frame});
        const Buffer lights(gpu, scene.lights);
        const Buffer materials(gpu, scene.materials);
        const Buffer objects(gpu, scene.objects);
        const Buffer pixels(gpu, VkDeviceSize(width) * height * sizeof(uint32_t));
        ComputePipeline pipeline(gpu, read_spirv(spirv_path),
                                 {&frame, &lights, &materials, &objects, &pixels});
        constexpr uint32_t kGroup = 8;  // render.comp's local_size_x and _y
        pipeline.run(gpu.queue(), (width + kGroup - 1) / kGroup, (height + kGroup - 1) / kGroup);
        // Read back: the fence has signalled and the memory is coherent.
        const auto* rgba = static_cast<const uint32_t*>(pixels.data());
        write_png(out, rgba, width, height);
        const std::set<uint32_t> colours(rgba, rgba + std::size_t(width) * height);
        std::printf("consumer: %s, %dx%d on %s, %zu lights, %zu distinct colours\n", out.c_str(),
                    width, height, gpu.name().c_str(), scene.lights.size(), colours.size());
        // A shader that returned NaN or nothing gives one colour (or a handful): not an image.
        if (colours.size() < 64) {
            std::fprintf(stderr, "consumer: only %zu distinct colours: the render is broken\n",
                         colours.size());
            return 4;
        }
    } catch (const BadScene& e) {
        std::fprintf(stderr, "consumer: error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "consumer: error: %s\n", e.what());
        return 3;
    }
    return 0;
}
