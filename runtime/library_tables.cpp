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
    // One entry per table the library declares (library_samplers): a sampler that reads
    // an earlier one's table is listed under that entry's "also", not again.
    const std::vector<LibrarySampler> plan = library_samplers(variants);
    nlohmann::ordered_json tables = nlohmann::ordered_json::array();
    std::vector<int> row_of(plan.size(), -1);
    for (std::size_t e = 0; e < plan.size(); ++e) {
        const LibrarySampler& s = plan[e];
        const Variant& v = variants[s.variant];
        if (s.shares >= 0) {
            const int row = row_of[static_cast<std::size_t>(s.shares)];
            tables[static_cast<std::size_t>(row)]["also"].push_back(
                {{"variant", canonical_name(v)}, {"sampler", library_rename(s.sampler, v)}});
            continue;
        }
        const std::vector<std::string> samplers = variant_samplers(v);
        std::size_t k = 0;
        while (k < samplers.size() && samplers[k] != s.sampler) ++k;
        const auto textures = variant_textures(v, diag);
        if (!textures || k >= textures->size()) return false;
        const Texture2D& t = *(*textures)[k];
        const std::string bare = s.sampler.rfind("al_", 0) == 0 ? s.sampler.substr(3) : s.sampler;
        const std::string file =
            fmt::format("{}_{}_{}.rgba32f", to_string(v.light), to_string(v.dist), bare);
        // The host is little-endian (x86-64, aarch64): the bytes are the floats.
        const std::string bytes(reinterpret_cast<const char*>(t.rgba.data()), t.bytes());
        if (!write_file_atomic((std::filesystem::path(dir) / file).string(), bytes, diag))
            return false;
        nlohmann::ordered_json row;
        row["variant"] = canonical_name(v);
        row["sampler"] = library_rename(s.sampler, v);
        row["set_macro"] = "AREALIGHT_SET";
        row["binding_macro"] = sampler_binding_macro(v, s.sampler);
        row["default_binding"] = fmt::format("AREALIGHT_BINDING + {}", s.binding_offset);
        row["binding_offset"] = s.binding_offset;
        // The HLSL library's texture and sampler state (register(tN), register(sN) in space
        // AREALIGHT_SPACE; one combined image sampler at binding N through glslang).
        row["space_macro"] = "AREALIGHT_SPACE";
        row["register_macro"] = sampler_register_macro(v, s.sampler);
        row["default_register"] = s.binding_offset;
        row["file"] = file;
        row["width"] = t.width;
        row["height"] = t.height;
        row["format"] = "R32G32B32A32_SFLOAT";
        row["layout"] = "row-major from v = 0, 4 little-endian fp32 per texel";
        row["filter"] = "linear";
        row["mipmaps"] = 1;
        row["address_mode"] = "clamp_to_edge";
        row["coordinates"] = "normalized";
        row_of[e] = static_cast<int>(tables.size());
        tables.push_back(std::move(row));
    }
    nlohmann::ordered_json manifest;
    manifest["format"] = "arealight-tables/1";
    manifest["generated_by"] = "arealight generate --tables; do not edit";
    manifest["tables"] = std::move(tables);
    return write_file_atomic((std::filesystem::path(dir) / "tables.json").string(),
                             manifest.dump(1) + "\n", diag);
}

}  // namespace arealight
