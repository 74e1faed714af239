#include "explore/script.h"

#include "explore/keys.h"
#include "explore/shape_editor.h"
#include "scene/light_direction.h"
#include "scene/load.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace m3055::explore {

namespace {

Model parse_model(const std::string& name) {
    for (Model m : all_models()) {
        if (name == to_string(m)) return m;
    }
    throw std::runtime_error("unknown model '" + name + "'");
}

int light_index(const ExplorerState& state, int index) {
    if (index < 0 || index >= static_cast<int>(state.scene.lights.size())) {
        throw std::runtime_error("no light " + std::to_string(index));
    }
    return index;
}

}  // namespace

Script Script::from_file(const std::string& path) {
    std::ifstream file(path);
    if (!file) throw std::runtime_error(path + ": cannot read the script");
    Script script;
    script.path_ = path;
    for (std::string line; std::getline(file, line);) script.lines_.push_back(line);
    return script;
}

void Script::step(ExplorerState& state, double now, long frames, int free_width, int free_height) {
    if (idling()) {
        if (now < idle_until_) return;
        idle_records_.push_back({idle_seconds_, frames - idle_start_frames_});
        std::printf("idle %.1f s: %ld frames drawn\n", idle_seconds_, frames - idle_start_frames_);
        std::fflush(stdout);
        idle_until_ = 0.0;
        return;
    }
    if (next_ >= lines_.size()) return;
    const std::size_t number = ++next_;
    const std::string& line = lines_[number - 1];
    try {
        run(state, line, now, frames, free_width, free_height);
    } catch (const std::exception& e) {
        ++errors_;
        state.error = path_ + ":" + std::to_string(number) + ": " + e.what();
        std::fprintf(stderr, "%s\n", state.error.c_str());
    }
}

void Script::run(ExplorerState& state, const std::string& line, double now, long frames,
                 int free_width, int free_height) {
    std::istringstream in(line.substr(0, line.find('#')));
    std::string command;
    if (!(in >> command)) return;  // blank or comment
    auto word = [&]() {
        std::string w;
        if (!(in >> w)) throw std::runtime_error(command + ": missing argument");
        return w;
    };
    auto number = [&]() {
        double v;
        if (!(in >> v)) throw std::runtime_error(command + ": expected a number");
        return v;
    };
    auto integer = [&]() { return static_cast<int>(number()); };

    if (command == "set") {
        const std::string path = word();
        std::string value;
        std::getline(in >> std::ws, value);
        nlohmann::json doc = scene_to_json(state.scene);
        apply_overrides(doc, {{path, value}}, "script");
        state.scene = scene_from_json(doc, "script");
        state.changed();
    } else if (command == "model") {
        Material* material = selected_material(state);
        if (!material) throw std::runtime_error("no object");
        set_model(*material, parse_model(word()));
        state.changed();
    } else if (command == "select_object") {
        const int i = integer();
        if (i < 0 || i >= static_cast<int>(state.scene.objects.size())) throw std::runtime_error("no object " + std::to_string(i));
        state.selected_object = i;
    } else if (command == "select_light") {
        state.selected_light = light_index(state, integer());
    } else if (command == "rescale_eq14") {
        Material* material = selected_material(state);
        if (!material || !rescale_to_eq14(material->model, material->d, material->lobes)) {
            throw std::runtime_error("rescale_eq14: not possible for this material");
        }
        state.changed();
    } else if (command == "light_preset") {
        LightPreset preset;
        const std::string name = word();
        if (!parse_light_preset(name, &preset)) throw std::runtime_error("unknown light preset '" + name + "'");
        apply_light_preset(state, preset);
    } else if (command == "light_angles") {
        const int i = light_index(state, integer());
        const double azimuth = number(), elevation = number();
        state.scene.lights[i].direction = direction_from_angles({azimuth, elevation});
        state.changed();
    } else if (command == "light_drag") {
        const int i = light_index(state, integer());
        const double x = number(), y = number();
        state.scene.lights[i].direction = direction_from_disc({x, y});
        state.changed();
    } else if (command == "add_light") {
        if (!add_light(state)) throw std::runtime_error("already " + std::to_string(kMaxExplorerLights) + " lights");
    } else if (command == "remove_light") {
        if (!remove_light(state, integer())) throw std::runtime_error("no such light");
    } else if (command == "add_object") {
        std::string name = "sphere";
        in >> name;  // optional: the shape
        const auto shape = parse_shape(name);
        if (!shape) throw std::runtime_error("unknown shape '" + name + "'");
        add_object(state, *shape);
    } else if (command == "shape") {
        const std::string name = word();
        const auto shape = parse_shape(name);
        if (!selected_material(state) || !shape) throw std::runtime_error("no object or unknown shape '" + name + "'");
        set_shape(state.scene.objects[state.selected_object], *shape);  // as the Objects panel's shape selector
        state.changed();
    } else if (command == "remove_object") {
        if (!remove_object(state, integer())) throw std::runtime_error("cannot remove that object");
    } else if (command == "figure") {
        if (!load_figure(state, word())) throw std::runtime_error(state.error);
    } else if (command == "load") {
        load_scene(state, word());  // a bad file shows in the window, like a drop
    } else if (command == "display") {
        const std::string which = word();
        if (which == "m3055") set_display_m3055(state);
        else if (which == "modern") set_display_modern(state, free_width, free_height);
        else throw std::runtime_error("display: m3055 or modern");
    } else if (command == "orbit") {
        const double dx = number(), dy = number();
        orbit_camera(state, dx, dy);
    } else if (command == "projection") {  // the Camera panel's combo
        const std::string name = word();
        if (name != "perspective" && name != "orthographic") throw std::runtime_error("projection: perspective or orthographic");
        state.scene.camera.projection = name == "perspective" ? Projection::perspective : Projection::orthographic;
        state.changed();
    } else if (command == "zoom") {
        zoom_camera(state, number());
    } else if (command == "compare") {
        const std::string on = word();
        if (on != "on" && on != "off") throw std::runtime_error("compare: on or off");
        set_compare(state, on == "on");
    } else if (command == "compare_model") {
        set_model(state.material_b, parse_model(word()));
        state.changed();
    } else if (command == "key") {
        int key = 0, mods = 0;
        const std::string name = word();
        if (!parse_key_name(name, &key, &mods)) throw std::runtime_error("unknown key '" + name + "'");
        handle_shortcut(state, key, mods);
    } else if (command == "screenshot") {
        state.screenshot_path = word();
        state.screenshot_requested = true;
    } else if (command == "save") {
        if (!save_scene(state, word())) throw std::runtime_error(state.error);
    } else if (command == "capture") {
        capture_path = word();
    } else if (command == "idle") {
        idle_seconds_ = number();
        idle_until_ = now + idle_seconds_;
        idle_start_frames_ = frames;
    } else if (command == "quit") {
        state.quit = true;
    } else {
        throw std::runtime_error("unknown command '" + command + "'");
    }
}

}  // namespace m3055::explore
