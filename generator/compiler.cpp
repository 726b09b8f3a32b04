// glslang front end, SPIRV-Tools validation and optimization. Nothing here prints: every message
// from either library is turned into a Diagnostic for the caller's consumer.
#include "arealight/compiler.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <cctype>
#include <memory>
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>
#include <sstream>

#include "arealight/spirv_instructions.hpp"
#include "file_includer.hpp"
#include "spirv_tools_severity.hpp"

namespace arealight {
namespace {

// Must match the client/target given to glslang (Vulkan 1.1 guarantees SPIR-V 1.3).
constexpr spv_target_env kTargetEnv = SPV_ENV_VULKAN_1_1;  // disassemble()

spv_target_env spirv_tools_env(TargetEnv env) {
    switch (env) {
        case TargetEnv::Vulkan1_0:
            return SPV_ENV_VULKAN_1_0;
        case TargetEnv::Vulkan1_1:
            return SPV_ENV_VULKAN_1_1;
        case TargetEnv::Vulkan1_2:
            return SPV_ENV_VULKAN_1_2;
        case TargetEnv::Vulkan1_3:
            return SPV_ENV_VULKAN_1_3;
    }
    return SPV_ENV_VULKAN_1_1;
}

// glslang's client and SPIR-V versions for a Vulkan version: each Vulkan's newest SPIR-V.
void set_glslang_env(glslang::TShader& shader, TargetEnv env) {
    switch (env) {
        case TargetEnv::Vulkan1_0:
            shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
            shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
            return;
        case TargetEnv::Vulkan1_1:
            shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
            shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
            return;
        case TargetEnv::Vulkan1_2:
            shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
            shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
            return;
        case TargetEnv::Vulkan1_3:
            shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3);
            shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_6);
            return;
    }
}
constexpr int kDefaultGlslVersion = 450;

// glslang needs InitializeProcess() before the first TShader and FinalizeProcess() once at the
// end; both are reference counted, so one function-local static owns a single reference.
class GlslangProcess {
  public:
    GlslangProcess() { glslang::InitializeProcess(); }
    ~GlslangProcess() { glslang::FinalizeProcess(); }
    GlslangProcess(const GlslangProcess&) = delete;
    GlslangProcess& operator=(const GlslangProcess&) = delete;
};

void ensure_glslang_initialized() {
    static GlslangProcess process;
}

// Tracks whether an error was reported, so a failure is never silent.
class Reporter {
  public:
    explicit Reporter(const DiagnosticConsumer& consumer) : consumer_(consumer) {}

    void operator()(Diagnostic d) {
        if (d.severity == Severity::Error) errors_ = true;
        if (consumer_) consumer_(d);
    }
    void error(const std::string& file, const std::string& message) {
        (*this)(Diagnostic{Severity::Error, file, 0, message});
    }
    bool any_error() const { return errors_; }

  private:
    const DiagnosticConsumer& consumer_;
    bool errors_ = false;
};

// Prefixes written by glslang's TInfoSink (Include/InfoSink.h).
struct Prefix {
    const char* text;
    Severity severity;
};
constexpr Prefix kPrefixes[] = {
    {"ERROR: ", Severity::Error},         {"INTERNAL ERROR: ", Severity::Error},
    {"UNIMPLEMENTED: ", Severity::Error}, {"UNKNOWN ERROR: ", Severity::Error},
    {"WARNING: ", Severity::Warning},     {"NOTE: ", Severity::Note},
};

// Splits "file:line: message" (TSourceLoc::getStringNameOrNum, then the line). The first
// ":<digits>: " is the separator, so a file name may itself contain colons before it.
bool split_location(const std::string& rest, std::string& file, int& line, std::string& message) {
    for (std::size_t colon = rest.find(':'); colon != std::string::npos;
         colon = rest.find(':', colon + 1)) {
        std::size_t end = colon + 1;
        while (end < rest.size() && std::isdigit(static_cast<unsigned char>(rest[end]))) ++end;
        if (end == colon + 1 || end >= rest.size() || rest[end] != ':' || colon == 0) continue;
        file = rest.substr(0, colon);
        line = std::stoi(rest.substr(colon + 1, end - colon - 1));
        message = rest.substr(end + 1);
        if (!message.empty() && message.front() == ' ') message.erase(0, 1);
        while (!message.empty() && message.back() == ' ') message.pop_back();
        return true;
    }
    return false;
}

