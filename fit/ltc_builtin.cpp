// The committed tables (data/ltc/*.txt, compiled in by fit/embed_ltc.cmake), parsed once.
#include <array>
#include <cstdio>
#include <cstdlib>

#include "arealight/ltc_table.hpp"
#include "embedded_ltc.hpp"

namespace arealight {

namespace {

const std::array<LtcTable, 4>& builtin_tables() {
    static const std::array<LtcTable, 4> tables = [] {
        std::array<LtcTable, 4> out;
        for (const Distribution d : {Distribution::Phong, Distribution::Blinn,
                                     Distribution::Beckmann, Distribution::Ggx}) {
            const std::string name = std::string("data/ltc/ltc_") + to_string(d) + ".txt";
            auto t = parse_ltc_table(embedded_ltc_table(d), name, [](const Diagnostic& g) {
                std::fprintf(stderr, "arealight: internal error: builtin %s\n", g.message.c_str());
            });
            if (!t || t->dist != d) std::abort();  // the build embedded a broken table
            out[static_cast<int>(d)] = std::move(*t);
        }
        return out;
    }();
    return tables;
}

}  // namespace

const LtcTable& builtin_ltc_table(Distribution d) {
    return builtin_tables()[static_cast<int>(d)];
}

const std::vector<Texture2D>& builtin_ltc_textures(Distribution d) {
    static const std::array<std::vector<Texture2D>, 4> textures = [] {
        std::array<std::vector<Texture2D>, 4> out;
        for (int k = 0; k < 4; ++k) out[k] = ltc_textures(builtin_tables()[k]);
        return out;
    }();
    return textures[static_cast<int>(d)];
}

}  // namespace arealight
