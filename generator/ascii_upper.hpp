// ASCII upper case of a name, as the generator spells macros from keys and tags
// ("polygon_ggx" -> "POLYGON_GGX"). Internal to the generator.
#pragma once

#include <cctype>
#include <string>

namespace arealight {

inline std::string ascii_upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace arealight
