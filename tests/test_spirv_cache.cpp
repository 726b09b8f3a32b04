// The folder of compiled kernels (spirv_cache.hpp): a hit returns the words an earlier
// compile wrote without compiling, and anything but the same tag and text compiles.
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "arealight/spirv_cache.hpp"
#include "scratch_folder.hpp"

namespace arealight::test {
namespace {

// A stand-in compiler: counts its calls and returns words made from the text, so that a
// wrong entry shows as wrong words.
struct CountingCompile {
    int calls = 0;
    bool fail = false;
    std::optional<std::vector<uint32_t>> operator()(const std::string& text) {
        ++calls;
        if (fail) return std::nullopt;
        std::vector<uint32_t> w{0x07230203u, static_cast<uint32_t>(text.size())};
        for (char c : text) w.push_back(static_cast<unsigned char>(c));
        return w;
    }
};

std::vector<std::filesystem::path> entries(const ScratchFolder& dir) {
    std::vector<std::filesystem::path> out;
    for (const auto& e : std::filesystem::directory_iterator(dir / "cache")) out.push_back(e.path());
    return out;
}

}  // namespace

TEST_CASE("spirv cache: a hit returns the stored words, anything else compiles", "[cache]") {
    ScratchFolder dir("spirv_cache");
    const std::string folder = dir / "cache";
    CountingCompile cc;
    auto run = [&](const std::string& tag, const std::string& text) {
        return cached_compile(folder, tag, text, [&] { return cc(text); });
    };
    const auto first = run("glsl kernel", "void main() {}");
    REQUIRE(first);
    CHECK(cc.calls == 1);
    const auto again = run("glsl kernel", "void main() {}");
    REQUIRE(again);
    CHECK(*again == *first);
    CHECK(cc.calls == 1);  // read, not compiled
    CHECK(entries(dir).size() == 1);

    // Another tag, another text: compiled, each its own entry.
    CHECK(run("hlsl kernel", "void main() {}"));
    CHECK(run("glsl kernel", "void main() { }"));
    CHECK(cc.calls == 3);
    CHECK(entries(dir).size() == 3);

    // An entry whose stored text is not the text asked for (what a clash of the 64-bit
    // name would give) is not used: the text is compiled and the entry rewritten.
    const std::string text = "void main() { return; }";
    REQUIRE(run("glsl kernel", text));
    std::filesystem::path written;
    for (const auto& p : entries(dir)) {
        std::ifstream in(p, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (bytes.find(text) != std::string::npos) written = p;
    }
    REQUIRE(!written.empty());
    {
        std::ifstream in(written, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        bytes.replace(bytes.find(text), 4, "VOID");
        std::ofstream(written, std::ios::binary | std::ios::trunc) << bytes;
    }
    const int before = cc.calls;
    const auto recompiled = run("glsl kernel", text);
    REQUIRE(recompiled);
    CHECK(cc.calls == before + 1);
    CHECK(*recompiled == *cc(text));
    const auto reread = run("glsl kernel", text);
    CHECK(cc.calls == before + 2);  // the cc(text) just above, not a compile
    REQUIRE(reread);
    CHECK(*reread == *recompiled);

    // A failed compile is not stored; no folder: every call compiles.
    cc.fail = true;
    CHECK(!run("glsl kernel", "broken"));
    CHECK(!run("glsl kernel", "broken"));
    CHECK(cc.calls == before + 4);
    cc.fail = false;
    int calls = 0;
    for (int i = 0; i < 2; ++i)
        CHECK(cached_compile("", "glsl kernel", "void main() {}", [&] {
            ++calls;
            return cc("x");
        }));
    CHECK(calls == 2);
}

}  // namespace arealight::test
