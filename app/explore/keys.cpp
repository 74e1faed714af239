#include "explore/keys.h"

#include <GLFW/glfw3.h>

#include <cctype>

namespace m3055::explore {

namespace {
// Number keys pick the figure presets in the paper's order; 0 is the spec example.
const char* const kFigureKeys[10] = {"spec_example", "fig05", "fig06", "fig07", "fig08",
                                     "fig09",        "fig10", "fig11", "fig12", "fig13"};

// 0-9 on the main row or the keypad -> 0..9; -1 for any other key.
int digit_of(int key) {
    if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) return key - GLFW_KEY_0;
    if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9) return key - GLFW_KEY_KP_0;
    return -1;
}

bool control_shortcut(ExplorerState& state, int key, int mods) {
    const bool shift = (mods & GLFW_MOD_SHIFT) != 0;
    if (key == GLFW_KEY_Z) return shift ? redo(state) : undo(state);
    if (key == GLFW_KEY_Y) return redo(state);
    if (key == GLFW_KEY_S) return save_or_ask(state), true;
    if (const int digit = digit_of(key); digit >= 0) return load_figure(state, kFigureKeys[digit]);
    return false;
}
}  // namespace

bool handle_shortcut(ExplorerState& state, int key, int mods, const KeyFocus& focus) {
    if (focus.text_input) return false;  // the field's own editing (and its own Ctrl+Z)
    if ((mods & GLFW_MOD_CONTROL) != 0) return control_shortcut(state, key, mods);
    if (focus.wants_keyboard || focus.item_active) return false;
    if (const int digit = digit_of(key); digit >= 0) {
        if (unsaved(state)) {
            state.status = "key " + std::to_string(digit) + " ignored: the scene has unsaved edits (Ctrl+" +
                           std::to_string(digit) + " replaces it, undoably)";
            return false;
        }
        return load_figure(state, kFigureKeys[digit]);
    }
    switch (key) {
        case GLFW_KEY_ESCAPE: state.quit_requested = true; return true;
        case GLFW_KEY_R: reset_camera(state); return true;
        case GLFW_KEY_F1: state.show_panels = !state.show_panels; return true;
        case GLFW_KEY_F12: state.screenshot_requested = true; return true;
        default: return false;
    }
}

bool parse_key_name(const std::string& name, int* key, int* mods) {
    std::string lower;
    for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    *mods = 0;
    if (lower.rfind("ctrl+", 0) == 0) {
        *mods |= GLFW_MOD_CONTROL;
        lower = lower.substr(5);
    }
    if (lower.rfind("shift+", 0) == 0) {
        *mods |= GLFW_MOD_SHIFT;
        lower = lower.substr(6);
    }
    if (lower == "escape" || lower == "esc") return *key = GLFW_KEY_ESCAPE, true;
    if (lower == "f1") return *key = GLFW_KEY_F1, true;
    if (lower == "f12") return *key = GLFW_KEY_F12, true;
    if (lower.size() == 1 && std::isdigit(static_cast<unsigned char>(lower[0]))) {
        return *key = GLFW_KEY_0 + (lower[0] - '0'), true;
    }
    if (lower.size() == 1 && lower[0] >= 'a' && lower[0] <= 'z') return *key = GLFW_KEY_A + (lower[0] - 'a'), true;
    return false;
}

}  // namespace m3055::explore
