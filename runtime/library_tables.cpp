#include "arealight/library_tables.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "arealight/atomic_file.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/generator.hpp"

namespace arealight {

bool write_library_tables(const std::vector<Variant>& variants, const std::string& dir,
                          const DiagnosticConsumer& diag) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        if (diag) diag({Severity::Error, dir, 0, dir + ": cannot create: " + ec.message()});
        return false;
    }
    nlohmann::ordered_json tables = nlohmann::ordered_json::array();
    int index = 0;  // the sampler's place in the library: binding AREALIGHT_BINDING + index
    for (const auto& v : variants) {
        const std::vector<std::string> samplers = variant_samplers(v);
        if (samplers.empty()) continue;
        const auto textures = variant_textures(v, diag);
        if (!textures) return false;
        for (std::size_t k = 0; k < samplers.size(); ++k, ++index) {
            const std::string& sampler = samplers[k];
            const Texture2D& t = *(*textures)[k];
            const std::string bare = sampler.rfind("al_", 0) == 0 ? sampler.substr(3) : sampler;
            const std::string file = fmt::format("{}_{}_{}.rgba32f", to_string(v.light),
                                                 to_string(v.dist), bare);
            // The host is little-endian (x86-64, aarch64): the bytes are the floats.
            const std::string bytes(reinterpret_cast<const char*>(t.rgba.data()), t.bytes());
            if (!write_file_atomic((std::filesystem::path(dir) / file).string(), bytes, diag))
                return false;
            nlohmann::ordered_json e;
            e["variant"] = canonical_name(v);
            e["sampler"] = library_rename(sampler, v);
            e["set_macro"] = "AREALIGHT_SET";
            e["binding_macro"] = sampler_binding_macro(v, sampler);
            e["default_binding"] = fmt::format("AREALIGHT_BINDING + {}", index);
            e["binding_offset"] = index;
            e["file"] = file;
            e["width"] = t.width;
            e["height"] = t.height;
            e["format"] = "R32G32B32A32_SFLOAT";
            e["layout"] = "row-major from v = 0, 4 little-endian fp32 per texel";
            e["filter"] = "linear";
            e["mipmaps"] = 1;
            e["address_mode"] = "clamp_to_edge";
            e["coordinates"] = "normalized";
            tables.push_back(std::move(e));
        }
    }
    nlohmann::ordered_json manifest;
    manifest["format"] = "arealight-tables/1";
    manifest["generated_by"] = "arealight generate --tables; do not edit";
    manifest["tables"] = std::move(tables);
    return write_file_atomic((std::filesystem::path(dir) / "tables.json").string(),
                             manifest.dump(1) + "\n", diag);
}

}  // namespace arealight
