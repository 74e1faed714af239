// Which material record each drawn surface reads: record i is object i's
// material (a mesh from a file: its first group's), then the other groups of
// every mesh from a file, object by object. A scene without such meshes has
// exactly one record an object, as before they existed.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace m3055 {

struct MaterialSlots {
    std::vector<const Material*> records;  // in record order
    std::vector<std::uint32_t> more;       // per object: the record of its group 1 (0 for objects with one)

    // The record of group `group` of object `object`.
    int record(std::size_t object, std::size_t group) const {
        return group == 0 ? int(object) : int(more[object] + group - 1);
    }
};

MaterialSlots material_slots(const std::vector<Object>& objects);

}  // namespace m3055
