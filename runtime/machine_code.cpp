#include "arealight/machine_code.hpp"

#include <capstone/capstone.h>
#include <elf.h>
#include <unistd.h>
#include <zstd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "arealight/evaluator.hpp"
#include "arealight/vulkan_runner.hpp"

namespace arealight {
namespace {

namespace fs = std::filesystem;

// Counts instructions in the executable sections of one ELF64 relocatable.
bool count_elf(const std::vector<unsigned char>& elf, csh handle, MachineCodeStats& stats) {
    if (elf.size() < sizeof(Elf64_Ehdr) || std::memcmp(elf.data(), ELFMAG, SELFMAG) != 0)
        return false;
    Elf64_Ehdr eh;
    std::memcpy(&eh, elf.data(), sizeof eh);
    if (eh.e_shoff == 0 || eh.e_shentsize != sizeof(Elf64_Shdr) ||
        eh.e_shoff + eh.e_shnum * sizeof(Elf64_Shdr) > elf.size())
        return false;
    for (int i = 0; i < eh.e_shnum; ++i) {
        Elf64_Shdr sh;
        std::memcpy(&sh, elf.data() + eh.e_shoff + i * sizeof(Elf64_Shdr), sizeof sh);
        if (!(sh.sh_flags & SHF_EXECINSTR) || sh.sh_type != SHT_PROGBITS) continue;
        if (sh.sh_offset + sh.sh_size > elf.size()) return false;
        // Skip-data mode: Capstone otherwise stops at the first byte run it cannot
        // decode (measured: ~700 of 44 000 instructions counted); skipped runs come
        // back as pseudo-instructions with id 0 and are not counted.
        cs_insn* insn = nullptr;
        const size_t n = cs_disasm(handle, elf.data() + sh.sh_offset, sh.sh_size, 0, 0, &insn);
        for (size_t k = 0; k < n; ++k) stats.instructions += insn[k].id != 0;
        if (insn) cs_free(insn, n);
        stats.bytes += sh.sh_size;
    }
    ++stats.objects;
    return true;
}

// Every zstd frame in a cache entry, decompressed (an entry holds a small header
// followed by the compressed blob).
std::vector<std::vector<unsigned char>> zstd_frames(const std::vector<unsigned char>& data) {
    static const unsigned char magic[4] = {0x28, 0xb5, 0x2f, 0xfd};
    std::vector<std::vector<unsigned char>> out;
    for (size_t at = 0; at + 4 <= data.size(); ++at) {
        if (std::memcmp(data.data() + at, magic, 4) != 0) continue;
        const size_t frame = ZSTD_findFrameCompressedSize(data.data() + at, data.size() - at);
        if (ZSTD_isError(frame)) continue;
        const unsigned long long size = ZSTD_getFrameContentSize(data.data() + at, frame);
        if (size == ZSTD_CONTENTSIZE_ERROR || size == ZSTD_CONTENTSIZE_UNKNOWN || size > (1u << 28))
            continue;
        std::vector<unsigned char> plain(size);
        const size_t got = ZSTD_decompress(plain.data(), plain.size(), data.data() + at, frame);
        if (!ZSTD_isError(got)) {
            plain.resize(got);
            out.push_back(std::move(plain));
        }
        at += frame - 1;
    }
    return out;
}

std::vector<fs::path> cache_entries(const std::string& cache_dir) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(cache_dir, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (it->is_regular_file() && it->path().filename() != "index") files.push_back(it->path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::optional<MachineCodeStats> count_files(const std::vector<fs::path>& files,
                                            const DiagnosticConsumer& diag) {
    csh handle;
    if (cs_open(CS_ARCH_X86, CS_MODE_64, &handle) != CS_ERR_OK ||
        cs_option(handle, CS_OPT_SKIPDATA, CS_OPT_ON) != CS_ERR_OK) {
        if (diag) diag({Severity::Error, "", 0, "capstone: cannot open an x86-64 disassembler"});
        return std::nullopt;
    }
    MachineCodeStats stats;
    for (const auto& f : files) {
        std::ifstream in(f, std::ios::binary);
        const std::vector<unsigned char> data((std::istreambuf_iterator<char>(in)), {});
        for (const auto& plain : zstd_frames(data)) count_elf(plain, handle, stats);
    }
    cs_close(&handle);
    return stats;
}

}  // namespace

std::optional<MachineCodeStats> count_cached_machine_code(const std::string& cache_dir,
                                                          const DiagnosticConsumer& diag) {
    return count_files(cache_entries(cache_dir), diag);
}

PrivateShaderCache::PrivateShaderCache() {
    std::error_code ec;
    const fs::path dir =
        fs::temp_directory_path(ec) / ("arealight-mesa-cache-" + std::to_string(::getpid()));
    if (ec) return;
    fs::remove_all(dir, ec);
    if (!fs::create_directories(dir, ec)) return;
    ::setenv("MESA_SHADER_CACHE_DIR", dir.c_str(), 1);
    path_ = dir.string();
}

PrivateShaderCache::~PrivateShaderCache() {
    if (path_.empty()) return;
    std::error_code ec;
    fs::remove_all(path_, ec);
}

std::optional<MachineCodeStats> lavapipe_machine_code(const Variant& v,
                                                      const std::string& cache_dir,
                                                      const DiagnosticConsumer& diag) {
    auto spirv = build_spirv(v, true, diag);
    if (!spirv) return std::nullopt;
    const auto before = cache_entries(cache_dir);
    {
        // A runner of its own: destroying it flushes the driver's cache writes.
        auto runner = VulkanRunner::create("llvmpipe", diag);
        std::vector<float> out;
        const float dummy[kFloatsPerCase] = {};
        // llvmpipe JIT-compiles at the first dispatch: run one (empty) case.
        if (!runner || !runner->run(*spirv, dummy, sizeof dummy, 1, out, kFloatsPerResult, diag,
                                    nullptr, variant_textures(v)))
            return std::nullopt;
    }
    std::vector<fs::path> added;
    for (const auto& f : cache_entries(cache_dir))
        if (!std::binary_search(before.begin(), before.end(), f)) added.push_back(f);
    auto stats = count_files(added, diag);
    if (stats && stats->objects == 0) {
        if (diag)
            diag({Severity::Error, "", 0,
                  "lavapipe added no shader to " + cache_dir +
                      " (MESA_SHADER_CACHE_DIR must be set before any Vulkan call)"});
        return std::nullopt;
    }
    return stats;
}

}  // namespace arealight
