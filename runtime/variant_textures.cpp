// The tables a variant samples (variant_samplers), by sampler name.
#include <stdexcept>
#include <string>

#include "arealight/evaluator.hpp"
#include "arealight/ltc_table.hpp"

namespace arealight {

std::vector<const Texture2D*> variant_textures(const Variant& v) {
    std::vector<const Texture2D*> out;
    for (const auto& name : variant_samplers(v)) {
        // The LTC tables (include/arealight/ltc_table.hpp): matrix, then amplitude.
        if (name == "al_ltc_matrix" || name == "al_ltc_amplitude") {
            const auto& ltc = builtin_ltc_textures(v.dist);
            const std::size_t k = name == "al_ltc_matrix" ? 0 : 1;
            if (ltc.size() <= k) {
                throw std::runtime_error("variant " + canonical_name(v) + ": the builtin LTC " +
                                         "tables of dist=" + to_string(v.dist) + " have " +
                                         std::to_string(ltc.size()) + " textures, not 2");
            }
            out.push_back(&ltc[k]);
            continue;
        }
        throw std::invalid_argument("variant " + canonical_name(v) + ": sampler '" + name +
                                    "' has no table (runtime/variant_textures.cpp knows "
                                    "al_ltc_matrix and al_ltc_amplitude)");
    }
    return out;
}

std::optional<std::vector<const Texture2D*>> variant_textures(const Variant& v,
                                                              const DiagnosticConsumer& diag) {
    try {
        return variant_textures(v);
    } catch (const std::exception& e) {
        if (diag) diag({Severity::Error, "", 0, e.what()});
        return std::nullopt;
    }
}

}  // namespace arealight
