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
// use_private_shader_cache); the cache must not already hold this variant.
std::optional<MachineCodeStats> lavapipe_machine_code(const Variant& v,
                                                      const std::string& cache_dir,
                                                      const DiagnosticConsumer& diag);

// Creates an empty folder for the shader cache and sets MESA_SHADER_CACHE_DIR to it.
// Call before any Vulkan use; returns the folder, or empty on failure.
std::string use_private_shader_cache();

}  // namespace arealight
