// `--gpu-family` of report, sweep, bench and quality: the RADV chip the GPU cost is
// compiled for, checked against the names the driver knows before it ever sees one
// (an unknown name aborts it).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "arealight/gpu_cost.hpp"

namespace arealight::cli {

inline void add_gpu_family_option(CLI::App* cmd, std::string& family) {
    std::string names;
    for (const auto& f : radv_families()) names += (names.empty() ? "" : " ") + f;
    cmd->add_option("--gpu-family", family,
                    "RADV chip family the GPU cost is compiled for (RADV_FORCE_FAMILY, null "
                    "device): " +
                        names)
        ->check(CLI::Validator(
            [](std::string& s) {
                return is_radv_family(s) ? std::string() : "'" + s + "' is not a RADV chip family";
            },
            "FAMILY"))
        ->capture_default_str();
}

// `--gpu-cache DIR` (or AREALIGHT_GPU_CACHE): GpuCostOptions::cache_dir. The folder is
// created when missing.
inline void add_gpu_cache_option(CLI::App* cmd, std::string& dir) {
    cmd->add_option("--gpu-cache", dir,
                    "folder that keeps RADV's statistics per module, so that a module "
                    "compiled once (in any run) is not compiled again; default: none")
        ->envname("AREALIGHT_GPU_CACHE");
}

}  // namespace arealight::cli
