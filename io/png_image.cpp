// PNG through libpng's simplified API (png_image_*, libpng 1.6): it reports errors in
// the image's message instead of longjmp, which would skip C++ destructors.
#include "arealight/png_image.hpp"

#include <png.h>

#include <cstring>

#include "arealight/atomic_file.hpp"

namespace arealight {

std::optional<std::string> encode_png(const Image8& image, const std::string& name,
                                      const DiagnosticConsumer& diag) {
    auto fail = [&](const std::string& why) -> std::optional<std::string> {
        if (diag) diag({Severity::Error, name, 0, name + ": cannot encode PNG: " + why});
        return std::nullopt;
    };
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3)
        return fail("the image is empty or its pixels do not match its size");
    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    png.width = static_cast<png_uint_32>(image.width);
    png.height = static_cast<png_uint_32>(image.height);
    png.format = PNG_FORMAT_RGB;
    // First call sizes the buffer, second fills it.
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&png, nullptr, &size, 0, image.rgb.data(), 0, nullptr))
        return fail(png.message);
    std::string bytes(size, '\0');
    if (!png_image_write_to_memory(&png, bytes.data(), &size, 0, image.rgb.data(), 0, nullptr))
        return fail(png.message);
    bytes.resize(size);
    return bytes;
}

bool write_png(const std::string& path, const Image8& image, const DiagnosticConsumer& diag) {
    auto bytes = encode_png(image, path, diag);
    return bytes && write_file_atomic(path, *bytes, diag);
}

}  // namespace arealight
