// The text of templates/*.glsl, compiled into the library at build time so the
// generator needs no source tree at run time (see cmake/embed_templates.cmake).
#pragma once

#include <string>
#include <vector>

namespace arealight {

struct EmbeddedTemplate {
    std::string path;  // "templates/NAME.glsl"
    std::string text;
};

const std::vector<EmbeddedTemplate>& embedded_templates();

}  // namespace arealight
