// Diagnostics are delivered to an injected consumer; the library never prints.
#pragma once

#include <functional>
#include <string>

namespace arealight {

enum class Severity { Note, Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string file;  // source the message is about (case file, template, ...)
    int line = 0;      // 0 when unknown
    std::string message;
};

// Receives every diagnostic. An empty consumer drops them (the library default).
using DiagnosticConsumer = std::function<void(const Diagnostic&)>;

// Progress of long work: `done` of `total` units finished.
using ProgressConsumer = std::function<void(std::size_t done, std::size_t total)>;

inline const char* to_string(Severity s) {
    switch (s) {
        case Severity::Note:
            return "note";
        case Severity::Warning:
            return "warning";
        case Severity::Error:
            return "error";
    }
    return "error";
}

}  // namespace arealight