// One Diagnostic per prefixed line of a glslang info log; unprefixed lines continue the previous
// message. glslang's "N compilation errors.  No code generated." summary repeats what was said.
void report_info_log(const char* log, const std::string& source_name, Reporter& report) {
    std::istringstream lines(log ? log : "");
    std::string text;
    // A plain value plus flag: GCC 12 warns falsely (-Wmaybe-uninitialized) on optional here.
    Diagnostic pending;
    bool has_pending = false;
    auto flush = [&] {
        if (has_pending) report(std::move(pending));
        has_pending = false;
    };
    while (std::getline(lines, text)) {
        if (!text.empty() && text.back() == '\r') text.pop_back();
        if (text.find_first_not_of(" \t") == std::string::npos) continue;
        const Prefix* prefix = nullptr;
        for (const Prefix& p : kPrefixes) {
            if (text.rfind(p.text, 0) == 0) {
                prefix = &p;
                break;
            }
        }
        if (!prefix) {
            if (has_pending) {
                pending.message += "\n" + text;
            } else {
                pending = Diagnostic{Severity::Note, source_name, 0, text};
                has_pending = true;
            }
            continue;
        }
        flush();
        const std::string rest = text.substr(std::char_traits<char>::length(prefix->text));
        Diagnostic d{prefix->severity, source_name, 0, rest};
        if (!split_location(rest, d.file, d.line, d.message)) {
            if (rest.find("No code generated.") != std::string::npos) continue;
        }
        pending = std::move(d);
        has_pending = true;
    }
    flush();
}

// SPIRV-Tools drops messages unless a consumer is installed (libspirv.hpp SetMessageConsumer).
spvtools::MessageConsumer spirv_tools_consumer(const std::string& tool,
                                               const std::string& source_name, Reporter& report) {
    return [&report, tool, source_name](spv_message_level_t level, const char*,
                                        const spv_position_t& position, const char* message) {
        std::string text = tool + ": " + (message ? message : "");
        if (position.index != 0) text += " (word " + std::to_string(position.index) + ")";
        report(Diagnostic{severity_of(level), source_name, 0, std::move(text)});
    };
}

// glslang 12 ignores TShader::setEntryPoint for GLSL and rejects a source entry other than "main"
// (ParseHelper.cpp), so the name is replaced in OpEntryPoint after translation.
void rename_entry_point(std::vector<uint32_t>& spirv, const std::string& name) {
    constexpr uint32_t kOpEntryPoint = 15;
    // Not for_each_spirv_instruction: the walk rewrites the instruction it stands on.
    for (std::size_t at = kSpirvHeaderWords; at < spirv.size();) {
        const std::size_t words = spirv[at] >> 16;
        if (words == 0 || at + words > spirv.size()) return;
        if ((spirv[at] & 0xffffu) != kOpEntryPoint) {
            at += words;
            continue;
        }
        // Operands: execution model, function id, nul-terminated name packed into words, then ids.
        std::size_t name_end = at + 3;
        while (name_end < at + words && (spirv[name_end] >> 24) != 0) ++name_end;
        ++name_end;
        std::vector<uint32_t> packed((name.size() + 4) / 4, 0u);
        for (std::size_t i = 0; i < name.size(); ++i) {
            packed[i / 4] |= static_cast<uint32_t>(static_cast<unsigned char>(name[i]))
                             << (8 * (i % 4));
        }
        std::vector<uint32_t> rebuilt(spirv.begin() + at, spirv.begin() + at + 3);
        rebuilt.insert(rebuilt.end(), packed.begin(), packed.end());
        rebuilt.insert(rebuilt.end(), spirv.begin() + name_end, spirv.begin() + at + words);
        rebuilt[0] = static_cast<uint32_t>(rebuilt.size() << 16) | kOpEntryPoint;
        spirv.erase(spirv.begin() + at, spirv.begin() + at + words);
        spirv.insert(spirv.begin() + at, rebuilt.begin(), rebuilt.end());
        at += rebuilt.size();
    }
}

bool validate(const std::vector<uint32_t>& spirv, spv_target_env env, const std::string& stage,
              const std::string& source_name, Reporter& report) {
    spvtools::SpirvTools tools(env);
    tools.SetMessageConsumer(spirv_tools_consumer("spirv-val", source_name, report));
    if (tools.Validate(spirv)) return true;
    report.error(source_name, "SPIR-V validation failed " + stage);
    return false;
}

EShLanguage glslang_stage(ShaderStage stage) {
    switch (stage) {
        case ShaderStage::Vertex:
            return EShLangVertex;
        case ShaderStage::TessControl:
            return EShLangTessControl;
        case ShaderStage::TessEvaluation:
            return EShLangTessEvaluation;
        case ShaderStage::Geometry:
            return EShLangGeometry;
        case ShaderStage::Fragment:
            return EShLangFragment;
        case ShaderStage::Compute:
            return EShLangCompute;
    }
    return EShLangCompute;
}

