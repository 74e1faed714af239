#include "passes/material_slots.h"

namespace m3055 {

MaterialSlots material_slots(const std::vector<Object>& objects) {
    MaterialSlots slots;
    slots.records.reserve(objects.size());
    for (const Object& object : objects) slots.records.push_back(&material_of(object, 0));
    slots.more.assign(objects.size(), 0);
    for (std::size_t i = 0; i < objects.size(); ++i) {
        if (objects[i].groups.size() < 2) continue;
        slots.more[i] = std::uint32_t(slots.records.size());
        for (std::size_t g = 1; g < objects[i].groups.size(); ++g) slots.records.push_back(&objects[i].groups[g].material);
    }
    return slots;
}

}  // namespace m3055
