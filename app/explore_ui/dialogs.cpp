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

// Opens the popup `name` in the frame after a command asked for `dialog`.
void open_when_asked(Explorer& explorer, Dialog dialog, const char* name) {
    if (explorer.view.dialog != dialog) return;
    explorer.view.dialog = Dialog::none;
    ImGui::OpenPopup(name);
}

// Not in the frame the dialog opens: the Esc that asked to quit would cancel it at once.
bool escape_pressed() {
    return !ImGui::IsWindowAppearing() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
}

void quit_dialog(Explorer& explorer) {
    open_when_asked(explorer, Dialog::unsaved_edits, "Unsaved edits");
    centre_next_window();
    if (!ImGui::BeginPopupModal("Unsaved edits", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    const bool current = unsaved(explorer.doc);
    const std::string& key = explorer.session.replaced_unsaved;  // a file, or "\n" + a name
    const std::string replaced = key.empty() || key[0] != '\n' ? key : key.substr(1);
    if (current) {
        ImGui::Text("\"%s\" has edits that are not saved.", explorer.doc.name.c_str());
        ImGui::TextUnformatted(explorer.doc.file.empty() ? "Save asks for a file name."
                                                        : ("Save writes " + explorer.doc.file + ".").c_str());
    }
    // A scene replaced by a load or a preset, its edits not saved: only undo brings it back.
    if (!replaced.empty())
        ImGui::Text("\"%s\" had edits that are not saved when it was replaced:\nCancel, then Ctrl+Z back to it, to keep them.",
                    replaced.c_str());
    if (current && ImGui::Button("Save")) {
        ImGui::CloseCurrentPopup();
        explorer.session.files.quit_after_save = true;
        run_command(explorer, command::Save{});  // now: whether it saved decides what follows
        if (explorer.view.dialog != Dialog::save_as && !unsaved(explorer.doc)) explorer.session.quit = true;
    }
    if (current) ImGui::SameLine();
    if (ImGui::Button("Discard")) {
        ImGui::CloseCurrentPopup();
        explorer.session.quit = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || escape_pressed()) {
        ImGui::CloseCurrentPopup();
        explorer.session.files.quit_after_save = false;
    }
    ImGui::EndPopup();
}

void save_as_dialog(Explorer& explorer) {
    open_when_asked(explorer, Dialog::save_as, "Save scene as");
    centre_next_window();
    if (!ImGui::BeginPopupModal("Save scene as", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(420.0f);
    const bool enter = ImGui::InputText("file", &explorer.view.save_path, ImGuiInputTextFlags_EnterReturnsTrue);
    // Only what this dialog's Save said: an older error (a failed screenshot) belongs elsewhere.
    std::string& said = explorer.view.save_as_error;
    if (!said.empty()) ImGui::TextColored(ImVec4(1, 0.43f, 0.43f, 1), "%s", said.c_str());
    if (ImGui::Button("Save") || enter) {
        explorer.session.messages.error.clear();
        if (run_command(explorer, command::SaveAs{explorer.view.save_path})) {
            ImGui::CloseCurrentPopup();
            said.clear();
            if (explorer.session.files.quit_after_save) explorer.session.quit = true;
        } else {
            said = explorer.session.messages.error;
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || escape_pressed()) {
        ImGui::CloseCurrentPopup();
        explorer.session.files.quit_after_save = false;
        // Its warning ("exists ...: Save again to overwrite it") is moot once cancelled.
        if (!said.empty() && explorer.session.messages.error == said) explorer.session.messages.error.clear();
        said.clear();
    }
    ImGui::EndPopup();
}

void load_error_dialog(Explorer& explorer) {
    open_when_asked(explorer, Dialog::load_error, "Could not load");
    centre_next_window();
    if (!ImGui::BeginPopupModal("Could not load", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
    ImGui::TextColored(ImVec4(1, 0.43f, 0.43f, 1), "%s", explorer.session.messages.load_error.c_str());
    ImGui::PopTextWrapPos();
    ImGui::TextUnformatted("The current scene is unchanged.");
    if (ImGui::Button("OK") || escape_pressed()) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

}  // namespace

void draw_menu_bar(Explorer& explorer) {
    if (!ImGui::BeginMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Save", "Ctrl+S")) explorer.commands.push(command::Save{});
        if (ImGui::MenuItem("Save as...")) explorer.commands.push(command::AskSaveAs{});
        if (ImGui::MenuItem("Open BRDF...")) explorer.view.dialog = Dialog::open_brdf;
        if (ImGui::MenuItem("Add model...")) explorer.view.dialog = Dialog::add_model;
        if (ImGui::MenuItem("Screenshot", "F12")) explorer.commands.push(command::Screenshot{});
        if (explorer.session.platform.can_quit) {
            ImGui::Separator();
            if (ImGui::MenuItem("Quit", "Esc")) explorer.commands.push(command::AskQuit{});
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        // One docked view at a time, where the plots' room allows one.
        if (ImGui::MenuItem("BRDF views", nullptr, &explorer.view.show_brdf_views) && explorer.view.show_brdf_views)
            explorer.view.show_spectra = false;
        if (ImGui::MenuItem("Spectra", nullptr, &explorer.view.show_spectra) && explorer.view.show_spectra)
            explorer.view.show_brdf_views = false;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        const History& h = explorer.doc.history;
        const std::string undo_text = h.can_undo() ? "Undo " + h.undo_label() : "Undo";
        const std::string redo_text = h.can_redo() ? "Redo " + h.redo_label() : "Redo";
        if (ImGui::MenuItem(undo_text.c_str(), "Ctrl+Z", false, h.can_undo())) explorer.commands.push(command::Undo{});
        if (ImGui::MenuItem(redo_text.c_str(), "Ctrl+Shift+Z / Ctrl+Y", false, h.can_redo())) explorer.commands.push(command::Redo{});
        ImGui::EndMenu();
    }
    // What a frame is waiting for (explore/busy.h), where the eye goes after an
    // edit. A narrow panel has room for one of the two: the hint, while it
    // lasts (a fraction of a second), then the unsaved mark again.
    const bool busy = !explorer.session.busy.empty();
    if (unsaved(explorer.doc) && !(busy && narrow_panel())) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "  unsaved edits");
    if (busy) ImGui::TextColored(ImVec4(0.5f, 0.8f, 1, 1), "  %s", explorer.session.busy.c_str());
    ImGui::EndMenuBar();
}

void draw_dialogs(Explorer& explorer) {
    quit_dialog(explorer);
    save_as_dialog(explorer);
    load_error_dialog(explorer);
    open_brdf_dialog(explorer);
    add_model_dialog(explorer);
}

}  // namespace m3055::explore
