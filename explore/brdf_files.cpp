#include "explore/brdf_files.h"

#include "brdf_file/brdf_model.h"
#include "explore/operations.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
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

std::string glsl_error(const ExplorerState& state, const Material& material) {
    return state.brdf_compile_check ? state.brdf_compile_check(material) : std::string();
}

std::vector<Material*> users_of(ExplorerState& state, const std::string& path) {
    std::vector<Material*> users;
    for (Object& object : state.scene.objects)
        if (brdf_path_of(object.material) == path) users.push_back(&object.material);
    if (brdf_path_of(state.material_b) == path) users.push_back(&state.material_b);
    return users;
}

// Re-reads `path` for every material using it; all or none change.
void reload(ExplorerState& state, const std::string& path) {
    const std::vector<Material*> users = users_of(state, path);
    if (users.empty()) return;
    std::vector<Material> fresh;
    try {
        for (const Material* m : users) fresh.push_back(reload_brdf_material(*m, path));
        const std::string error = glsl_error(state, fresh.front());
        if (!error.empty()) {
            retire_brdf_model(fresh.front().model());  // or no general program compiles again
            state.brdf_error = error;
            state.brdf_error_path = path;
            state.status = "not reloaded " + path + ": an error (Material section); the last version that compiled stays";
            return;
        }
    } catch (const std::exception& e) {  // BrdfError: "FILE:LINE: problem"
        state.brdf_error = e.what();
        state.brdf_error_path = path;
        state.status = "not reloaded " + path + ": an error (Material section); the last version that compiled stays";
        return;
    }
    for (std::size_t i = 0; i < users.size(); ++i) *users[i] = fresh[i];
    state.brdf_error.clear();
    note_edit(state, "reload " + file_name(path));
    state.status = "reloaded " + path;
}

}  // namespace

bool is_brdf_path(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".brdf";
}

bool open_brdf(ExplorerState& state, const std::string& path) {
    Material* target = selected_material(state);
    std::string error = target ? "" : "no object to apply " + path + " to";
    std::string model_path;
    if (target) {
        try {
            const BrdfModel& model = load_brdf_model(path);
            const Material fresh(*model.spec);  // the file's defaults
            error = glsl_error(state, fresh);
            if (error.empty()) *target = fresh;
            else retire_brdf_model(*model.spec);
            model_path = model.path;
        } catch (const std::exception& e) {
            error = e.what();
        }
    }
    if (!error.empty()) {
        state.brdf_error = state.load_error = error;
        state.brdf_error_path = path;
        return false;
    }
    state.brdf_stamps[model_path] = stamp(model_path);  // watched from now on
    state.brdf_error.clear();
    note_edit(state, "open " + file_name(path));
    state.status = "opened " + path + " on object " + std::to_string(state.selected_object);
    return true;
}

std::vector<std::string> brdf_files_in_use(const ExplorerState& state) {
    std::vector<std::string> paths;
    auto note = [&paths](const Material& m) {
        const std::string path = brdf_path_of(m);
        if (!path.empty() && std::find(paths.begin(), paths.end(), path) == paths.end()) paths.push_back(path);
    };
    for (const Object& object : state.scene.objects) note(object.material);
    note(state.material_b);
    return paths;
}

bool poll_brdf_files(ExplorerState& state, double now) {
    // Found by the last poll, shown as "reloading FILE..." since: reload them now.
    if (!state.brdf_reload_pending.empty()) {
        for (const std::string& path : state.brdf_reload_pending) reload(state, path);
        state.brdf_reload_pending.clear();
        return true;
    }
    if (now < state.brdf_next_poll) return false;
    state.brdf_next_poll = now + kBrdfPollSeconds;
    for (const std::string& path : brdf_files_in_use(state)) {
        const std::string current = stamp(path);
        const auto [seen, first_time] = state.brdf_stamps.emplace(path, current);
        if (first_time || seen->second == current) continue;
        seen->second = current;
        state.brdf_reload_pending.push_back(path);
    }
    return !state.brdf_reload_pending.empty();
}

}  // namespace m3055::explore
