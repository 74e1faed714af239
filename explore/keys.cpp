#include "explore/keys.h"


#include <cctype>

namespace m3055::explore {

namespace {

// Number keys pick the figure presets in the paper's order; 0 is the spec example.
const char* const kFigureKeys[10] = {"spec_example", "fig05", "fig06", "fig07", "fig08",
                                     "fig09",        "fig10", "fig11", "fig12", "fig13"};

bool control_shortcut(CommandQueue& commands, const KeyPress& press, FigureChord chord) {
    switch (press.key) {
        case Key::z: return press.shift ? (commands.push(command::Redo{}), true) : (commands.push(command::Undo{}), true);
        case Key::y: return commands.push(command::Redo{}), true;
        case Key::s: return commands.push(command::Save{}), true;
        case Key::digit:  // in the page Ctrl+digit without Alt is left to the browser (its tabs, its zoom)
            if (chord == FigureChord::ctrl_alt && !press.alt) return false;
            return commands.push(command::LoadFigure{kFigureKeys[press.digit]}), true;
        default: return false;
    }
}

}  // namespace

const char* figure_for_digit(int digit) { return digit >= 0 && digit <= 9 ? kFigureKeys[digit] : ""; }

const char* figure_chord_name(FigureChord chord) { return chord == FigureChord::ctrl_alt ? "Ctrl+Alt" : "Ctrl"; }

bool handle_shortcut(Explorer& explorer, const KeyPress& press, const KeyFocus& focus) {
    if (focus.text_input) return false;  // the field's own editing (and its own Ctrl+Z)
    if (press.key == Key::digit && (press.digit < 0 || press.digit > 9)) return false;
    CommandQueue& commands = explorer.commands;
    const FigureChord chord = explorer.session.platform.figure_chord;
    if (press.ctrl) return control_shortcut(commands, press, chord);
    if (focus.wants_keyboard || focus.item_active) return false;
    switch (press.key) {
        case Key::digit: {  // typed, not a shortcut: a number meant for a field must not replace the scene
            const std::string digit = std::to_string(press.digit);
            explorer.session.messages.status = "key " + digit + " does nothing: " + figure_chord_name(chord) + "+" + digit +
                                               " (or Objects > Fig. buttons) loads " + kFigureKeys[press.digit] +
                                               ", undoably";
            return false;
        }
        case Key::escape: commands.push(command::AskQuit{}); return true;
        case Key::r: commands.push(command::ResetCamera{}); return true;
        case Key::f1: commands.push(command::TogglePanels{}); return true;
        case Key::f12: commands.push(command::Screenshot{}); return true;
        default: return false;
    }
}

std::optional<KeyPress> parse_key_name(const std::string& name) {
    std::string lower;
    for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    KeyPress press;
    if (lower.rfind("ctrl+", 0) == 0) {
        press.ctrl = true;
        lower = lower.substr(5);
    }
    if (lower.rfind("alt+", 0) == 0) {
        press.alt = true;
        lower = lower.substr(4);
    }
    if (lower.rfind("shift+", 0) == 0) {
        press.shift = true;
        lower = lower.substr(6);
    }
    if (lower == "escape" || lower == "esc") press.key = Key::escape;
    else if (lower == "f1") press.key = Key::f1;
    else if (lower == "f12") press.key = Key::f12;
    else if (lower == "r") press.key = Key::r;
    else if (lower == "s") press.key = Key::s;
    else if (lower == "y") press.key = Key::y;
    else if (lower == "z") press.key = Key::z;
    else if (lower.size() == 1 && std::isdigit(static_cast<unsigned char>(lower[0]))) {
        press.key = Key::digit;
        press.digit = lower[0] - '0';
    } else if (lower.size() == 1 && lower[0] >= 'a' && lower[0] <= 'z') {
        press.key = Key::other;  // a letter with no shortcut: does nothing, as in the window
    } else {
        return std::nullopt;
    }
    return press;
}

}  // namespace m3055::explore
