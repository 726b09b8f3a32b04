// The severity of a SPIRV-Tools message as a Diagnostic's (the compiler's validation and
// optimization, and the unroller, report through it).
#pragma once

#include <spirv-tools/libspirv.h>

#include "arealight/diagnostics.hpp"

namespace arealight {

inline Severity severity_of(spv_message_level_t level) {
    switch (level) {
        case SPV_MSG_FATAL:
        case SPV_MSG_INTERNAL_ERROR:
        case SPV_MSG_ERROR:
            return Severity::Error;
        case SPV_MSG_WARNING:
            return Severity::Warning;
        case SPV_MSG_INFO:
        case SPV_MSG_DEBUG:
            return Severity::Note;
    }
    return Severity::Error;
}

}  // namespace arealight
