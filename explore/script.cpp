#include "explore/script.h"

#include "explore/apply.h"
#include "explore/add_model.h"
#include "explore/brdf_files.h"
#include "explore/busy.h"
#include "explore/files.h"
#include "explore/keys.h"
#include "explore/operations.h"
#include "explore/shapes.h"
#include "grading/ab_compare.h"
#include "scene/light_direction.h"
#include "scene/load.h"
#include "models/model_spec.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace m3055::explore {

namespace {

// One command line being run: its words, and what the handlers may touch.
struct Call {
    Explorer& explorer;
    Script& script;
    std::istringstream in;
    std::string command;
    double now;
    long frames;
    int free_width, free_height;

    std::string word() {
        std::string w;
        if (!(in >> w)) throw std::runtime_error(command + ": missing argument");
        return w;
    }
    double number() {
        double v;
        if (!(in >> v)) throw std::runtime_error(command + ": expected a number");
        return v;
    }
    int integer() { return static_cast<int>(number()); }
    std::string rest() {
        std::string value;
        std::getline(in >> std::ws, value);
        return value;
    }
    const Scene& scene() const { return explorer.doc.scene; }
    View& view() { return explorer.view; }
    const Material& material() {
        const Material* m = selected_material(explorer);
        if (!m) throw std::runtime_error("no object");
        return *m;
    }
    int light() {
        const int index = integer();
        if (index < 0 || index >= static_cast<int>(scene().lights.size()))
            throw std::runtime_error("no light " + std::to_string(index));
        return index;
    }
    Shape shape(const std::string& name) {
        const auto found = parse_shape(name);
        if (!found) throw std::runtime_error("unknown shape '" + name + "'");
        return *found;
    }
    // The command applied now, as a widget's or key's would be this frame.
    bool run(Command c) { return run_command(explorer, std::move(c)); }
};

using Handler = void (*)(Call&);

// ---- Scene and material --------------------------------------------------------------

void set_value(Call& c) {
    const std::string path = c.word();
    c.run(command::SetSceneValue{path, c.rest()});
}

void model(Call& c) {
    const std::string name = c.word();
    const Material& material = c.material();
    c.run(command::SetMaterial{c.view().selected_object, with_model_named(material, name), "", selected_group(c.explorer)});
}

void print_models(Call&) {
    for (const ModelSpec* model : all_models()) std::printf("model %s\t%s\n", model->name.c_str(), model->label.c_str());
    std::fflush(stdout);
}

void select_object(Call& c) {
    const int i = c.integer();
    if (!c.run(command::SelectObject{i})) throw std::runtime_error("no object " + std::to_string(i));
}

void rescale_eq14(Call& c) {
    Material rescaled;
    if (!eq14_rescaled(c.material(), &rescaled)) throw std::runtime_error("rescale_eq14: not possible for this material");
    c.run(command::SetMaterial{c.view().selected_object, rescaled, kEq14Action, selected_group(c.explorer)});
}

void add_object_command(Call& c) {
    std::string name = "sphere";
    c.in >> name;  // optional: the shape
    c.run(command::AddObject{c.shape(name)});
}

void shape(Call& c) {
    const Shape shape = c.shape(c.word());
    c.material();  // there is a selected object
    const int index = c.view().selected_object;
    Object object = c.scene().objects[std::size_t(index)];
    set_shape(object, shape);  // as the Objects panel's shape selector
    c.run(command::SetObject{index, object});
}

void remove_object_command(Call& c) {
    if (!c.run(command::RemoveObject{c.integer()})) throw std::runtime_error("cannot remove that object");
}

void figure(Call& c) {
    if (!c.run(command::LoadFigure{c.word()})) throw std::runtime_error(c.explorer.session.messages.error);
}

void load(Call& c) { c.run(command::LoadScene{c.word()}); }  // a bad file shows in the window, like a drop

// ---- Lights -------------------------------------------------------------------------------

void select_light(Call& c) { c.run(command::SelectLight{c.light()}); }

void light_preset(Call& c) {
    LightPreset preset;
    const std::string name = c.word();
    if (!parse_light_preset(name, &preset)) throw std::runtime_error("unknown light preset '" + name + "'");
    c.run(command::ApplyLightPreset{preset});
}

void light_angles(Call& c) {
    const int i = c.light();
    const double azimuth = c.number(), elevation = c.number();
    Light light = c.scene().lights[std::size_t(i)];
    light.direction = direction_from_angles({azimuth, elevation});
    c.run(command::SetLight{i, light});
}

void light_drag(Call& c) {
    const int i = c.light();
    const double x = c.number(), y = c.number();
    Light light = c.scene().lights[std::size_t(i)];
    light.direction = direction_from_disc({x, y});
    c.run(command::SetLight{i, light});
}

void add_light_command(Call& c) {
    if (!c.run(command::AddLight{})) throw std::runtime_error("already " + std::to_string(kMaxExplorerLights) + " lights");
}

void remove_light_command(Call& c) {
    if (!c.run(command::RemoveLight{c.integer()})) throw std::runtime_error("no such light");
}

// ---- View, display and compare -----------------------------------------------------------

void display(Call& c) {
    const std::string which = c.word();
    const Display& now = c.scene().display;
    if (which == "m3055") c.run(command::SetDisplay{m3055_display(now), "display M3055"});
    else if (which == "modern") c.run(command::SetDisplay{modern_display(now, c.free_width, c.free_height), "display modern"});
    else throw std::runtime_error("display: m3055 or modern");
}

void orbit(Call& c) {
    const double dx = c.number(), dy = c.number();
    c.run(command::OrbitCamera{dx, dy});
}

void zoom(Call& c) { c.run(command::ZoomCamera{c.number()}); }

void projection(Call& c) {  // the Camera panel's combo
    const std::string name = c.word();
    if (name != "perspective" && name != "orthographic")
        throw std::runtime_error("projection: perspective or orthographic");
    Camera camera = c.scene().camera;
    camera.projection = name == "perspective" ? Projection::perspective : Projection::orthographic;
    c.run(command::SetCamera{camera});
}

void compare(Call& c) {
    const std::string on = c.word();
    if (on != "on" && on != "off") throw std::runtime_error("compare: on or off");
    c.run(command::SetCompare{on == "on"});
}

void compare_model(Call& c) {
    c.run(command::SetMaterial{kMaterialB, with_model_named(c.explorer.doc.material_b, c.word()), ""});
}

void plot_light(Call& c) { c.view().plotted_light = c.light(); }  // the plot header's light combo
void plot_scale(Call& c) {  // the plot header's scale combo, and its outer value (optional)
    const std::string name = c.word();
    if (name == "fixed") c.view().plot_scale = RadialScale::fixed;
    else if (name == "model_max") c.view().plot_scale = RadialScale::model_max;
    else if (name == "log") c.view().plot_scale = RadialScale::log;
    else if (name == "lobe") c.view().plot_scale = RadialScale::lobe;
    else throw std::runtime_error("plot_scale: fixed, model_max, log or lobe");
    double top = name == "log" ? 1000.0 : 1.0;
    if (!c.rest().empty()) throw std::runtime_error("plot_scale: one word");
    c.view().plot_top = top;
}

std::pair<int, int> display_pixel(Call& c) {
    const int x = c.integer(), y = c.integer();
    const Display& d = c.scene().display;
    if (x < 0 || y < 0 || x >= d.width || y >= d.height)
        throw std::runtime_error(c.command + ": (" + std::to_string(x) + ", " + std::to_string(y) +
                                 ") is outside the " + std::to_string(d.width) + " x " + std::to_string(d.height) +
                                 " display");
    return {x, y};
}
int display_pixel_row(Call& c) {
    const int y = c.integer();
    if (y < 0 || y >= c.scene().display.height)
        throw std::runtime_error(c.command + ": row " + std::to_string(y) + " is outside the " +
                                 std::to_string(c.scene().display.height) + "-row display");
    return y;
}
// Hovering display pixel (x, y): prints "probe ..." once rendered.
void probe(Call& c) {
    const auto [x, y] = display_pixel(c);
    c.run(DisplayRequest{command::Probe{x, y}});
}
// A click on display pixel (x, y): selects the object there.
void click(Call& c) {
    const auto [x, y] = display_pixel(c);
    c.run(DisplayRequest{command::Pick{x, y}});
}

void light_name(Call& c) {  // the Lights panel's name field
    const int index = c.light();
    Light light = c.scene().lights[std::size_t(index)];
    light.name = valid_light_name(c.rest());
    c.run(command::SetLight{index, light});
}

void section(Call& c) {  // a click on a side panel header: "section Lights closed"
    const std::string rest = c.rest();
    const auto space = rest.find_last_of(' ');
    const std::string name = space == std::string::npos ? "" : rest.substr(0, space), how = rest.substr(space + 1);
    if (name.empty() || (how != "open" && how != "closed")) throw std::runtime_error("section: NAME open|closed");
    if (name == kPlotsTitle) c.view().plots_folded = how == "closed";  // the plots' title bar under the side panel
    else c.view().section_requests[name] = how == "open";
}

void copy_b(Call& c) { c.run(command::CopyAToB{}); }  // the A/B panel's "B = copy of A"

void compare_diff(Call& c) {  // the A/B panel's difference pane checkbox
    const std::string on = c.word();
    if (on != "on" && on != "off") throw std::runtime_error("compare_diff: on or off");
    c.view().compare_diff = on == "on";
}
void diff_scale(Call& c) {  // the A/B panel's scale: auto or 1 ... 255
    const std::string value = c.word();
    if (value == "auto") {
        c.view().diff_scale = 0;
        return;
    }
    const int scale = std::atoi(value.c_str());
    if (scale < 1 || scale > grading::kMaxDifferenceScale || std::to_string(scale) != value)
        throw std::runtime_error("diff_scale: auto or a whole number in [1, 255]");
    c.view().diff_scale = scale;
}
void print_compare(Call& c) {  // "compare differing=N pixels=M scale=S", once rendered
    if (!c.view().compare) throw std::runtime_error("print_compare: the A/B split is off");
    c.run(DisplayRequest{command::PrintCompare{}});
}
void print_profile(Call& c) {  // hovering row Y of A (optional), then its profile, once rendered
    if (!(c.in >> std::ws).eof()) c.view().profile_row = display_pixel_row(c);
    c.run(DisplayRequest{command::PrintProfile{}});
}
void save_difference(Call& c) {  // the difference pane's image, at display resolution
    if (!c.view().compare || !c.view().compare_diff)
        throw std::runtime_error("save_difference: needs compare on and compare_diff on");
    c.run(DisplayRequest{command::SaveDifference{c.word()}});
}

// ---- .brdf files (explore/brdf_files.h) ------------------------------------------------------

// File > Open BRDF's dialog with PATH typed (or a drop): errors show in the window, as `load`'s.
void open_brdf_command(Call& c) { c.run(command::OpenBrdf{c.rest()}); }

// File > Add model...'s dialog with PATH typed; `drop PATH`: what a file dropped on the window gives.
void add_model_command(Call& c) { c.run(command::AddModel{c.rest()}); }
void drop_command(Call& c) { c.run(dropped_file_command(c.rest())); }

// What an editor's save does to a watched file: DST's bytes replaced by SRC's
// (written to a temporary and renamed, so the watcher never reads half a file).
void replace_file(Call& c) {
    const std::string from = c.word(), to = c.word();
    std::ifstream in(from, std::ios::binary);
    if (!in) throw std::runtime_error("replace_file: cannot read " + from);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string temporary = to + ".saving";
    std::ofstream(temporary, std::ios::binary) << bytes;
    if (std::rename(temporary.c_str(), to.c_str()) != 0) throw std::runtime_error("replace_file: cannot write " + to);
}

// View > BRDF views.
void brdf_views(Call& c) {
    const std::string how = c.word();
    if (how != "on" && how != "off") throw std::runtime_error("brdf_views: on|off");
    c.view().show_brdf_views = how == "on";
    if (how == "on") c.view().show_spectra = false;  // one docked view at a time
}

// View > Spectra.
void spectra(Call& c) {
    const std::string how = c.word();
    if (how != "on" && how != "off") throw std::runtime_error("spectra: on|off");
    c.view().show_spectra = how == "on";
    if (how == "on") c.view().show_brdf_views = false;
}

// One line: the Material section's .brdf error and the status strip.
void print_brdf(Call& c) {
    const Messages& m = c.explorer.session.messages;
    std::printf("brdf error=%s\tstatus=%s\terror=%s\tbusy=%s\n", m.brdf_error.c_str(), m.status.c_str(), m.error.c_str(),
                busy_line(c.explorer.session.brdf_watch, 0).c_str());
    std::fflush(stdout);
}

// ---- Undo/redo (Edit menu) -----------------------------------------------------------------

void undo_command(Call& c) {
    if (!c.run(command::Undo{})) throw std::runtime_error("undo: nothing to undo");
}
void redo_command(Call& c) {
    if (!c.run(command::Redo{})) throw std::runtime_error("redo: nothing to redo");
}
// One line: the title's name, and what Undo and Redo would do.
void print_state(Call& c) {
    commit_edits(c.explorer);
    const History& h = c.explorer.doc.history;
    std::printf("state title=%s\tundo=%s\tredo=%s\tsteps=%zu\tbusy=%s\tselected=%d\n", title_name(c.explorer.doc).c_str(),
                h.can_undo() ? h.undo_label().c_str() : "", h.can_redo() ? h.redo_label().c_str() : "",
                h.undo_steps(), c.explorer.session.busy.c_str(), c.view().selected_object);
    std::fflush(stdout);
}

// --assignment's live grade, printed by the frame loop once it is current.
void print_grade(Call& c) {
    if (!c.explorer.session.practice.active) throw std::runtime_error("print_grade: no --assignment");
    c.run(DisplayRequest{command::PrintGrade{}});
}

// ---- Keys, files and the script itself -----------------------------------------------------

void key(Call& c) {
    const std::string name = c.word();
    const std::optional<KeyPress> press = parse_key_name(name);
    if (!press) throw std::runtime_error("unknown key '" + name + "'");
    if (handle_shortcut(c.explorer, *press)) apply_commands(c.explorer);
}

void screenshot(Call& c) { c.run(DisplayRequest{command::Screenshot{c.word()}}); }
void save_display(Call& c) { c.run(DisplayRequest{command::SaveDisplay{c.word()}}); }

void save(Call& c) {
    if (!c.run(command::SaveTo{c.word()})) throw std::runtime_error(c.explorer.session.messages.error);
}

void screenshot_dir(Call& c) { c.explorer.session.files.screenshot_dir = c.rest(); }
void capture(Call& c) { c.script.capture_path = c.word(); }
void idle(Call& c) { c.script.start_idle(c.number(), c.now, c.frames); }
void settle(Call& c) { c.script.start_idle(c.number(), c.now, c.frames, true); }
void quit(Call& c) { c.run(command::Quit{}); }

// Command name -> handler (the list in script.h).
const std::map<std::string, Handler>& commands() {
    static const std::map<std::string, Handler> table = {
        {"set", set_value},         {"model", model},
        {"print_models", print_models}, {"select_object", select_object},
        {"select_light", select_light}, {"rescale_eq14", rescale_eq14},
        {"light_preset", light_preset}, {"light_angles", light_angles},
        {"light_drag", light_drag}, {"add_light", add_light_command},
        {"remove_light", remove_light_command}, {"add_object", add_object_command},
        {"shape", shape},           {"remove_object", remove_object_command},
        {"figure", figure},         {"load", load},
        {"display", display},       {"orbit", orbit},
        {"projection", projection}, {"zoom", zoom},
        {"compare", compare},       {"compare_model", compare_model},
        {"key", key},               {"screenshot", screenshot},
        {"save", save},             {"capture", capture},
        {"idle", idle},             {"quit", quit},
        {"settle", settle},
        {"undo", undo_command},     {"redo", redo_command},
        {"copy_b", copy_b},         {"plot_light", plot_light},
        {"plot_scale", plot_scale}, {"probe", probe},
        {"click", click},           {"light_name", light_name},
        {"section", section},         {"print_state", print_state},
        {"screenshot_dir", screenshot_dir}, {"compare_diff", compare_diff},
        {"diff_scale", diff_scale},   {"print_compare", print_compare},
        {"print_profile", print_profile}, {"save_difference", save_difference},
        {"open_brdf", open_brdf_command}, {"add_model", add_model_command},
        {"drop", drop_command},
        {"replace_file", replace_file}, {"print_brdf", print_brdf},
        {"brdf_views", brdf_views},  {"spectra", spectra},
        {"print_grade", print_grade}, {"save_display", save_display},
    };
    return table;
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

void Script::step(Explorer& explorer, double now, long frames, int free_width, int free_height) {
    if (idling()) {
        if (now < idle_until_ && !settled(explorer, frames)) return;
        // A settle that ended early counts the time it took.
        const double seconds = std::min(idle_seconds_, now - (idle_until_ - idle_seconds_));
        idle_records_.push_back({seconds, frames - idle_start_frames_});
        std::printf("%s %.1f s: %ld frames drawn\n", until_settled_ ? "settle" : "idle", seconds,
                    frames - idle_start_frames_);
        std::fflush(stdout);
        idle_until_ = 0.0;
        return;
    }
    if (next_ >= lines_.size()) return;
    const std::size_t number = ++next_;
    const std::string& line = lines_[number - 1];
    try {
        run(explorer, line, now, frames, free_width, free_height);
    } catch (const std::exception& e) {
        ++errors_;
        std::string& error = explorer.session.messages.error;
        error = path_ + ":" + std::to_string(number) + ": " + e.what();
        std::fprintf(stderr, "%s\n", error.c_str());
    }
}

void Script::start_idle(double seconds, double now, long frames, bool until_settled) {
    idle_seconds_ = seconds;
    idle_until_ = now + seconds;
    idle_start_frames_ = frames;
    until_settled_ = until_settled;
}

bool Script::settled(const Explorer& explorer, long frames) const {
    return settling() && frames > idle_start_frames_ && explorer.session.busy.empty();
}

void Script::run(Explorer& explorer, const std::string& line, double now, long frames, int free_width,
                 int free_height) {
    Call call{explorer, *this, std::istringstream(line.substr(0, line.find('#'))), {}, now, frames, free_width,
              free_height};
    if (!(call.in >> call.command)) return;  // blank or comment
    const auto found = commands().find(call.command);
    if (found == commands().end()) throw std::runtime_error("unknown command '" + call.command + "'");
    found->second(call);
}

}  // namespace m3055::explore
