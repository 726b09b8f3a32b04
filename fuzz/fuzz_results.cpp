// libFuzzer target: parse_results (arealight-results/1) on arbitrary bytes, and the
// writer's round trip of whatever it accepts.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "arealight/case_io.hpp"
#include "fuzz_support.hpp"

namespace {

// Bitwise for present values: the writer promises round-trip-exact doubles.
bool same(const std::optional<double>& a, const std::optional<double>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || std::memcmp(&*a, &*b, sizeof(double)) == 0;
}

bool same(const arealight::CaseResult& a, const arealight::CaseResult& b) {
    return a.id == b.id && same(a.diffuse, b.diffuse) && same(a.specular, b.specular) &&
           same(a.ndf, b.ndf) && same(a.moment, b.moment) && same(a.error, b.error) &&
           same(a.error_diffuse, b.error_diffuse) && same(a.error_ndf, b.error_ndf) &&
           same(a.error_moment, b.error_moment) && a.converged == b.converged;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace arealight;
    const auto set = fuzz::read_checked(data, size, [](const std::string& text, auto diag) {
        return parse_results(text, "fuzz.results.json", diag);
    });
    if (!set) return 0;
    // Whatever was read is written and read back unchanged.
    fuzz::ErrorCounter again_counter;
    const auto again = parse_results(format_results(*set), "round-trip", again_counter.consumer());
    fuzz::require(again.has_value(), "the writer's output of an accepted file does not read back");
    fuzz::require(again->variant == set->variant && again->backend == set->backend &&
                      again->results.size() == set->results.size(),
                  "round trip changed the header or the result count");
    for (std::size_t i = 0; i < set->results.size(); ++i)
        fuzz::require(same(again->results[i], set->results[i]), "round trip changed a result");
    return 0;
}
