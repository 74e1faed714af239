#include "scene/scene.h"

namespace m3055 {

const char* to_string(Model model) {
    switch (model) {
        case Model::highlight: return "highlight";
        case Model::translucent: return "translucent";
        case Model::metal: return "metal";
        case Model::metal_blinn: return "metal_blinn";
        case Model::metal_phong: return "metal_phong";
        case Model::lambert: return "lambert";
        case Model::half_lambert: return "half_lambert";
        case Model::half_lambert_clamped: return "half_lambert_clamped";
        case Model::half_lambert_normalized: return "half_lambert_normalized";
        case Model::oren_nayar: return "oren_nayar";
        case Model::phong: return "phong";
        case Model::blinn_phong: return "blinn_phong";
        case Model::microfacet: return "microfacet";
        case Model::ward: return "ward";
        case Model::heidrich_seidel: return "heidrich_seidel";
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

const char* to_string(Distribution distribution) {
    switch (distribution) {
        case Distribution::blinn_phong: return "blinn_phong";
        case Distribution::gaussian: return "gaussian";
        case Distribution::beckmann: return "beckmann";
        case Distribution::ggx: return "ggx";
    }
    return "?";
}

const char* to_string(Fresnel fresnel) {
    switch (fresnel) {
        case Fresnel::none: return "none";
        case Fresnel::schlick: return "schlick";
        case Fresnel::dielectric: return "dielectric";
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
    }
    return "?";
}

const char* to_string(Projection projection) {
    return projection == Projection::perspective ? "perspective" : "orthographic";
}

}  // namespace m3055
