// The materials an object wears (scene.h): one, or one a group of a model file.
#include "scene/scene.h"

namespace m3055 {

const Material& material_of(const Object& object, std::size_t group) {
    return group < object.groups.size() ? object.groups[group].material : object.material;
}

std::vector<const Material*> materials_of(const Object& object) {
    if (object.groups.empty()) return {&object.material};
    std::vector<const Material*> out;
    for (const GroupMaterial& group : object.groups) out.push_back(&group.material);
    return out;
}

}  // namespace m3055
