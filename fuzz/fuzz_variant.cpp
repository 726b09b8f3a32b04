// libFuzzer target: parse_variant and variant_matches on arbitrary bytes.
#include <cstddef>
#include <cstdint>
#include <string>

#include "arealight/variant.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace arealight;
    const auto v = fuzz::read_checked(data, size, [](const std::string& text, auto diag) {
        return parse_variant(text, diag);
    });
    const std::string name(reinterpret_cast<const char*>(data), size);
    // The input as a partial-name pattern: a matcher must not crash on what the parser rejects.
    static const Variant fixed = *parse_variant("dist=ggx,method=ltc,light=polygon", {});
    (void)variant_matches(fixed, name);
    if (!v) return 0;
    // parse_variant returns exactly the valid variants, and the canonical name reads back.
    fuzz::require(is_valid(*v), "parse_variant accepted an invalid variant");
    const auto back = parse_variant(canonical_name(*v), {});
    fuzz::require(back && *back == *v, "canonical_name does not read back as the same variant");
    // A variant matches the name it was parsed from, as spelled ("nodes=02" included:
    // fuzz/crashes/README.md, finding 1), and its canonical name.
    fuzz::require(variant_matches(*v, name), "a variant does not match the name it was read from");
    fuzz::require(variant_matches(*v, canonical_name(*v)),
                  "a variant does not match its canonical name");
    return 0;
}
