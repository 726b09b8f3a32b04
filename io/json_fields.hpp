// What every arealight JSON reader shares (case, result, scene, render scene and quality
// files): reading the file, parsing it, and "FILE: WHERE: field 'F': reason" messages,
// an unknown field named with the nearest known one (CONTRACT 3).
#pragma once

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "arealight/diagnostics.hpp"

namespace arealight::io_detail {

// "FILE: MESSAGE" as an error.
void report(const DiagnosticConsumer& diag, const std::string& file, const std::string& message);

// The whole file, or nullopt after "FILE: cannot read: REASON".
std::optional<std::string> read_text(const std::string& path, const DiagnosticConsumer& diag);

// The parsed document, or nullopt after "FILE: invalid JSON: ...".
std::optional<nlohmann::json> parse_json(const std::string& text, const std::string& file,
                                         const DiagnosticConsumer& diag);

// Collects "FILE: WHERE: field 'FIELD': reason" messages for one file.
class Reporter {
  public:
    Reporter(std::string file, const DiagnosticConsumer& diag)
        : file_(std::move(file)), diag_(diag) {}
    void error(const std::string& where, const std::string& field, const std::string& reason);
    int errors() const { return errors_; }

  private:
    std::string file_;
    const DiagnosticConsumer& diag_;
    int errors_ = 0;
};

// Whether the document is an object whose "format" is `format`; else reports why
// ("FILE: field 'format': ...") and returns false.
bool check_format(const nlohmann::json& doc, const std::string& format, Reporter& rep);

// A value as a message shows it: scalars as JSON, containers by kind only (dump()
// recurses once per level of nesting and would overflow the stack on a deep one).
std::string describe(const nlohmann::json& v);

// The names an object may hold (CONTRACT 3): every field of `obj` that is not among
// `known`, nor `extra`, nor "comment", nor named "x-..." is an error under `where`, the
// field named `prefix` + its name, with the nearest known name as a suggestion.
using FieldNames = std::initializer_list<std::string_view>;
void check_fields(Reporter& rep, const std::string& where, const std::string& prefix,
                  const nlohmann::json& obj, FieldNames known, FieldNames extra = {});

}  // namespace arealight::io_detail
