// The tables a generated library samples, as `arealight generate --tables DIR` describes them
// in DIR/tables.json (format arealight-tables/1): which binding takes which file and how the
// renderer must sample it.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

struct BadTables : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Table {
    std::string sampler;     // the library's uniform sampler2D
    int binding_offset = 0;  // its binding is AREALIGHT_BINDING + binding_offset
    int width = 0, height = 0;
    std::vector<float> rgba;  // width * height texels, row-major from v = 0
};

// Every table of DIR/tables.json with its texels; throws BadTables naming the file, the table
// and the field for a manifest or a sampling mode this renderer does not implement (it
// samples R32G32B32A32_SFLOAT, linear, clamp to edge, normalized coordinates, one level).
std::vector<Table> read_tables(const std::string& dir);
