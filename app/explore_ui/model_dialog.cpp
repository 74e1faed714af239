// File > Add model...'s dialog: a path field, as Open BRDF's; the page opens
// the browser's file chooser instead, whose picked file is added by its extension.
#include "explore_ui/panels.h"

#include "explore/add_model.h"
#include "explore/apply.h"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace m3055::explore {

void add_model_dialog(Explorer& explorer) {
    if (explorer.view.dialog == Dialog::add_model) {
        explorer.view.dialog = Dialog::none;
        if (explorer.session.platform.pick_file) {  // the browser's file chooser
            explorer.session.platform.pick_file();
            return;
        }
        explorer.session.messages.load_error.clear();
        ImGui::OpenPopup("Add model");
    }
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal("Add model", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::TextUnformatted("A Wavefront .obj (with its .mtl) or glTF .gltf/.glb file, added standing on the floor.");
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(420.0f);
    const bool enter = ImGui::InputText("file", &explorer.view.model_path, ImGuiInputTextFlags_EnterReturnsTrue);
    if (!explorer.session.messages.load_error.empty()) {
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
        ImGui::TextColored(ImVec4(1, 0.43f, 0.43f, 1), "%s", explorer.session.messages.load_error.c_str());
        ImGui::PopTextWrapPos();
    }
    if (ImGui::Button("Add") || enter) {
        if (run_command(explorer, command::AddModel{explorer.view.model_path})) ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    const bool escape = !ImGui::IsWindowAppearing() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
    if (ImGui::Button("Cancel") || escape) {
        // The dialog showed why the model was not added; the File section's
        // "Could not load" is about scenes, and the model is not a problem now.
        Messages& messages = explorer.session.messages;
        if (messages.error == messages.load_error) messages.error.clear();
        messages.load_error.clear();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace m3055::explore
