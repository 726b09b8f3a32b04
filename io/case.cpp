#include "arealight/case.hpp"

namespace arealight {

const char* to_string(LightType t) {
    switch (t) {
        case LightType::Polygon:
            return "polygon";
        case LightType::Disk:
            return "disk";
        case LightType::Sphere:
            return "sphere";
        case LightType::Ellipsoid:
            return "ellipsoid";
    }
    return "polygon";
}

const char* to_string(Distribution d) {
    switch (d) {
        case Distribution::Phong:
            return "phong";
        case Distribution::Blinn:
            return "blinn";
        case Distribution::Beckmann:
            return "beckmann";
        case Distribution::Ggx:
            return "ggx";
    }
    return "phong";
}

bool is_microfacet(Distribution d) {
    return d != Distribution::Phong;
}

}  // namespace arealight
