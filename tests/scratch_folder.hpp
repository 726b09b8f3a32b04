// A scratch folder for tests that write files (shaders that #include each other,
// generated libraries): fresh per test case, removed at the end.
#pragma once

#include <unistd.h>  // getpid: scratch folders of concurrent test runs differ

#include <filesystem>
#include <fstream>
#include <string>

namespace arealight::test {

class ScratchFolder {
  public:
    explicit ScratchFolder(const std::string& name)
        : path_(std::filesystem::temp_directory_path() /
                ("arealight_test_" + name + "_" + std::to_string(::getpid()))) {
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;

    std::string write(const std::string& relative, const std::string& text) const {
        const auto path = path_ / relative;
        std::filesystem::create_directories(path.parent_path());
        std::ofstream(path) << text;
        return path.string();
    }
    std::string operator/(const std::string& relative) const { return (path_ / relative).string(); }

  private:
    std::filesystem::path path_;
};

}  // namespace arealight::test
