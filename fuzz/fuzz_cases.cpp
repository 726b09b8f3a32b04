// libFuzzer target: parse_cases (arealight-cases/1) on arbitrary bytes.
#include <cstddef>
#include <cstdint>
#include <string>

#include "accepted.hpp"
#include "arealight/case_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace arealight;
    const auto set = fuzz::read_checked(data, size, [](const std::string& text, auto diag) {
        return parse_cases(text, "fuzz.cases.json", diag);
    });
    if (!set) return 0;
    for (const Case& c : set->cases) {
        fuzz::require(!c.id.empty(), "accepted case without id");
        fuzz::require(fuzz::finite(c.p) && fuzz::finite(c.n) && fuzz::finite(c.v),
                      "accepted non-finite p, n or v");
        fuzz::check_accepted(c.light);
        fuzz::check_accepted(c.material);
    }
    return 0;
}
