#include "explore/brdf_files.h"

#include "brdf_file/brdf_model.h"
#include "explore/edits.h"
#include "explore/operations.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <system_error>

namespace m3055::explore {

namespace {

// "mtime size": what changes when an editor saves the file. One stat, so
// polling costs nothing next to a frame.
std::string stamp(const std::string& path) {
    std::error_code ec;
    const auto time = std::filesystem::last_write_time(path, ec);
    if (ec) return "missing";
    const auto size = std::filesystem::file_size(path, ec);
    // long long: the clock's count is __int128 in some C++ libraries (Emscripten's libc++).
    return std::to_string(static_cast<long long>(time.time_since_epoch().count())) + " " +
           std::to_string(ec ? 0 : static_cast<unsigned long long>(size));
}

std::string file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// The .brdf file behind a material ("" for a built-in model).
std::string brdf_path_of(const Material& material) {
    const BrdfModel* model = find_brdf_model(material.model());
    return model ? model->path : std::string();
}

std::string glsl_error(const Explorer& e, const Material& material) {
    const auto& check = e.session.platform.brdf_compile_check;
    return check ? check(material) : std::string();
}

// The objects (by index) and B (kMaterialB) whose material comes from `path`.
std::vector<int> users_of(const Explorer& e, const std::string& path) {
    std::vector<int> users;
    const std::vector<Object>& objects = e.doc.scene.objects;
    for (std::size_t i = 0; i < objects.size(); ++i)
        if (brdf_path_of(objects[i].material) == path) users.push_back(int(i));
    if (brdf_path_of(e.doc.material_b) == path) users.push_back(kMaterialB);
    return users;
}

const Material& material_at(const Explorer& e, int user) {
    return user == kMaterialB ? e.doc.material_b : e.doc.scene.objects[std::size_t(user)].material;
}

// Re-reads `path` for every material using it; all or none change (one undo step).
void reload(Explorer& e, const std::string& path) {
    const std::vector<int> users = users_of(e, path);
    if (users.empty()) return;
    Messages& messages = e.session.messages;
    std::vector<Material> fresh;
    try {
        for (int user : users) fresh.push_back(reload_brdf_material(material_at(e, user), path));
        const std::string error = glsl_error(e, fresh.front());
        if (!error.empty()) {
            retire_brdf_model(fresh.front().model());  // or no general program compiles again
            messages.brdf_error = error;
            messages.brdf_path = path;
            messages.status = "not reloaded " + path + ": an error (Material section); the last version that compiled stays";
            return;
        }
    } catch (const std::exception& error) {  // BrdfError: "FILE:LINE: problem"
        messages.brdf_error = error.what();
        messages.brdf_path = path;
        messages.status = "not reloaded " + path + ": an error (Material section); the last version that compiled stays";
        return;
    }
    for (std::size_t i = 0; i < users.size(); ++i)
        edit_document(e, {MaterialEdit{users[i], material_at(e, users[i]), fresh[i]}, "reload " + file_name(path)});
    messages.brdf_error.clear();
    messages.status = "reloaded " + path;
}

}  // namespace

bool is_brdf_path(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".brdf";
}

bool open_brdf(Explorer& e, const std::string& path) {
    const Material* target = selected_material(e);
    std::string error = target ? "" : "no object to apply " + path + " to";
    std::string model_path;
    std::optional<Material> fresh;
    if (target) {
        try {
            const BrdfModel& model = load_brdf_model(path);
            fresh.emplace(*model.spec);  // the file's defaults
            error = glsl_error(e, *fresh);
            if (!error.empty()) retire_brdf_model(*model.spec);
            model_path = model.path;
        } catch (const std::exception& exception) {
            error = exception.what();
        }
    }
    Messages& messages = e.session.messages;
    if (!error.empty()) {
        messages.brdf_error = messages.load_error = error;
        messages.brdf_path = path;
        return false;
    }
    e.session.brdf_watch.stamps[model_path] = stamp(model_path);  // watched from now on
    messages.brdf_error.clear();
    const int object = e.view.selected_object;
    edit_document(e, {MaterialEdit{object, *target, *fresh, selected_group(e)}, "open " + file_name(path)});
    messages.status = "opened " + path + " on object " + std::to_string(object);
    return true;
}

std::vector<std::string> brdf_files_in_use(const Explorer& e) {
    std::vector<std::string> paths;
    auto note = [&paths](const Material& m) {
        const std::string path = brdf_path_of(m);
        if (!path.empty() && std::find(paths.begin(), paths.end(), path) == paths.end()) paths.push_back(path);
    };
    for (const Object& object : e.doc.scene.objects) note(object.material);
    note(e.doc.material_b);
    return paths;
}

const std::vector<std::string>& watched_brdf_files(Explorer& e) {
    BrdfWatch& watch = e.session.brdf_watch;
    if (watch.in_use_revision != e.doc.revision) {
        watch.in_use = brdf_files_in_use(e);
        watch.in_use_revision = e.doc.revision;
    }
    return watch.in_use;
}

bool reload_changed_brdf_files(Explorer& e) {
    BrdfWatch& watch = e.session.brdf_watch;
    if (watch.reload_pending.empty()) return false;
    for (const std::string& path : watch.reload_pending) reload(e, path);
    watch.reload_pending.clear();
    return true;
}

bool poll_brdf_files(Explorer& e, double now) {
    BrdfWatch& watch = e.session.brdf_watch;
    if (!watch.reload_pending.empty() || now < watch.next_poll) return false;  // found already: waiting for idle time
    watch.next_poll = now + kBrdfPollSeconds;
    for (const std::string& path : watched_brdf_files(e)) {
        const std::string current = stamp(path);
        const auto [seen, first_time] = watch.stamps.emplace(path, current);
        if (first_time || seen->second == current) continue;
        seen->second = current;
        watch.reload_pending.push_back(path);
    }
    return !watch.reload_pending.empty();
}

}  // namespace m3055::explore
