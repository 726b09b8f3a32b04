// Every Vulkan call here goes through pointers the RADV library itself hands out; with
// VK_NO_PROTOTYPES nothing can bind to the loader's exports by mistake.
#define VK_NO_PROTOTYPES
#include "radv_device.hpp"

#include <dlfcn.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "arealight/gpu_cost.hpp"
#include "spirv_layout.hpp"

namespace arealight {
namespace {

// Sets an environment variable for a scope and puts back what was there before.
class ScopedEnv {
  public:
    // overwrite = false: set only when unset (a caller's own choice stands).
    ScopedEnv(const char* name, const std::string& value, bool overwrite) : name_(name) {
        const char* old = std::getenv(name);
        had_ = old != nullptr;
        if (had_) old_ = old;
        if (!had_ || overwrite) {
            ::setenv(name, value.c_str(), 1);
            changed_ = true;
        }
    }
    ~ScopedEnv() {
        if (!changed_) return;
        if (had_)
            ::setenv(name_, old_.c_str(), 1);
        else
            ::unsetenv(name_);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

  private:
    const char* name_;
    std::string old_;
    bool had_ = false, changed_ = false;
};

// What RADV reads from the environment while it creates (and, for its internal meta
// shaders' cache, destroys) a device.
struct RadvEnvironment {
    explicit RadvEnvironment(const std::string& family)
        : force_family("RADV_FORCE_FAMILY", family, true),
          no_cache("MESA_SHADER_CACHE_DISABLE", "true", true),
          runtime_dir("XDG_RUNTIME_DIR", std::filesystem::temp_directory_path().string(), false),
          cache_home("XDG_CACHE_HOME", cache_folder(), false) {}

    // RADV keeps its meta shaders under $XDG_CACHE_HOME (else ~/.cache): a folder of
    // our own in the temporary directory instead.
    static std::string cache_folder() {
        const auto dir = std::filesystem::temp_directory_path() / "arealight-radv-cache";
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        return dir.string();
    }

    ScopedEnv force_family, no_cache, runtime_dir, cache_home;
};

// Undoes what was made, last first, however the scope ends.
class Cleanup {
  public:
    Cleanup() = default;
    Cleanup(const Cleanup&) = delete;
    Cleanup& operator=(const Cleanup&) = delete;
    ~Cleanup() {
        for (auto it = steps_.rbegin(); it != steps_.rend(); ++it) (*it)();
    }
    void add(std::function<void()> f) { steps_.push_back(std::move(f)); }

  private:
    std::vector<std::function<void()>> steps_;
};

// Vulkan's two-call enumeration: the count, then that many values.
template <typename T, typename Call>
std::vector<T> enumerate_all(Call call) {
    uint32_t n = 0;
    call(&n, nullptr);
    std::vector<T> out(n);
    if (n) call(&n, out.data());
    out.resize(n);
    return out;
}

std::string timeout_text(double seconds) {
    char text[96];
    std::snprintf(text, sizeof text, "ACO did not finish within %g s; the compile was stopped",
                  seconds);
    return text;
}

std::string result_text(VkResult r) {
    return "VkResult " + std::to_string(static_cast<int>(r));
}

// The driver library a manifest names (ICD manifest "library_path").
std::optional<std::string> manifest_library(const std::string& icd, std::string& why) {
    std::ifstream in(icd);
    if (!in) {
        why = icd + " not found (Debian: mesa-vulkan-drivers)";
        return std::nullopt;
    }
    const auto doc = nlohmann::json::parse(in, nullptr, false);
    const auto* path = doc.is_object() && doc.contains("ICD") && doc["ICD"].is_object() &&
                               doc["ICD"].contains("library_path") &&
                               doc["ICD"]["library_path"].is_string()
                           ? &doc["ICD"]["library_path"]
                           : nullptr;
    if (!path) {
        why = icd + " has no ICD.library_path";
        return std::nullopt;
    }
    std::string lib = path->get<std::string>();
    // A relative path is relative to the manifest (Vulkan loader convention).
    if (lib.find('/') != std::string::npos && lib.front() != '/')
        lib = (std::filesystem::path(icd).parent_path() / lib).string();
    return lib;
}

}  // namespace

struct RadvDevice::Impl {
    std::string family, driver_info, device_name;
    VkInstance instance = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    uint32_t max_push_constants = 128;