// glslang's preamble is read before the shader's first line but after its #version, which
// glslang scans for separately; this is how glslc spares users the #extension line.
constexpr const char* kIncludePreamble = "#extension GL_GOOGLE_include_directive : enable\n";

// glslang front end: parse, link and translate. The program refers to the shader's intermediate
// tree, so it is declared after the shader and therefore destroyed first (ShaderLang.h).
std::optional<std::vector<uint32_t>> glsl_to_spirv(const std::string& source,
                                                   const std::string& source_name,
                                                   const CompileOptions& options,
                                                   Reporter& report,
                                                   std::vector<std::string>* included_files) {
    ensure_glslang_initialized();
    const EShLanguage stage = glslang_stage(options.stage);
    glslang::TShader shader(stage);
    const char* text = source.c_str();
    const int length = static_cast<int>(source.size());
    const char* name = source_name.c_str();
    shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
    const bool hlsl = options.language == SourceLanguage::Hlsl;
    shader.setEnvInput(hlsl ? glslang::EShSourceHlsl : glslang::EShSourceGlsl, stage,
                       glslang::EShClientVulkan, 100);
    // glslang 12's HLSL front end marks structured buffers BufferBlock, which SPIR-V 1.4
    // removed: HLSL for Vulkan 1.2 and 1.3 is SPIR-V 1.3 (which every Vulkan >= 1.1 takes),
    // validated for the Vulkan asked for.
    set_glslang_env(shader, hlsl && options.target_env > TargetEnv::Vulkan1_1 ? TargetEnv::Vulkan1_1
                                                                              : options.target_env);
    auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    if (hlsl) {
        // HLSL names its entry function; the module's entry point is options.entry. Its
        // preprocessor takes #include and #line "file" without an extension.
        messages = static_cast<EShMessages>(messages | EShMsgReadHlsl);
        shader.setEntryPoint(options.entry.c_str());
        shader.setSourceEntryPoint(
            (options.source_entry.empty() ? options.entry : options.source_entry).c_str());
        // A Texture2D and the SamplerState it is sampled with become one combined image
        // sampler at the texture's binding: the descriptors the GLSL form's sampler2D
        // takes, so both libraries bind their tables the same way (tables.json).
        shader.setTextureSamplerTransformMode(EShTexSampTransUpgradeTextureRemoveSampler);
    }

    if (options.includes && !hlsl) shader.setPreamble(kIncludePreamble);
    FileIncluder includer(options.include_dirs);
    const bool parsed =
        shader.parse(GetDefaultResources(), kDefaultGlslVersion, false, messages, includer);
    if (included_files) *included_files = includer.files();
    report_info_log(shader.getInfoLog(), source_name, report);
    // glslang can log an ERROR and still return true; an error always means failure here.
    if (!parsed || report.any_error()) {
        if (!report.any_error()) report.error(source_name, "glslang: compilation failed");
        return std::nullopt;
    }

    glslang::TProgram program;
    program.addShader(&shader);
    const bool linked = program.link(messages);
    report_info_log(program.getInfoLog(), source_name, report);
    // Without the named entry function glslang's HLSL front end warns and writes an empty
    // main(): an error here.
    if (hlsl && std::string(program.getInfoLog()).find("Entry point not found") != std::string::npos) {
        report.error(source_name, "no entry function " +
                                      (options.source_entry.empty() ? options.entry
                                                                    : options.source_entry) +
                                      " in the HLSL shader (name it with -E)");
        return std::nullopt;
    }
    if (!linked || report.any_error()) {
        if (!report.any_error()) report.error(source_name, "glslang: linking failed");
        return std::nullopt;
    }

    std::vector<uint32_t> spirv;
    spv::SpvBuildLogger logger;
    glslang::SpvOptions spv_options;
    spv_options.disableOptimizer = true;  // SPIRV-Tools does this below, with validation
    glslang::GlslangToSpv(*program.getIntermediate(stage), spirv, &logger, &spv_options);
    const std::string spv_messages = logger.getAllMessages();
    if (!spv_messages.empty()) {
        report(Diagnostic{Severity::Warning, source_name, 0, "glslang SPIR-V: " + spv_messages});
    }
    if (spirv.empty()) {
        report.error(source_name, "glslang produced no SPIR-V");
        return std::nullopt;
    }
    if (!hlsl && options.entry != "main") rename_entry_point(spirv, options.entry);
    return spirv;
}

}  // namespace

