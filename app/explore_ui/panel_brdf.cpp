// The .brdf parts of the UI: File > Open BRDF's dialog (a path field:
// explore_ui/path_dialog.h) and the Material section's note on the selected object's file: which
// file, that it is watched, and the last parse or GLSL error in red (the
// file's own line), while the last good version keeps rendering.
#include "explore_ui/panels.h"

#include "brdf_file/brdf_model.h"
#include "explore/apply.h"
#include "explore/brdf_files.h"
#include "explore_ui/path_dialog.h"
#include "explore_ui/widgets.h"

#include <imgui.h>

#include <string>

namespace m3055::explore {

namespace {
const ImVec4 kRed(1, 0.43f, 0.43f, 1);
}

void open_brdf_dialog(Explorer& explorer) {
    path_dialog(explorer, {"Open BRDF", Dialog::open_brdf,
                           "A BRDF Explorer .brdf file for object " + std::to_string(explorer.view.selected_object) +
                               " (its sliders come from the file).",
                           "Open", &explorer.view.brdf_path, &explorer.session.messages.brdf_error,
                           [&] { return run_command(explorer, command::OpenBrdf{explorer.view.brdf_path}); }});
}

void brdf_material_note(const Explorer& explorer, const Material& material) {
    const BrdfModel* model = find_brdf_model(material.model());
    if (model) {
        ImGui::PushTextWrapPos(0.0f);  // a long path wraps instead of running off the panel
        ImGui::TextDisabled("file %s (watched: saving it reloads, values kept)", model->path.c_str());
        ImGui::PopTextWrapPos();
        tooltip("Edit the .brdf in any editor and save: it is re-read and recompiled within half a second.");
    }
    if (explorer.session.messages.brdf_error.empty()) return;
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kRed, "%s", explorer.session.messages.brdf_error.c_str());
    ImGui::PopTextWrapPos();
    // The error may be about a file another object (or an undone step) uses:
    // say whose it is rather than seem to blame the selected material.
    if (model && model->path == explorer.session.messages.brdf_path) ImGui::TextDisabled("(showing the last version that compiled)");
    else ImGui::TextDisabled("(not the selected object's material: %s)", explorer.session.messages.brdf_path.c_str());
}

}  // namespace m3055::explore
