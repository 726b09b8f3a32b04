// Seed preparation for the JSON fuzz targets: splits arealight-cases/1 and
// arealight-results/1 files (tens to hundreds of kB) into files of one case or result
// each, under the fuzzers' input size limit, keeping the file's other keys.
//   split_seeds OUT_DIR MAX_PER_FILE FILE...
// Spreads the picks over each file (every k-th entry) so that its variety survives the cap.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

int main(int argc, char** argv) {
    if (argc < 4) {
        std::cerr << "usage: split_seeds OUT_DIR MAX_PER_FILE FILE...\n";
        return 2;
    }
    const std::string out = argv[1];
    const long cap = std::strtol(argv[2], nullptr, 10);
    if (cap <= 0) {
        std::cerr << "split_seeds: MAX_PER_FILE must be a positive integer\n";
        return 2;
    }
    int written = 0;
    for (int a = 3; a < argc; ++a) {
        std::ifstream in(argv[a]);
        std::stringstream text;
        text << in.rdbuf();
        const auto doc = nlohmann::json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
        if (!doc.is_object()) {
            std::cerr << "split_seeds: " << argv[a] << ": not a JSON object\n";
            return 1;
        }
        const char* list = doc.contains("cases") ? "cases" : "results";
        const auto it = doc.find(list);
        if (it == doc.end() || !it->is_array() || it->empty()) continue;
        const std::size_t n = it->size();
        const std::size_t step = (n + static_cast<std::size_t>(cap) - 1) / static_cast<std::size_t>(cap);
        for (std::size_t i = 0; i < n; i += step) {
            nlohmann::json one = doc;
            one[list] = nlohmann::json::array({(*it)[i]});
            std::ofstream(out + "/" + std::to_string(written++) + ".json") << one.dump();
        }
    }
    std::cout << "split_seeds: " << written << " seeds in " << out << "\n";
    return 0;
}
