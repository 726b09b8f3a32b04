// `arealight compile`: a small glslc for shaders that #include arealight libraries (glslang +
// SPIRV-Tools in process). Its options are in cli/main.cpp, which calls run_compile.
#pragma once

#include <string>
#include <vector>

namespace arealight::cli {

struct CompileArgs {
    std::string shader;
    std::string out;
    std::vector<std::string> include_dirs;
    std::string stage;    // empty: from the shader's extension
    std::string depfile;  // empty: none
    std::string entry;       // HLSL entry function; empty: main
    std::string target_env;  // empty: vulkan1.1
    bool no_opt = false;
};

// Exit codes as cli/main.cpp: 0 ok, 1 unreadable shader or compile error, 2 no stage for the
// extension, 3 write failure.
int run_compile(const CompileArgs& args);

}  // namespace arealight::cli
