#include "fit_ltc.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>

#include "arealight/atomic_file.hpp"
#include "arealight/ltc_table.hpp"
#include "exit_code.hpp"
#include "print_diagnostic.hpp"

namespace arealight::cli {

namespace {

Distribution distribution_of(const std::string& s) {
    for (Distribution d : {Distribution::Phong, Distribution::Blinn, Distribution::Beckmann,
                           Distribution::Ggx}) {
        if (s == to_string(d)) return d;
    }
    return Distribution::Ggx;  // unreachable: CLI11 checks the name
}

}  // namespace

int run_fit_ltc(const FitLtcArgs& args) {
    const Distribution d = distribution_of(args.dist);
    LtcFitOptions opt;
    opt.size = args.size;
    opt.threads = static_cast<int>(args.threads);
    const auto start = std::chrono::steady_clock::now();
    const bool live = isatty(fileno(stderr)) != 0;
    auto last = start;
    opt.progress = [&](int done, int total) {
        const auto now = std::chrono::steady_clock::now();
        if (done != total && now - last < std::chrono::milliseconds(live ? 250 : 5000)) return;
        last = now;
        std::fprintf(stderr, "%sfit-ltc %s: %d/%d cells, %.1f s%s", live ? "\r" : "",
                     args.dist.c_str(), done, total,
                     std::chrono::duration<double>(now - start).count(),
                     live && done != total ? "" : "\n");
        std::fflush(stderr);
    };
    auto table = fit_ltc(d, opt, print_diagnostic);
    if (!table) return kRuntime;
    table->command = "arealight fit-ltc --dist " + args.dist + " --size " +
                     std::to_string(args.size) + " --out " + args.out;
    if (!write_file_atomic(args.out, format_ltc_table(*table), print_diagnostic)) return kRuntime;
    std::fprintf(stderr, "fit-ltc %s: %dx%d cells in %.1f s; wrote %s\n", args.dist.c_str(),
                 args.size, args.size,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                 args.out.c_str());
    return kOk;
}

}  // namespace arealight::cli
