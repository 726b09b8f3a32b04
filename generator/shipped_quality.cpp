// data/quality/measured.json, compiled in by cmake/embed_text.cmake, parsed once.
#include "arealight/scene_select.hpp"

namespace arealight {

const char* embedded_quality_text();

const QualityData& shipped_quality() {
    static const QualityData data =
        parse_quality(embedded_quality_text(), "data/quality/measured.json", {})
            .value_or(QualityData{});
    return data;
}

}  // namespace arealight