    PFN_vkDestroyInstance destroy_instance = nullptr;
    PFN_vkDestroyDevice destroy_device = nullptr;
    PFN_vkCreateDescriptorSetLayout create_set_layout = nullptr;
    PFN_vkDestroyDescriptorSetLayout destroy_set_layout = nullptr;
    PFN_vkCreatePipelineLayout create_pipeline_layout = nullptr;
    PFN_vkDestroyPipelineLayout destroy_pipeline_layout = nullptr;
    PFN_vkCreateShaderModule create_shader_module = nullptr;
    PFN_vkDestroyShaderModule destroy_shader_module = nullptr;
    PFN_vkCreateComputePipelines create_compute_pipelines = nullptr;
    PFN_vkDestroyPipeline destroy_pipeline = nullptr;
    PFN_vkGetPipelineExecutablePropertiesKHR executable_properties = nullptr;
    PFN_vkGetPipelineExecutableStatisticsKHR executable_statistics = nullptr;

    ~Impl() {
        RadvEnvironment env(family);
        if (device != VK_NULL_HANDLE && destroy_device) destroy_device(device, nullptr);
        if (instance != VK_NULL_HANDLE && destroy_instance) destroy_instance(instance, nullptr);
        // The library stays loaded: Mesa drivers are not written to be unloaded, and the
        // loader may hold it too.
    }
};

RadvDevice::RadvDevice(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
RadvDevice::~RadvDevice() = default;
const std::string& RadvDevice::family() const {
    return impl_->family;
}
const std::string& RadvDevice::driver_info() const {
    return impl_->driver_info;
}
const std::string& RadvDevice::device_name() const {
    return impl_->device_name;
}

std::unique_ptr<RadvDevice> RadvDevice::create(const std::string& family_name,
                                               const std::string& icd,
                                               const DiagnosticConsumer& diag) {
    auto fail = [&](const std::string& m) -> std::unique_ptr<RadvDevice> {
        if (diag) diag({Severity::Warning, "", 0, "gpu cost left out: " + m});
        return nullptr;
    };
    std::string family = family_name;
    std::transform(family.begin(), family.end(), family.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    // RADV aborts the process on a family it does not know: never pass it one.
    if (!is_radv_family(family))
        return fail("'" + family_name +
                    "' is not a RADV chip family (e.g. navi21, gfx1100, vega10)");
    std::string why;
    const auto lib = manifest_library(icd, why);
    if (!lib) return fail(why);
    void* handle = ::dlopen(lib->c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* e = ::dlerror();
        return fail("cannot load " + *lib + ": " + (e ? e : "dlopen failed"));
    }
    using Negotiate = VkResult(VKAPI_PTR*)(uint32_t*);
    if (auto negotiate = reinterpret_cast<Negotiate>(
            ::dlsym(handle, "vk_icdNegotiateLoaderICDInterfaceVersion"))) {
        uint32_t version = 5;  // the newest the loader of Vulkan 1.3 speaks
        negotiate(&version);
    }
    auto gipa =
        reinterpret_cast<PFN_vkGetInstanceProcAddr>(::dlsym(handle, "vk_icdGetInstanceProcAddr"));
    if (!gipa) return fail(*lib + " exports no vk_icdGetInstanceProcAddr");

    auto impl = std::make_unique<Impl>();
    impl->family = family;
    RadvEnvironment env(family);
    auto create_instance =
        reinterpret_cast<PFN_vkCreateInstance>(gipa(VK_NULL_HANDLE, "vkCreateInstance"));
    if (!create_instance) return fail(*lib + ": no vkCreateInstance");
    auto app = VkApplicationInfo{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "arealight gpu cost";
    app.apiVersion = VK_API_VERSION_1_3;
    auto ici = VkInstanceCreateInfo{};
    ici.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    ici.pApplicationInfo = &app;
    if (VkResult r = create_instance(&ici, nullptr, &impl->instance); r != VK_SUCCESS)
        return fail("RADV vkCreateInstance failed: " + result_text(r));
    const VkInstance inst = impl->instance;
#define AREALIGHT_INSTANCE_FN(name) reinterpret_cast<PFN_##name>(gipa(inst, #name))
    impl->destroy_instance = AREALIGHT_INSTANCE_FN(vkDestroyInstance);
    auto enumerate = AREALIGHT_INSTANCE_FN(vkEnumeratePhysicalDevices);
    auto properties2 = AREALIGHT_INSTANCE_FN(vkGetPhysicalDeviceProperties2);
    auto features2 = AREALIGHT_INSTANCE_FN(vkGetPhysicalDeviceFeatures2);
    auto queue_families = AREALIGHT_INSTANCE_FN(vkGetPhysicalDeviceQueueFamilyProperties);
    auto extensions = AREALIGHT_INSTANCE_FN(vkEnumerateDeviceExtensionProperties);
    auto create_device = AREALIGHT_INSTANCE_FN(vkCreateDevice);
    auto gdpa = AREALIGHT_INSTANCE_FN(vkGetDeviceProcAddr);
#undef AREALIGHT_INSTANCE_FN
    if (!impl->destroy_instance || !enumerate || !properties2 || !features2 || !queue_families ||
        !extensions || !create_device || !gdpa)
        return fail(*lib + ": an instance entry point is missing");

    const auto devices = enumerate_all<VkPhysicalDevice>(
        [&](uint32_t* n, VkPhysicalDevice* out) { enumerate(inst, n, out); });
    if (devices.empty()) return fail("RADV lists no null device for family " + family);
    const VkPhysicalDevice pd = devices.front();

    auto driver = VkPhysicalDeviceDriverProperties{};
    driver.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
    auto props = VkPhysicalDeviceProperties2{};
    props.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
    props.pNext = &driver;
    properties2(pd, &props);
    impl->device_name = props.properties.deviceName;
    impl->driver_info = driver.driverInfo;
    impl->max_push_constants = props.properties.limits.maxPushConstantsSize;

    const auto ext = enumerate_all<VkExtensionProperties>(
        [&](uint32_t* n, VkExtensionProperties* out) { extensions(pd, nullptr, n, out); });
    const bool has_stats = std::any_of(ext.begin(), ext.end(), [](const VkExtensionProperties& e) {
        return std::string(e.extensionName) == VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME;
    });
    auto exec = VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR{};
    exec.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR;
    auto features = VkPhysicalDeviceFeatures2{};
    features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    features.pNext = &exec;
    features2(pd, &features);
    if (!has_stats || !exec.pipelineExecutableInfo)
        return fail(impl->device_name + " does not report pipeline statistics (" +
                    VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME + ")");

    const auto qf = enumerate_all<VkQueueFamilyProperties>(
        [&](uint32_t* n, VkQueueFamilyProperties* out) { queue_families(pd, n, out); });
    const uint32_t nqf = static_cast<uint32_t>(qf.size());
    uint32_t compute = nqf;
    for (uint32_t i = 0; i < nqf && compute == nqf; ++i)
        if (qf[i].queueFlags & VK_QUEUE_COMPUTE_BIT) compute = i;
    if (compute == nqf) return fail(impl->device_name + " has no compute queue");

    const float priority = 1.0f;
    auto queue = VkDeviceQueueCreateInfo{};
    queue.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queue.queueFamilyIndex = compute;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    auto enable = VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR{};
    enable.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR;
    enable.pipelineExecutableInfo = VK_TRUE;
    const char* names[] = {VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME};
    auto dci = VkDeviceCreateInfo{};
    dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    dci.pNext = &enable;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &queue;
    dci.enabledExtensionCount = 1;
    dci.ppEnabledExtensionNames = names;
    if (VkResult r = create_device(pd, &dci, nullptr, &impl->device); r != VK_SUCCESS)
        return fail("RADV vkCreateDevice failed: " + result_text(r));
    const VkDevice dev = impl->device;
#define AREALIGHT_DEVICE_FN(name) reinterpret_cast<PFN_##name>(gdpa(dev, #name))
    impl->destroy_device = AREALIGHT_DEVICE_FN(vkDestroyDevice);
    impl->create_set_layout = AREALIGHT_DEVICE_FN(vkCreateDescriptorSetLayout);
    impl->destroy_set_layout = AREALIGHT_DEVICE_FN(vkDestroyDescriptorSetLayout);
    impl->create_pipeline_layout = AREALIGHT_DEVICE_FN(vkCreatePipelineLayout);
    impl->destroy_pipeline_layout = AREALIGHT_DEVICE_FN(vkDestroyPipelineLayout);
    impl->create_shader_module = AREALIGHT_DEVICE_FN(vkCreateShaderModule);
    impl->destroy_shader_module = AREALIGHT_DEVICE_FN(vkDestroyShaderModule);
    impl->create_compute_pipelines = AREALIGHT_DEVICE_FN(vkCreateComputePipelines);
    impl->destroy_pipeline = AREALIGHT_DEVICE_FN(vkDestroyPipeline);
    impl->executable_properties = AREALIGHT_DEVICE_FN(vkGetPipelineExecutablePropertiesKHR);
    impl->executable_statistics = AREALIGHT_DEVICE_FN(vkGetPipelineExecutableStatisticsKHR);
#undef AREALIGHT_DEVICE_FN
    if (!impl->destroy_device || !impl->create_set_layout || !impl->destroy_set_layout ||
        !impl->create_pipeline_layout || !impl->destroy_pipeline_layout ||
        !impl->create_shader_module || !impl->destroy_shader_module ||
        !impl->create_compute_pipelines || !impl->destroy_pipeline ||
        !impl->executable_properties || !impl->executable_statistics)
        return fail(impl->device_name + ": a device entry point is missing");
    return std::unique_ptr<RadvDevice>(new RadvDevice(std::move(impl)));
}

namespace {

// The process's mapped bytes now (/proc/self/statm, first field, in pages).
uint64_t mapped_bytes() {
    std::ifstream in("/proc/self/statm");
    uint64_t pages = 0;
    in >> pages;
    return pages * static_cast<uint64_t>(::sysconf(_SC_PAGESIZE));
}

// The child's answer on the pipe: "ok SUBGROUP\n" then "VALUE NAME\n" per statistic, or
// "error MESSAGE\n".
std::string encode(const std::optional<RadvStatistics>& s, const std::string& error) {
    if (!s) return "error " + error + "\n";
    std::string out = "ok " + std::to_string(s->subgroup_size) + "\n";
    for (const auto& [name, value] : s->values) {
        char number[32];
        std::snprintf(number, sizeof number, "%.17g", value);
        out += std::string(number) + " " + name + "\n";
    }
    return out;
}

std::optional<RadvStatistics> decode(const std::string& text, std::string& error) {
    std::istringstream in(text);
    std::string word;
    in >> word;
    if (word == "error") {
        std::getline(in >> std::ws, error);
        return std::nullopt;
    }
    RadvStatistics s;
    if (word != "ok" || !(in >> s.subgroup_size)) {
        error = "the compiling process ended without an answer";
        return std::nullopt;
    }
    double value = 0;
    std::string name;
    while (in >> value && std::getline(in >> std::ws, name)) s.values[name] = value;
    return s;
}

}  // namespace

std::optional<RadvStatistics> RadvDevice::compile(const std::vector<uint32_t>& spirv,
                                                  const DiagnosticConsumer& diag, double seconds,
                                                  uint64_t memory_bytes, bool* timed_out) {
    if (timed_out) *timed_out = false;
    if (seconds <= 0) return compile_here(spirv, diag);
    auto fail = [&](const std::string& m) -> std::optional<RadvStatistics> {
        if (diag) diag({Severity::Error, "", 0, "gpu cost (RADV " + impl_->family + "): " + m});
        return std::nullopt;
    };
    int fds[2];
    if (::pipe(fds) != 0) return fail("pipe failed");
    const uint64_t limit = memory_bytes ? mapped_bytes() + memory_bytes : 0;
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        return fail("fork failed");
    }
    if (pid == 0) {
        // The child: this thread alone, the driver's state as the parent left it (a null
        // device holds no kernel handle). Only _exit: the parent owns every other resource.
        ::close(fds[0]);
        if (limit) {
            const rlimit r{limit, limit};
            ::setrlimit(RLIMIT_AS, &r);
        }
        std::string error;
        const auto stats = compile_here(spirv, [&](const Diagnostic& d) {
            if (d.severity == Severity::Error && error.empty()) error = d.message;
        });
        const std::string answer = encode(stats, error);
        for (std::size_t at = 0; at < answer.size();) {
            const ssize_t n = ::write(fds[1], answer.data() + at, answer.size() - at);
            if (n <= 0) break;
            at += static_cast<std::size_t>(n);
        }
        ::_exit(stats ? 0 : 1);
    }
    ::close(fds[1]);
    std::string text;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    bool late = false;
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                              deadline - std::chrono::steady_clock::now())
                              .count();
        if (left <= 0) {
            late = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000)));
        if (ready < 0 && errno != EINTR) break;
        if (ready <= 0) continue;
        char buf[4096];
        const ssize_t n = ::read(fds[0], buf, sizeof buf);
        if (n <= 0) break;  // end of the answer
        text.append(buf, static_cast<std::size_t>(n));
    }
    ::close(fds[0]);
    if (late) ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (late) {
        if (timed_out) *timed_out = true;
        return fail(timeout_text(seconds));
    }
    std::string error;
    auto stats = decode(text, error);
    if (!stats && WIFSIGNALED(status)) {
        // Past its memory limit the driver cannot allocate and aborts: stopped, like late.
        if (timed_out && limit) *timed_out = true;
        error = "the compiling process died (signal " + std::to_string(WTERMSIG(status)) +
                (limit ? "; past its memory limit, the compile was stopped" : "") + ")";
    }
    if (!stats) return fail(error);
    return stats;
}

