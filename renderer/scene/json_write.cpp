// scene_to_json: Scene -> the docs/spec.md#7-scene-files format. Doubles are stored as JSON
// doubles, which nlohmann writes in their shortest exact form, so
// scene_from_json(scene_to_json(s)) == s for any scene the loader produced.
// Fields a model / light type / projection does not read are not written (the
// loader would reject them); they come back as the struct defaults.
#include "scene/load.h"

#include "scene/json_lights.h"
#include "scene/json_material.h"
#include "scene/json_model_file.h"
#include "scene/json_shapes.h"

#include <nlohmann/json.hpp>

namespace m3055 {

using nlohmann::json;

namespace {

json vec(const dvec3& v) { return json::array({v.x, v.y, v.z}); }

json display_json(const Display& display) {
    json out = {{"width", display.width}, {"height", display.height}, {"bits", display.bits}, {"dither", display.dither}};
    if (display.view_transform != ViewTransform::none) out["view_transform"] = to_string(display.view_transform);  // absent = none
    return out;
}

json camera_json(const Camera& camera) {
    json out = {{"projection", to_string(camera.projection)},
                {"position", vec(camera.position)},
                {"target", vec(camera.target)},
                {"up", vec(camera.up)}};
    if (camera.projection == Projection::perspective)
        out["fov_y_deg"] = camera.fov_y_deg;
    else
        out["height"] = camera.height;
    return out;
}

}  // namespace

json scene_to_json(const Scene& scene, const PathWriting& writing) {
    json lights = json::array();
    for (const Light& light : scene.lights) lights.push_back(scene_json::light_json(light));
    json objects = json::array();
    for (const Object& object : scene.objects) {
        json entry = scene_json::shape_json(object);
        if (object.shape == Shape::mesh)
            scene_json::write_mesh_file(object, writing, entry);
        else
            entry["material"] = scene_json::material_json(object.material, writing);
        objects.push_back(std::move(entry));
    }
    json out = {{"display", display_json(scene.display)},
                {"background", vec(scene.background)},
                {"camera", camera_json(scene.camera)},
                {"lights", std::move(lights)},
                {"objects", std::move(objects)}};
    if (scene.ambient != dvec3(0.0)) out["ambient"] = vec(scene.ambient);  // absent = none
    return out;
}

}  // namespace m3055
