#include "explore/document.h"

#include <algorithm>

namespace m3055::explore {

// A file by its path; a scene without one by its name (no path holds a newline).
std::string saved_key(const Document& doc) { return doc.file.empty() ? "\n" + doc.name : doc.file; }

Material* material_of(Document& doc, int& selected) {
    if (doc.scene.objects.empty()) return nullptr;
    selected = std::clamp(selected, 0, static_cast<int>(doc.scene.objects.size()) - 1);
    return &doc.scene.objects[std::size_t(selected)].material;
}

bool unsaved(const Document& doc) {
    const auto saved = doc.saved_revisions.find(saved_key(doc));
    return saved == doc.saved_revisions.end() || saved->second != doc.revision;
}

void mark_saved(Document& doc) { doc.saved_revisions[saved_key(doc)] = doc.revision; }

std::string title_name(const Document& doc) { return doc.name + (unsaved(doc) ? " * (unsaved edits)" : ""); }

}  // namespace m3055::explore
