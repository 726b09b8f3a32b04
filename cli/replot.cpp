#include "replot.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <utility>

#include "arealight/atomic_file.hpp"
#include "arealight/read_file.hpp"
#include "arealight/report.hpp"
#include "print_diagnostic.hpp"

namespace arealight::cli {

namespace {

enum Exit { kOk = 0, kBadInput = 1, kRuntime = 3 };

}  // namespace

CLI::App* add_replot_command(CLI::App& app, ReplotArgs& args) {
    auto* cmd = app.add_subcommand(
        "replot",
        "Draw a report's or sweep's markdown and pictures again from its JSON (DIR/report.json "
        "or DIR/sweep.json), with today's plots and marks (Pareto front, recommended "
        "variant), without measuring again; the JSON is rewritten with the marks");
    cmd->add_option("dirs", args.dirs, "folders that arealight report or sweep wrote")->required();
    return cmd;
}

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
