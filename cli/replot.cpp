#include "replot.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <utility>

#include "arealight/atomic_file.hpp"
#include "arealight/read_file.hpp"
#include "arealight/report.hpp"
#include "exit_code.hpp"
#include "print_diagnostic.hpp"

namespace arealight::cli {

int run_replot(const ReplotArgs& args) {
    // Every folder is read before anything is written.
    std::vector<std::pair<std::string, Report>> reports;
    for (const auto& dir : args.dirs) {
        std::string stem;
        for (const char* s : {"report", "sweep"})
            if (std::filesystem::exists(dir + "/" + s + ".json")) stem = s;
        if (stem.empty()) {
            print_diagnostic({Severity::Error, dir, 0,
                              dir + ": no report.json or sweep.json (arealight report or sweep "
                                    "writes them)"});
            return kBadInput;
        }
        const std::string path = dir + "/" + stem + ".json";
        const auto text = read_file(path, print_diagnostic);
        if (!text) return kBadInput;
        auto report = read_report_json(*text, path, print_diagnostic);
        if (!report) return kBadInput;
        if (report->sweep() != (stem == "sweep")) {
            print_diagnostic({Severity::Error, path, 0,
                              path + ": a " + (report->sweep() ? "sweep" : "report") +
                                  " in a file named " + stem + ".json"});
            return kBadInput;
        }
        reports.emplace_back(dir + "/" + stem, std::move(*report));
    }
    for (const auto& [stem, report] : reports) {
        const std::string dir = std::filesystem::path(stem).parent_path().string();
        std::vector<std::pair<std::string, std::string>> files = {
            {stem + ".json", report_json(report)}, {stem + ".md", report_markdown(report)}};
        for (auto& [name, svg] : report_pictures(report))
            files.emplace_back(dir + "/" + name, std::move(svg));
        for (const auto& [path, text] : files)
            if (!write_file_atomic(path, text, print_diagnostic)) return kRuntime;
        fmt::print(stderr, "replot: {} ({} rows): {} files\n", stem, report.rows.size(),
                   files.size());
    }
    return kOk;
}

}  // namespace arealight::cli
