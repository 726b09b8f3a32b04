#include "arealight/read_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace arealight {

std::optional<std::string> read_file(const std::string& path, const DiagnosticConsumer& diag) {
    std::error_code ec;
    std::ifstream in(path, std::ios::binary);
    // A folder opens as a stream and reads as empty.
    const char* why = !in ? "missing or unreadable"
                          : std::filesystem::is_directory(path, ec) ? "it is a folder" : nullptr;
    if (why) {
        if (diag) diag({Severity::Error, path, 0, path + ": cannot read: " + why});
        return std::nullopt;
    }
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (in.bad()) {
        if (diag) diag({Severity::Error, path, 0, path + ": cannot read: I/O error"});
        return std::nullopt;
    }
    return bytes.str();
}

}  // namespace arealight
