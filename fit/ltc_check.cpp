// arealight-ltc-check: the LTC specular of every polygon case of a table's distribution,
// computed in double precision exactly as the shader does (fit/ltc_check_eval.cpp), written
// as arealight-results/1 for shared/tools/score.
//
//   arealight-ltc-check --table data/ltc/ltc_ggx.txt --cases CASES.json --out OUT.json
#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "arealight/case_io.hpp"
#include "arealight/ltc_table.hpp"
#include "ltc_check.hpp"

int main(int argc, char** argv) {
    CLI::App app{"Evaluate a fitted LTC table on the polygon cases of its distribution"};
    std::string table_path, cases_path, out_path;
    app.add_option("--table", table_path, "LTC table file (arealight fit-ltc)")->required();
    app.add_option("--cases", cases_path, "arealight-cases/1 file")->required();
    app.add_option("--out", out_path, "arealight-results/1 file to write")->required();
    CLI11_PARSE(app, argc, argv);

    auto print = [](const arealight::Diagnostic& d) {
        std::fprintf(stderr, "arealight-ltc-check: %s\n", d.message.c_str());
    };
    std::ifstream in(table_path, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "arealight-ltc-check: %s: cannot read\n", table_path.c_str());
        return 1;
    }
    std::stringstream ss;
    ss << in.rdbuf();
    const auto table = arealight::parse_ltc_table(ss.str(), table_path, print);
    if (!table) return 1;
    const auto cases = arealight::read_cases(cases_path, print);
    if (!cases) return 1;
    arealight::ResultSet rs;
    rs.variant = std::string("dist=") + arealight::to_string(table->dist) +
                 ",method=ltc,light=polygon (arealight-ltc-check, fp64)";
    rs.backend = "cpu";
    for (const auto& c : cases->cases) {
        double spec, diff;
        if (!arealight::ltcfit::ltc_polygon_case(*table, c, spec, diff)) continue;
        arealight::CaseResult r;
        r.id = c.id;
        r.specular = spec;
        r.diffuse = diff;
        rs.results.push_back(r);
    }
    if (!arealight::write_results(out_path, rs, print)) return 3;
    std::fprintf(stderr, "arealight-ltc-check: %zu %s polygon cases\n", rs.results.size(),
                 arealight::to_string(table->dist));
    return 0;
}
