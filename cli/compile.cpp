#include "compile.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <iterator>

#include "arealight/atomic_file.hpp"
#include "arealight/compiler.hpp"
#include "exit_code.hpp"

namespace arealight::cli {

namespace {

// Compiler diagnostics carry their position apart from the message: print it gcc-style, so
// that an error in an included file reads `lib.glsl:12: ...`.
void print_compiler_diagnostic(const Diagnostic& d) {
    std::string where;
    if (d.line > 0) {
        where = fmt::format("{}:{}: ", d.file, d.line);
    } else if (!d.file.empty() && d.message.rfind(d.file + ":", 0) != 0) {
        where = d.file + ": ";  // unless the message (a write failure) already names it
    }
    fmt::print(stderr, "arealight: {}: {}{}\n", to_string(d.severity), where, d.message);
}

// Make's rule syntax: a space in a path is escaped, as gcc -MD writes it.
std::string make_escaped(const std::string& path) {
    std::string out;
    for (char c : path) {
        if (c == ' ' || c == '#') out += '\\';
        if (c == '$') out += '$';
        out += c;
    }
    return out;
}

}  // namespace

int run_compile(const CompileArgs& args) {
    CompileOptions options;
    options.optimize = !args.no_opt;
    options.includes = true;
    options.include_dirs = args.include_dirs;
    options.language = language_from_path(args.shader);
    const bool hlsl = options.language == SourceLanguage::Hlsl;
    // x.frag.hlsl: the stage is the extension before .hlsl.
    const std::string stage_name =
        hlsl ? args.shader.substr(0, args.shader.size() - 5) : args.shader;
    const auto stage = args.stage.empty() ? stage_from_path(stage_name)
                                          : stage_from_path("." + args.stage);
    if (!stage) {
        print_compiler_diagnostic(
            {Severity::Error, args.shader, 0,
             hlsl ? "no shader stage for this HLSL file: name it x.vert.hlsl, x.frag.hlsl, "
                    "x.comp.hlsl (or .tesc, .tese, .geom before .hlsl), or give --stage"
                  : "no shader stage for this extension: name it .vert, .tesc, .tese, .geom, "
                    ".frag or .comp, or give --stage"});
        return kUsage;
    }
    options.stage = *stage;
    if (!args.entry.empty() && !hlsl) {
        print_compiler_diagnostic({Severity::Error, args.shader, 0,
                                   "-E names an HLSL entry function; a GLSL shader starts at "
                                   "main()"});
        return kUsage;
    }
    if (hlsl) {
        options.entry = "main";
        options.source_entry = args.entry.empty() ? "main" : args.entry;
    }
    if (!args.target_env.empty()) options.target_env = *target_env_from_string(args.target_env);

    std::ifstream in(args.shader, std::ios::binary);
    if (!in) {
        print_compiler_diagnostic({Severity::Error, args.shader, 0, "cannot read"});
        return kBadInput;
    }
    const std::string source((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());

    std::vector<std::string> included;
    const auto spirv = compile_shader(source, args.shader, options, print_compiler_diagnostic, &included);
    if (!spirv) return kBadInput;

    const std::string bytes(reinterpret_cast<const char*>(spirv->data()),
                            spirv->size() * sizeof(uint32_t));
    if (!args.depfile.empty()) {
        std::string rule = make_escaped(args.out) + ": " + make_escaped(args.shader);
        for (const auto& file : included) rule += " \\\n  " + make_escaped(file);
        rule += "\n";
        if (!write_file_atomic(args.depfile, rule, print_compiler_diagnostic)) return kRuntime;
    }
    if (!write_file_atomic(args.out, bytes, print_compiler_diagnostic)) return kRuntime;
    return kOk;
}

}  // namespace arealight::cli
