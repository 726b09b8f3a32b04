#include "file_includer.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace arealight {
namespace {

namespace fs = std::filesystem;

// glslang 12 follows includes without a depth limit; a cycle without include guards would
// recurse until the stack overflows.
constexpr std::size_t kMaxDepth = 64;

// The text lives as long as its result: glslang reads it until releaseInclude.
struct Owned {
    std::string text;
};

std::string folder_of(const std::string& file) {
    const fs::path parent = fs::path(file).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

}  // namespace

FileIncluder::FileIncluder(std::vector<std::string> include_dirs)
    : include_dirs_(std::move(include_dirs)) {}

FileIncluder::~FileIncluder() = default;

FileIncluder::IncludeResult* FileIncluder::failure(std::string message) {
    auto* owned = new Owned{std::move(message)};
    return new IncludeResult("", owned->text.data(), owned->text.size(), owned);
}

FileIncluder::IncludeResult* FileIncluder::search(const std::string& header,
                                                  const std::vector<std::string>& dirs,
                                                  std::size_t depth, bool last_resort) {
    if (depth > kMaxDepth) {
        return failure("include depth exceeds " + std::to_string(kMaxDepth) +
                       " (a cycle without include guards?)");
    }
    for (const std::string& dir : dirs) {
        const fs::path path = (fs::path(dir) / header).lexically_normal();
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) continue;
        std::ifstream in(path, std::ios::binary);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (!in.good() && !in.eof()) return failure("cannot read " + path.string());
        const std::string name = path.string();
        if (std::find(files_.begin(), files_.end(), name) == files_.end()) files_.push_back(name);
        auto* owned = new Owned{std::move(text)};
        return new IncludeResult(name, owned->text.data(), owned->text.size(), owned);
    }
    if (!last_resort) return nullptr;
    std::string searched;
    if (local_miss_header_ == header) searched = local_miss_dir_;
    for (const std::string& dir : dirs) searched += (searched.empty() ? "" : ", ") + dir;
    return failure(searched.empty() ? "not found (no include folder given)"
                                    : "not found (searched " + searched + ")");
}

FileIncluder::IncludeResult* FileIncluder::includeLocal(const char* header, const char* includer,
                                                        std::size_t depth) {
    const std::string dir = folder_of(includer ? includer : "");
    IncludeResult* found = search(header, {dir}, depth, false);
    if (!found) {
        local_miss_header_ = header;
        local_miss_dir_ = dir;
    }
    return found;
}

FileIncluder::IncludeResult* FileIncluder::includeSystem(const char* header, const char*,
                                                         std::size_t depth) {
    IncludeResult* found = search(header, include_dirs_, depth, true);
    local_miss_header_.clear();
    return found;
}

void FileIncluder::releaseInclude(IncludeResult* result) {
    if (!result) return;
    delete static_cast<Owned*>(result->userData);
    delete result;
}

}  // namespace arealight