std::optional<std::vector<uint32_t>> compile_shader(const std::string& source,
                                                  const std::string& source_name,
                                                  const CompileOptions& options,
                                                  const DiagnosticConsumer& diag,
                                                  std::vector<std::string>* included_files) {
    Reporter report(diag);
    if (included_files) included_files->clear();
    if (options.entry.empty()) {
        report.error(source_name, "CompileOptions::entry is empty");
        return std::nullopt;
    }
    const spv_target_env env = spirv_tools_env(options.target_env);
    std::optional<std::vector<uint32_t>> spirv =
        glsl_to_spirv(source, source_name, options, report, included_files);
    if (!spirv) return std::nullopt;
    // glslang's HLSL output is valid only after legalization (HLSL passes resources and
    // structs holding them by value; spirv-opt's --legalize-hlsl), whether optimized or not.
    const bool legalize = options.language == SourceLanguage::Hlsl;
    if (!legalize && !validate(*spirv, env, "after glslang", source_name, report)) return std::nullopt;
    if (!options.optimize && !legalize) return spirv;

    spvtools::Optimizer optimizer(env);
    optimizer.SetMessageConsumer(spirv_tools_consumer("spirv-opt", source_name, report));
    if (legalize) optimizer.RegisterLegalizationPasses();
    if (options.optimize) optimizer.RegisterPerformancePasses();
    std::vector<uint32_t> optimized;
    if (!optimizer.Run(spirv->data(), spirv->size(), &optimized)) {
        report.error(source_name, "spirv-opt failed");
        return std::nullopt;
    }
    if (!validate(optimized, env, options.optimize ? "after spirv-opt" : "after legalization",
                  source_name, report)) {
        return std::nullopt;
    }
    return optimized;
}

std::optional<ShaderStage> stage_from_path(const std::string& path) {
    const std::size_t dot = path.rfind('.');
    const std::size_t slash = path.find_last_of("/\\");
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::nullopt;
    const std::string ext = path.substr(dot + 1);
    for (ShaderStage s : {ShaderStage::Vertex, ShaderStage::TessControl, ShaderStage::TessEvaluation,
                          ShaderStage::Geometry, ShaderStage::Fragment, ShaderStage::Compute}) {
        if (ext == to_string(s)) return s;
    }
    return std::nullopt;
}

const char* to_string(ShaderStage stage) {
    switch (stage) {
        case ShaderStage::Vertex:
            return "vert";
        case ShaderStage::TessControl:
            return "tesc";
        case ShaderStage::TessEvaluation:
            return "tese";
        case ShaderStage::Geometry:
            return "geom";
        case ShaderStage::Fragment:
            return "frag";
        case ShaderStage::Compute:
            return "comp";
    }
    return "comp";
}

SourceLanguage language_from_path(const std::string& path) {
    const std::size_t dot = path.rfind('.');
    const std::size_t slash = path.find_last_of("/\\");
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) {
        return SourceLanguage::Glsl;
    }
    return path.substr(dot + 1) == "hlsl" ? SourceLanguage::Hlsl : SourceLanguage::Glsl;
}

const char* to_string(TargetEnv env) {
    switch (env) {
        case TargetEnv::Vulkan1_0:
            return "vulkan1.0";
        case TargetEnv::Vulkan1_1:
            return "vulkan1.1";
        case TargetEnv::Vulkan1_2:
            return "vulkan1.2";
        case TargetEnv::Vulkan1_3:
            return "vulkan1.3";
    }
    return "vulkan1.1";
}

std::optional<TargetEnv> target_env_from_string(const std::string& name) {
    for (TargetEnv e : {TargetEnv::Vulkan1_0, TargetEnv::Vulkan1_1, TargetEnv::Vulkan1_2,
                        TargetEnv::Vulkan1_3}) {
        if (name == to_string(e)) return e;
    }
    return std::nullopt;
}

std::size_t spirv_instruction_count(const std::vector<uint32_t>& spirv) {
    std::size_t count = 0;
    for_each_spirv_instruction(spirv, [&](std::size_t, uint32_t, uint32_t) { ++count; });
    return count;
}

std::size_t spirv_texture_sample_count(const std::vector<uint32_t>& spirv) {
    // OpImageSampleImplicitLod (87) .. OpImageSparseDrefGather (96 excluded: 95 is
    // OpImageFetch) and their sparse forms (305 .. 315): every instruction that reads
    // an image through a sampler or by texel (SPIR-V spec 3.37.10).
    auto samples = [](uint32_t op) { return (op >= 87 && op <= 95) || (op >= 305 && op <= 315); };
    std::size_t count = 0;
    for_each_spirv_instruction(spirv,
                               [&](std::size_t, uint32_t, uint32_t op) { count += samples(op); });
    return count;
}

std::string disassemble(const std::vector<uint32_t>& spirv) {
    spvtools::SpirvTools tools(kTargetEnv);
    std::string text;
    const uint32_t options =
        SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES | SPV_BINARY_TO_TEXT_OPTION_INDENT;
    if (!tools.Disassemble(spirv, &text, options)) return {};
    return text;
}

}  // namespace arealight
