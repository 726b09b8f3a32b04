// What every reader fuzz target checks besides the sanitizers: a reader that fails
// says why (at least one error), and one that succeeds reports no error.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "arealight/diagnostics.hpp"

namespace arealight::fuzz {

// Counts the errors a reader reports.
struct ErrorCounter {
    int errors = 0;
    DiagnosticConsumer consumer() {
        return [this](const Diagnostic& d) {
            if (d.severity == Severity::Error) ++errors;
        };
    }
};

// Stops the run (libFuzzer then saves the input) when `ok` is false.
inline void require(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "fuzz invariant violated: %s\n", what);
    std::abort();
}

// A nullopt result has at least one error; a value has none.
template <typename T>
void require_reported(const std::optional<T>& result, const ErrorCounter& counter) {
    require(result.has_value() == (counter.errors == 0),
            result ? "a successful read reported an error" : "a failed read reported no error");
}

// The fuzzer's bytes as text, given to `read(text, consumer)`, whose result must agree with
// what it reported (require_reported).
template <typename Read>
auto read_checked(const std::uint8_t* data, std::size_t size, Read read) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    ErrorCounter counter;
    auto result = read(text, counter.consumer());
    require_reported(result, counter);
    return result;
}

}  // namespace arealight::fuzz
