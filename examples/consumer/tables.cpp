#include "tables.hpp"

#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

namespace {

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw BadTables(path + ": cannot read");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// `field` of table `where` must equal `want`: the only way this renderer samples.
void expect(const nlohmann::json& t, const char* field, const std::string& want,
            const std::string& where) {
    if (!t.contains(field) || t[field] != want)
        throw BadTables(where + ": field '" + field + "': expected \"" + want + "\"");
}

}  // namespace

std::vector<Table> read_tables(const std::string& dir) {
    const std::string manifest = dir + "/tables.json";
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(read_bytes(manifest));
    } catch (const nlohmann::json::exception& e) {
        throw BadTables(manifest + ": " + e.what());
    }
    if (j.value("format", "") != "arealight-tables/1")
        throw BadTables(manifest + ": field 'format': expected \"arealight-tables/1\"");
    std::vector<Table> tables;
    try {
        for (std::size_t i = 0; i < j.at("tables").size(); ++i) {
            const nlohmann::json& t = j["tables"][i];
            const std::string where = manifest + ": tables[" + std::to_string(i) + "]";
            expect(t, "format", "R32G32B32A32_SFLOAT", where);
            expect(t, "filter", "linear", where);
            expect(t, "address_mode", "clamp_to_edge", where);
            expect(t, "coordinates", "normalized", where);
            if (t.at("mipmaps") != 1) throw BadTables(where + ": field 'mipmaps': expected 1");
            Table table;
            table.sampler = t.at("sampler").get<std::string>();
            table.binding_offset = t.at("binding_offset").get<int>();
            table.width = t.at("width").get<int>();
            table.height = t.at("height").get<int>();
            if (table.width < 1 || table.height < 1 || table.width > 4096 || table.height > 4096)
                throw BadTables(where + ": fields 'width', 'height': 1 to 4096 texels");
            const std::string file = dir + "/" + t.at("file").get<std::string>();
            const std::string bytes = read_bytes(file);
            const std::size_t texels = std::size_t(table.width) * table.height;
            if (bytes.size() != texels * 4 * sizeof(float))
                throw BadTables(file + ": " + std::to_string(bytes.size()) + " bytes, expected " +
                                std::to_string(texels * 4 * sizeof(float)) + " (" + where + ")");
            // Little-endian fp32 in the file, as on this (x86-64 or aarch64) host.
            table.rgba.resize(texels * 4);
            std::memcpy(table.rgba.data(), bytes.data(), bytes.size());
            tables.push_back(std::move(table));
        }
    } catch (const nlohmann::json::exception& e) {
        throw BadTables(manifest + ": " + e.what());
    }
    return tables;
}
