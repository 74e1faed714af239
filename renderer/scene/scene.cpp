#include "scene/scene.h"

namespace m3055 {

const char* to_string(Model model) {
    switch (model) {
        case Model::highlight: return "highlight";
        case Model::translucent: return "translucent";
        case Model::metal: return "metal";
        case Model::metal_blinn: return "metal_blinn";
        case Model::metal_phong: return "metal_phong";
    }
    return "?";
}

const char* to_string(LightType type) {
    switch (type) {
        case LightType::directional: return "directional";
        case LightType::point: return "point";
        case LightType::spot: return "spot";
    }
    return "?";
}

const char* to_string(Projection projection) {
    return projection == Projection::perspective ? "perspective" : "orthographic";
}

}  // namespace m3055
