#include "arealight/spirv_cache.hpp"

#include <fmt/format.h>
#include <glslang/build_info.h>
#include <spirv-tools/libspirv.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

#include "arealight/atomic_file.hpp"
#include "arealight/fnv_hash.hpp"

namespace arealight {
namespace {

// An entry: this line, the tag's and the text's lengths on one line, the tag, the text,
// then the SPIR-V words in the machine's byte order (the folder never leaves the machine).
constexpr const char* kMagic = "arealight-spirv-cache/1\n";

std::string entry_path(const std::string& dir, const std::string& tag, const std::string& source) {
    uint64_t h = fnv1a(tag);
    h = fnv1a(h, 0);
    for (unsigned char c : source) h = fnv1a(h, c);
    return (std::filesystem::path(dir) / fmt::format("{:016x}.spv", h)).string();
}

std::string header(const std::string& tag, const std::string& source) {
    return fmt::format("{}{} {}\n", kMagic, tag.size(), source.size()) + tag + source;
}

std::optional<std::vector<uint32_t>> read_entry(const std::string& path, const std::string& head) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() <= head.size() || bytes.compare(0, head.size(), head) != 0) return std::nullopt;
    const std::size_t n = bytes.size() - head.size();
    if (n % sizeof(uint32_t) != 0) return std::nullopt;
    std::vector<uint32_t> words(n / sizeof(uint32_t));
    std::memcpy(words.data(), bytes.data() + head.size(), n);
    return words;
}

}  // namespace

std::string compiler_versions() {
    return fmt::format("glslang {}.{}.{}{}, {}", GLSLANG_VERSION_MAJOR, GLSLANG_VERSION_MINOR,
                       GLSLANG_VERSION_PATCH, GLSLANG_VERSION_FLAVOR, spvSoftwareVersionString());
}

std::optional<std::vector<uint32_t>> cached_compile(
    const std::string& dir, const std::string& tag, const std::string& source,
    const std::function<std::optional<std::vector<uint32_t>>()>& compile) {
    if (dir.empty()) return compile();
    const std::string path = entry_path(dir, tag, source);
    const std::string head = header(tag, source);
    if (auto words = read_entry(path, head)) return words;
    auto words = compile();
    if (!words) return words;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    std::string bytes = head;
    bytes.append(reinterpret_cast<const char*>(words->data()), words->size() * sizeof(uint32_t));
    if (!ec) write_file_atomic(path, bytes, nullptr);
    return words;
}

}  // namespace arealight
