// Mesa's RADV driver on a null device (no GPU needed): compiles SPIR-V compute
// modules with ACO for one AMD chip family and reads back what the driver reports of
// the result (VK_KHR_pipeline_executable_properties). The driver is loaded directly
// (dlopen of the library its ICD manifest names, vk_icdGetInstanceProcAddr), not
// through the Vulkan loader, so the process's loader instances (lavapipe) never see
// this device and this device never sees their environment.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "arealight/diagnostics.hpp"

namespace arealight {

struct RadvStatistics {
    uint32_t subgroup_size = 0;            // the wave size the shader was compiled for
    std::map<std::string, double> values;  // statistic name (RADV's) -> value
};

class RadvDevice {
  public:
    // nullptr with one diagnostic when the manifest, its library, or a null device for
    // `family` (one of radv_families(), checked first) is missing. The device is created
    // with RADV_FORCE_FAMILY and MESA_SHADER_CACHE_DISABLE set (so figures are compiled,
    // not loaded) and XDG_RUNTIME_DIR and XDG_CACHE_HOME where unset; each variable is
    // restored before this returns, and around destruction. Not thread-safe (it edits
    // the process environment): create and use from one thread.
    static std::unique_ptr<RadvDevice> create(const std::string& family, const std::string& icd,
                                              const DiagnosticConsumer& diag);
    ~RadvDevice();
    RadvDevice(const RadvDevice&) = delete;
    RadvDevice& operator=(const RadvDevice&) = delete;

    const std::string& family() const;       // lower case
    const std::string& driver_info() const;  // VkPhysicalDeviceDriverProperties::driverInfo
    const std::string& device_name() const;

    // Compiles the module's GLCompute entry point "main" with the pipeline layout its
    // decorations declare, and returns the statistics of its one executable. With a
    // time limit (seconds > 0) the compile runs in a forked copy of this process, which
    // is killed past the limit or when it needs more than `memory_bytes` beyond what
    // the process already maps (ACO takes minutes and many GB on some unrolled
    // modules); `timed_out` then says it was stopped. nullopt with a diagnostic on failure.
    std::optional<RadvStatistics> compile(const std::vector<uint32_t>& spirv,
                                          const DiagnosticConsumer& diag, double seconds = 0,
                                          uint64_t memory_bytes = 0, bool* timed_out = nullptr);

  private:
    std::optional<RadvStatistics> compile_here(const std::vector<uint32_t>& spirv,
                                               const DiagnosticConsumer& diag);
    struct Impl;
    explicit RadvDevice(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace arealight
