#include "scene/json_shapes.h"

#include "scene/shape_limits.h"

namespace m3055::scene_json {

namespace {

const Range kLength{0.0, 1e6, true, false};  // sizes and radii: (0, 1e6], like the sphere's radius
const Range kAngle = closed(-360.0, 360.0);

// The keys each shape reads, besides "shape" and "material".
std::vector<std::string> shape_keys(Shape shape) {
    switch (shape) {
        case Shape::sphere: return {"center", "radius"};
        case Shape::plane: return {"center", "normal", "size"};
        case Shape::cube: return {"center", "size", "rotation_deg"};
        case Shape::cylinder: return {"center", "axis", "radius", "height", "capped", "segments"};
        case Shape::torus: return {"center", "axis", "major_radius", "minor_radius", "segments"};
        case Shape::mesh: return {"center", "file", "size", "rotation_deg", "materials"};
    }
    return {};
}

const char* plural(Shape shape) {
    switch (shape) {
        case Shape::sphere: return "spheres";
        case Shape::plane: return "planes";
        case Shape::cube: return "cubes";
        case Shape::cylinder: return "cylinders";
        case Shape::torus: return "tori";
        case Shape::mesh: return "meshes";
    }
    return "?";
}

// For a key that other shapes read: "only for cylinders and tori"; else "".
std::string owners(const std::string& key) {
    std::vector<std::string> found;
    for (Shape shape : {Shape::sphere, Shape::plane, Shape::cube, Shape::cylinder, Shape::torus, Shape::mesh})
        for (const std::string& k : shape_keys(shape))
            if (k == key) found.push_back(plural(shape));
    if (found.empty()) return {};
    std::string text = "only for " + found[0];
    for (std::size_t i = 1; i < found.size(); ++i) text += (i + 1 == found.size() ? " and " : ", ") + found[i];
    return text;
}

}  // namespace

void read_shape(const Node& node, Object& object) {
    if (node.has("shape"))
        object.shape = static_cast<Shape>(node.child("shape").one_of({"sphere", "plane", "cube", "cylinder", "torus", "mesh"}));
    std::vector<std::string> allowed = shape_keys(object.shape);
    allowed.insert(allowed.end(), {"shape", "material"});
    node.check_keys(allowed, [](const std::string& key) { return owners(key); });

    object.center = node.required("center").vec3_in(kCoordinate);
    switch (object.shape) {
        case Shape::sphere:
            object.radius = node.required("radius").number_in(kLength);
            break;
        case Shape::plane:
            if (node.has("normal")) object.axis = node.child("normal").direction();
            object.size = node.required("size").number_in(kLength);
            break;
        case Shape::cube:
        case Shape::mesh:  // its file and materials: scene/json_model_file.h
            object.size = node.required("size").number_in(kLength);
            if (node.has("rotation_deg")) object.rotation_deg = node.child("rotation_deg").vec3_in(kAngle);
            break;
        case Shape::cylinder:
            if (node.has("axis")) object.axis = node.child("axis").direction();
            object.radius = node.required("radius").number_in(kLength);
            object.height = node.required("height").number_in(kLength);
            if (node.has("capped")) object.capped = node.child("capped").boolean();
            break;
        case Shape::torus: {
            if (node.has("axis")) object.axis = node.child("axis").direction();
            object.major_radius = node.required("major_radius").number_in(kLength);
            const Node minor = node.required("minor_radius");
            object.minor_radius = minor.number_in(kLength);
            // r >= R would make a self-intersecting (horn or spindle) torus.
            if (!(object.minor_radius < object.major_radius))
                minor.fail("must be less than major_radius (" + format_number(object.major_radius) + "), got " +
                           format_number(object.minor_radius));
            break;
        }
    }
    if (node.has("segments"))
        object.segments = node.child("segments").whole_in(kMinSegments, kMaxSegments);
}

json shape_json(const Object& object) {
    json out = {{"shape", to_string(object.shape)}, {"center", json::array({object.center.x, object.center.y, object.center.z})}};
    auto vec = [](const dvec3& v) { return json::array({v.x, v.y, v.z}); };
    switch (object.shape) {
        case Shape::sphere:
            out["radius"] = object.radius;
            break;
        case Shape::plane:
            out["normal"] = vec(object.axis);
            out["size"] = object.size;
            break;
        case Shape::cube:
        case Shape::mesh:  // its file and materials: write_mesh_file
            out["size"] = object.size;
            out["rotation_deg"] = vec(object.rotation_deg);
            break;
        case Shape::cylinder:
            out["axis"] = vec(object.axis);
            out["radius"] = object.radius;
            out["height"] = object.height;
            out["capped"] = object.capped;
            break;
        case Shape::torus:
            out["axis"] = vec(object.axis);
            out["major_radius"] = object.major_radius;
            out["minor_radius"] = object.minor_radius;
            break;
    }
    if (object.segments > 0 && (object.shape == Shape::cylinder || object.shape == Shape::torus))
        out["segments"] = object.segments;
    return out;
}

}  // namespace m3055::scene_json
