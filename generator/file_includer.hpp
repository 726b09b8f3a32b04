// glslang's #include resolver over the file system: "name" beside the including file, then in
// the include folders; <name> in the include folders only (glslc's rule).
#pragma once

#include <glslang/Public/ShaderLang.h>

#include <cstddef>
#include <string>
#include <vector>

namespace arealight {

class FileIncluder : public glslang::TShader::Includer {
  public:
    explicit FileIncluder(std::vector<std::string> include_dirs);
    ~FileIncluder() override;
    FileIncluder(const FileIncluder&) = delete;
    FileIncluder& operator=(const FileIncluder&) = delete;

    // glslang calls includeLocal for "name" and, when that fails, includeSystem; for <name>
    // only includeSystem. A failure result carries the folders searched, which glslang puts
    // into its error at the #include line.
    IncludeResult* includeLocal(const char* header, const char* includer,
                                std::size_t depth) override;
    IncludeResult* includeSystem(const char* header, const char* includer,
                                 std::size_t depth) override;
    void releaseInclude(IncludeResult* result) override;

    // Every file read, once each, in first-read order.
    const std::vector<std::string>& files() const { return files_; }

  private:
    IncludeResult* search(const std::string& header, const std::vector<std::string>& dirs,
                          std::size_t depth, bool last_resort);
    IncludeResult* failure(std::string message);

    std::vector<std::string> include_dirs_;
    std::vector<std::string> files_;
    // The folder a failed "name" was looked for in, for includeSystem's message.
    std::string local_miss_header_, local_miss_dir_;
};

}  // namespace arealight
