#include "explore_ui/path_dialog.h"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace m3055::explore {

void path_dialog(Explorer& explorer, const PathDialog& dialog) {
    if (explorer.view.dialog == dialog.dialog) {
        explorer.view.dialog = Dialog::none;
        if (explorer.session.platform.pick_file) {  // the browser's file chooser
            explorer.session.platform.pick_file();
            return;
        }
        dialog.error->clear();
        ImGui::OpenPopup(dialog.title);
    }
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(dialog.title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::TextUnformatted(dialog.text.c_str());
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(420.0f);
    const bool enter = ImGui::InputText("file", dialog.path, ImGuiInputTextFlags_EnterReturnsTrue);
    if (!dialog.error->empty()) {
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
        ImGui::TextColored(ImVec4(1, 0.43f, 0.43f, 1), "%s", dialog.error->c_str());
        ImGui::PopTextWrapPos();
    }
    if (ImGui::Button(dialog.ok) || enter) {
        if (dialog.run()) ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    const bool escape = !ImGui::IsWindowAppearing() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
    if (ImGui::Button("Cancel") || escape) {
        if (dialog.cancelled) dialog.cancelled();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace m3055::explore