std::optional<RadvStatistics> RadvDevice::compile_here(const std::vector<uint32_t>& spirv,
                                                       const DiagnosticConsumer& diag) {
    auto fail = [&](const std::string& m) -> std::optional<RadvStatistics> {
        if (diag) diag({Severity::Error, "", 0, "gpu cost (RADV " + impl_->family + "): " + m});
        return std::nullopt;
    };
    // Whether a call succeeded; reported as "CALL failed: VkResult N" when not.
    auto ok = [&](VkResult r, const char* call) {
        if (r != VK_SUCCESS) fail(std::string(call) + " failed: " + result_text(r));
        return r == VK_SUCCESS;
    };
    std::string why;
    const auto layout = reflect_spirv_layout(spirv, "main", why);
    if (!layout) return fail(why);
    const Impl& d = *impl_;
    const VkDevice dev = d.device;
    Cleanup cleanup;

    // One set layout per set up to the last used, empty where the module uses none.
    uint32_t sets = 0;
    for (const auto& s : layout->descriptors) sets = std::max(sets, s.set + 1);
    std::vector<VkDescriptorSetLayout> set_layouts;
    for (uint32_t set = 0; set < sets; ++set) {
        std::vector<VkDescriptorSetLayoutBinding> bindings;
        for (const auto& s : layout->descriptors)
            if (s.set == set)
                bindings.push_back(
                    {s.binding, s.type, s.count, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
        auto info = VkDescriptorSetLayoutCreateInfo{};
        info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
        info.bindingCount = static_cast<uint32_t>(bindings.size());
        info.pBindings = bindings.data();
        VkDescriptorSetLayout l = VK_NULL_HANDLE;
        if (!ok(d.create_set_layout(dev, &info, nullptr, &l), "vkCreateDescriptorSetLayout"))
            return std::nullopt;
        cleanup.add([&d, dev, l] { d.destroy_set_layout(dev, l, nullptr); });
        set_layouts.push_back(l);
    }
    // Push constants: the block's extent in whole words, within the device's limit.
    const uint32_t push = (std::min(layout->push_constant_bytes, d.max_push_constants) + 3u) & ~3u;
    const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, push};
    auto pli = VkPipelineLayoutCreateInfo{};
    pli.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    pli.setLayoutCount = sets;
    pli.pSetLayouts = set_layouts.data();
    pli.pushConstantRangeCount = push ? 1 : 0;
    pli.pPushConstantRanges = &range;
    VkPipelineLayout pipeline_layout = VK_NULL_HANDLE;
    if (!ok(d.create_pipeline_layout(dev, &pli, nullptr, &pipeline_layout),
            "vkCreatePipelineLayout"))
        return std::nullopt;
    cleanup.add(
        [&d, dev, pipeline_layout] { d.destroy_pipeline_layout(dev, pipeline_layout, nullptr); });

    auto smi = VkShaderModuleCreateInfo{};
    smi.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    smi.codeSize = spirv.size() * sizeof(uint32_t);
    smi.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    if (!ok(d.create_shader_module(dev, &smi, nullptr, &module), "vkCreateShaderModule"))
        return std::nullopt;
    cleanup.add([&d, dev, module] { d.destroy_shader_module(dev, module, nullptr); });

    auto cpi = VkComputePipelineCreateInfo{};
    cpi.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    cpi.flags = VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR;
    cpi.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    cpi.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    cpi.stage.module = module;
    cpi.stage.pName = "main";
    cpi.layout = pipeline_layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    if (!ok(d.create_compute_pipelines(dev, VK_NULL_HANDLE, 1, &cpi, nullptr, &pipeline),
            "vkCreateComputePipelines"))
        return std::nullopt;
    cleanup.add([&d, dev, pipeline] { d.destroy_pipeline(dev, pipeline, nullptr); });

    auto pinfo = VkPipelineInfoKHR{};
    pinfo.sType = VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR;
    pinfo.pipeline = pipeline;
    uint32_t executables = 0;
    if (!ok(d.executable_properties(dev, &pinfo, &executables, nullptr),
            "vkGetPipelineExecutablePropertiesKHR"))
        return std::nullopt;
    if (executables != 1)
        return fail("expected one executable in a compute pipeline, got " +
                    std::to_string(executables));
    auto props = VkPipelineExecutablePropertiesKHR{};
    props.sType = VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR;
    if (!ok(d.executable_properties(dev, &pinfo, &executables, &props),
            "vkGetPipelineExecutablePropertiesKHR"))
        return std::nullopt;

    auto xinfo = VkPipelineExecutableInfoKHR{};
    xinfo.sType = VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR;
    xinfo.pipeline = pipeline;
    xinfo.executableIndex = 0;
    uint32_t n = 0;
    if (!ok(d.executable_statistics(dev, &xinfo, &n, nullptr),
            "vkGetPipelineExecutableStatisticsKHR"))
        return std::nullopt;
    std::vector<VkPipelineExecutableStatisticKHR> stats(n);
    for (auto& s : stats) s.sType = VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR;
    if (!ok(d.executable_statistics(dev, &xinfo, &n, stats.data()),
            "vkGetPipelineExecutableStatisticsKHR"))
        return std::nullopt;

    RadvStatistics out;
    out.subgroup_size = props.subgroupSize;
    for (const auto& s : stats) {
        double value = 0;
        switch (s.format) {
            case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR:
                value = s.value.b32 ? 1 : 0;
                break;
            case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR:
                value = static_cast<double>(s.value.i64);
                break;
            case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR:
                value = static_cast<double>(s.value.u64);
                break;
            default:
                value = s.value.f64;
                break;
        }
        out.values[s.name] = value;
    }
    return out;
}

}  // namespace arealight
