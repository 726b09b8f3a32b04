#include "arealight/pfm_image.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <sstream>

#include "arealight/atomic_file.hpp"
#include "arealight/read_file.hpp"

namespace arealight {
namespace {

bool host_little_endian() {
    const std::uint32_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

float swapped(float x) {
    unsigned char b[4];
    std::memcpy(b, &x, 4);
    std::swap(b[0], b[3]);
    std::swap(b[1], b[2]);
    std::memcpy(&x, b, 4);
    return x;
}

}  // namespace

std::string format_pfm(const LinearImage& image) {
    std::string out = fmt::format("PF\n{} {}\n{}\n", image.width, image.height,
                                  host_little_endian() ? "-1.0" : "1.0");
    const std::size_t row = static_cast<std::size_t>(image.width) * 3;
    for (int y = image.height - 1; y >= 0; --y)
        out.append(reinterpret_cast<const char*>(image.rgb.data() + y * row), row * sizeof(float));
    return out;
}

bool write_pfm(const std::string& path, const LinearImage& image, const DiagnosticConsumer& diag) {
    return write_file_atomic(path, format_pfm(image), diag);
}

std::optional<LinearImage> parse_pfm(const std::string& bytes, const std::string& name,
                                     const DiagnosticConsumer& diag) {
    auto fail = [&](const std::string& why) -> std::optional<LinearImage> {
        if (diag) diag({Severity::Error, name, 0, name + ": not a colour PFM: " + why});
        return std::nullopt;
    };
    // The header is three whitespace-separated tokens after "PF", then one whitespace byte.
    std::istringstream header(bytes);
    std::string magic;
    long long w = 0, h = 0;
    double scale = 0;
    if (!(header >> magic) || magic != "PF") return fail("it does not start with \"PF\"");
    if (!(header >> w >> h) || w <= 0 || h <= 0 || w > 1 << 16 || h > 1 << 16)
        return fail("the width and height are not two numbers in 1..65536");
    if (!(header >> scale) || scale == 0) return fail("the scale is missing or zero");
    const std::size_t start = static_cast<std::size_t>(header.tellg()) + 1;
    const std::size_t count = static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3;
    if (bytes.size() != start + count * sizeof(float))
        return fail(fmt::format("{} bytes of pixels, expected {} for {}x{}", bytes.size() - start,
                                count * sizeof(float), w, h));
    LinearImage img;
    img.width = static_cast<int>(w);
    img.height = static_cast<int>(h);
    img.rgb.resize(count);
    const bool swap = (scale < 0) != host_little_endian();
    const std::size_t row = static_cast<std::size_t>(w) * 3;
    for (long long y = 0; y < h; ++y) {
        // File rows run bottom to top.
        float* dst = img.rgb.data() + static_cast<std::size_t>(h - 1 - y) * row;
        std::memcpy(dst, bytes.data() + start + static_cast<std::size_t>(y) * row * sizeof(float),
                    row * sizeof(float));
        if (swap)
            for (std::size_t k = 0; k < row; ++k) dst[k] = swapped(dst[k]);
    }
    return img;
}

std::optional<LinearImage> read_pfm(const std::string& path, const DiagnosticConsumer& diag) {
    auto bytes = read_file(path, diag);
    if (!bytes) return std::nullopt;
    return parse_pfm(*bytes, path, diag);
}

}  // namespace arealight
