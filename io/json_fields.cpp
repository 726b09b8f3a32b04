// File reading and field validation shared by arealight's JSON readers (json_fields.hpp).
#include "json_fields.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>
#include <vector>

namespace arealight {
namespace io_detail {

using json = nlohmann::json;

void report(const DiagnosticConsumer& diag, const std::string& file, const std::string& message) {
    if (diag) diag({Severity::Error, file, 0, file + ": " + message});
}

// The whole file, or nullopt after "FILE: cannot read: REASON". POSIX calls rather than
// iostreams, because only they give a reliable errno (a folder opens as a stream, then reads
// as empty and would be misreported as invalid JSON).
std::optional<std::string> read_text(const std::string& path, const DiagnosticConsumer& diag) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        report(diag, path, std::string("cannot read: ") + std::strerror(errno));
        return std::nullopt;
    }
    std::string text;
    char buf[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n == 0) break;
        if (n < 0) {
            if (errno == EINTR) continue;
            const int err = errno;
            ::close(fd);
            report(diag, path, std::string("cannot read: ") + std::strerror(err));
            return std::nullopt;
        }
        text.append(buf, static_cast<std::size_t>(n));
    }
    ::close(fd);
    return text;
}

// nlohmann reports a number beyond the double range as out_of_range rather than parse_error,
// so every json::exception counts as a syntax problem here.
std::optional<json> parse_json(const std::string& text, const std::string& file,
                               const DiagnosticConsumer& diag) {
    try {
        return json::parse(text);
    } catch (const json::exception& e) {
        report(diag, file, std::string("invalid JSON: ") + e.what());
        return std::nullopt;
    }
}

void Reporter::error(const std::string& where, const std::string& field,
                     const std::string& reason) {
    ++errors_;
    std::string msg;
    if (!where.empty()) msg += where + ": ";
    if (!field.empty()) msg += "field '" + field + "': ";
    msg += reason;
    report(diag_, file_, msg);
}

// A value as a message shows it: scalars as JSON, containers by kind only, because dump()
// recurses once per level and a deeply nested value (a 200 kB file) overflows the stack.
std::string describe(const json& v) {
    if (v.is_array()) return "an array";
    if (v.is_object()) return "an object";
    return v.dump();
}

namespace {

// Levenshtein distance: the number of one-character edits from a to b.
std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

void check_fields(Reporter& rep, const std::string& where, const std::string& prefix,
                  const json& obj, FieldNames known, FieldNames extra) {
    if (!obj.is_object()) return;
    for (auto it = obj.begin(); it != obj.end(); ++it) {
        const std::string& name = it.key();
        if (name == "comment" || name.rfind("x-", 0) == 0) continue;
        auto listed = [&](FieldNames names) {
            return std::find(names.begin(), names.end(), std::string_view(name)) != names.end();
        };
        if (listed(known) || listed(extra)) continue;
        std::string_view nearest;
        std::size_t best = SIZE_MAX;
        for (FieldNames names : {known, extra})
            for (std::string_view k : names)
                if (const std::size_t d = edit_distance(name, k); d < best) {
                    best = d;
                    nearest = k;
                }
        rep.error(where, prefix + name,
                  nearest.empty() ? std::string("unknown field")
                                  : fmt::format("unknown field (did you mean '{}{}'?)", prefix,
                                                nearest));
    }
}

bool check_format(const json& doc, const std::string& format, Reporter& rep) {
    if (!doc.is_object()) {
        rep.error("", "format", "the file must be a JSON object");
        return false;
    }
    auto f = doc.find("format");
    if (f == doc.end()) {
        rep.error("", "format", "missing (expected \"" + format + "\")");
        return false;
    }
    if (!f->is_string() || f->get<std::string>() != format) {
        rep.error("", "format", "is " + describe(*f) + ", expected \"" + format + "\"");
        return false;
    }
    return true;
}

}  // namespace io_detail
}  // namespace arealight
