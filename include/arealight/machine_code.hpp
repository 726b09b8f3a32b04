// Deterministic machine-level cost of a variant: the x86-64 code lavapipe
// JIT-compiles for it, read back from the Mesa shader cache (each entry a
// zstd-compressed ELF object) and disassembled with Capstone.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "arealight/diagnostics.hpp"
#include "arealight/variant.hpp"

namespace arealight {

struct MachineCodeStats {
    std::size_t instructions = 0;  // x86-64 instructions in executable sections
    std::size_t bytes = 0;         // their size
    std::size_t objects = 0;       // ELF objects found (one per compiled shader)
};

// Counts the code of every ELF object stored under a Mesa shader cache folder.
std::optional<MachineCodeStats> count_cached_machine_code(const std::string& cache_dir,
                                                          const DiagnosticConsumer& diag);

// Compiles the variant on lavapipe and counts the code the driver adds to
// `cache_dir`. Mesa reads MESA_SHADER_CACHE_DIR once per process, so the caller
// must point it at `cache_dir` before the first Vulkan call (see
// PrivateShaderCache); the cache must not already hold this variant.
std::optional<MachineCodeStats> lavapipe_machine_code(const Variant& v,
                                                      const std::string& cache_dir,
                                                      const DiagnosticConsumer& diag);

// An empty shader cache folder of this process, named by MESA_SHADER_CACHE_DIR from its
// construction, removed with its contents at its destruction (the driver's cache is a
// measuring instrument, not state to keep). Construct it before any Vulkan use and
// destroy it after the last Vulkan object; path() is empty when the folder could not be
// made.
class PrivateShaderCache {
public:
    PrivateShaderCache();
    ~PrivateShaderCache();
    PrivateShaderCache(const PrivateShaderCache&) = delete;
    PrivateShaderCache& operator=(const PrivateShaderCache&) = delete;
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

}  // namespace arealight
