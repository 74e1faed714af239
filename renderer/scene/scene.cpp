#include "scene/scene.h"

#include "models/model_spec.h"

namespace m3055 {

const char* to_string(ViewTransform transform) {
    return transform == ViewTransform::srgb ? "srgb" : "none";
}

const char* to_string(LightType type) {
    switch (type) {
        case LightType::directional: return "directional";
        case LightType::point: return "point";
        case LightType::spot: return "spot";
        case LightType::rect: return "rect";
        case LightType::disk: return "disk";
        case LightType::sky: return "sky";
    }
    return "?";
}

const char* to_string(Shape shape) {
    switch (shape) {
        case Shape::sphere: return "sphere";
        case Shape::plane: return "plane";
        case Shape::cube: return "cube";
        case Shape::cylinder: return "cylinder";
        case Shape::torus: return "torus";
        case Shape::mesh: return "mesh";
    }
    return "?";
}

const char* to_string(Projection projection) {
    return projection == Projection::perspective ? "perspective" : "orthographic";
}

LobeList lobes_for(const Light& light, const Material& material) {
    const std::optional<LobeKind>& wanted = material.model().light_lobes;
    if (wanted && !light.lobes.empty() && light.lobe_kind == *wanted) return LobeList(light.lobes);
    return material.lobes();
}

}  // namespace m3055
