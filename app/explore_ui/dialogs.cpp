// The explorer's menu bar (File, Edit with the undo/redo steps by name) and
// its modal dialogs: unsaved edits on quit, Save As, and a failed load from a
// drop (shown in the middle of the window, where the user is looking).
#include "explore_ui/panels.h"

#include "explore_ui/narrow_panel.h"
#include "explore_ui/widgets.h"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace m3055::explore {

namespace {

void centre_next_window() {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
}

// Not in the frame the dialog opens: the Esc that asked to quit would cancel it at once.
bool escape_pressed() {
    return !ImGui::IsWindowAppearing() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
}

void quit_dialog(ExplorerState& state) {
    if (state.quit_requested) {
        state.quit_requested = false;
        if (!unsaved(state)) state.quit = true;
        else ImGui::OpenPopup("Unsaved edits");
    }
    centre_next_window();
    if (!ImGui::BeginPopupModal("Unsaved edits", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::Text("\"%s\" has edits that are not saved.", state.scene_name.c_str());
    ImGui::TextUnformatted(state.scene_file.empty() ? "Save asks for a file name."
                                                    : ("Save writes " + state.scene_file + ".").c_str());
    if (ImGui::Button("Save")) {
        ImGui::CloseCurrentPopup();
        state.quit_after_save = true;
        save_or_ask(state);
        if (!state.save_as_requested && !unsaved(state)) state.quit = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
        ImGui::CloseCurrentPopup();
        state.quit = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || escape_pressed()) {
        ImGui::CloseCurrentPopup();
        state.quit_after_save = false;
    }
    ImGui::EndPopup();
}

void save_as_dialog(ExplorerState& state) {
    if (state.save_as_requested) {
        state.save_as_requested = false;
        ImGui::OpenPopup("Save scene as");
    }
    centre_next_window();
    if (!ImGui::BeginPopupModal("Save scene as", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(420.0f);
    const bool enter = ImGui::InputText("file", &state.save_path, ImGuiInputTextFlags_EnterReturnsTrue);
    if (!state.error.empty()) ImGui::TextColored(ImVec4(1, 0.43f, 0.43f, 1), "%s", state.error.c_str());
    if (ImGui::Button("Save") || enter) {
        state.error.clear();
        if (save_as(state, state.save_path)) {
            ImGui::CloseCurrentPopup();
            if (state.quit_after_save) state.quit = true;
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || escape_pressed()) {
        ImGui::CloseCurrentPopup();
        state.quit_after_save = false;
    }
    ImGui::EndPopup();
}

void load_error_dialog(ExplorerState& state) {
    if (state.show_load_error) {
        state.show_load_error = false;
        ImGui::OpenPopup("Could not load");
    }
    centre_next_window();
    if (!ImGui::BeginPopupModal("Could not load", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
    ImGui::TextColored(ImVec4(1, 0.43f, 0.43f, 1), "%s", state.load_error.c_str());
    ImGui::PopTextWrapPos();
    ImGui::TextUnformatted("The current scene is unchanged.");
    if (ImGui::Button("OK") || escape_pressed()) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

}  // namespace

void draw_menu_bar(ExplorerState& state) {
    if (!ImGui::BeginMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Save", "Ctrl+S")) save_or_ask(state);
        if (ImGui::MenuItem("Save as...")) request_save_as(state);
        if (ImGui::MenuItem("Open BRDF...")) state.open_brdf_requested = true;
        if (ImGui::MenuItem("Screenshot", "F12")) state.screenshot_requested = true;
        if (state.platform.can_quit) {
            ImGui::Separator();
            if (ImGui::MenuItem("Quit", "Esc")) state.quit_requested = true;
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        ImGui::MenuItem("BRDF views", nullptr, &state.show_brdf_views);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        const History& h = state.history;
        const std::string undo_text = h.can_undo() ? "Undo " + h.undo_label() : "Undo";
        const std::string redo_text = h.can_redo() ? "Redo " + h.redo_label() : "Redo";
        if (ImGui::MenuItem(undo_text.c_str(), "Ctrl+Z", false, h.can_undo())) undo(state);
        if (ImGui::MenuItem(redo_text.c_str(), "Ctrl+Shift+Z / Ctrl+Y", false, h.can_redo())) redo(state);
        ImGui::EndMenu();
    }
    // What a frame is waiting for (explore/busy.h), where the eye goes after an
    // edit. A narrow panel has room for one of the two: the hint, while it
    // lasts (a fraction of a second), then the unsaved mark again.
    const bool busy = !state.busy.empty();
    if (unsaved(state) && !(busy && narrow_panel())) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "  unsaved edits");
    if (busy) ImGui::TextColored(ImVec4(0.5f, 0.8f, 1, 1), "  %s", state.busy.c_str());
    ImGui::EndMenuBar();
}

void draw_dialogs(ExplorerState& state) {
    quit_dialog(state);
    save_as_dialog(state);
    load_error_dialog(state);
    open_brdf_dialog(state);
}

}  // namespace m3055::explore
