#include "explore/apply.h"

#include "explore/add_model.h"
#include "explore/brdf_files.h"
#include "explore/files.h"
#include "explore/operations.h"
#include "explore/overloaded.h"

namespace m3055::explore {

namespace {

bool ask_quit(Explorer& e) {
    if (!e.session.platform.can_quit) return false;  // a page is closed by its tab, not by Esc
    if (work_unsaved(e)) e.view.dialog = Dialog::unsaved_edits;
    else e.session.quit = true;
    return true;
}

}  // namespace

bool apply_command(Explorer& e, const Command& command) {
    return std::visit(
        Overloaded{
            [&](const DisplayRequest& request) {
                e.display_requests.push_back(request);
                e.session.render_needed = true;  // answered after the displays are drawn
                return true;
            },
            [&](const command::OpenBrdf& c) { return open_brdf(e, c.path); },
            [&](const command::AskQuit&) { return ask_quit(e); },
            [&](const command::Quit&) { return e.session.quit = true; },
            [&](const command::SelectObject& c) {
                if (c.index < 0 || c.index >= static_cast<int>(e.doc.scene.objects.size())) return false;
                e.view.selected_object = c.index;
                return true;
            },
            [&](const command::SelectLight& c) {
                if (c.index < 0 || c.index >= static_cast<int>(e.doc.scene.lights.size())) return false;
                e.view.selected_light = c.index;
                return true;
            },
            [&](const command::TogglePanels&) { return e.view.show_panels = !e.view.show_panels, true; },
            [&](const auto& c) { return apply(e, c); },
        },
        command);
}

void apply_commands(Explorer& e) {
    for (const Command& command : e.commands.take()) {
        try {
            apply_command(e, command);
        } catch (const std::exception& error) {
            e.session.messages.error = error.what();
        }
    }
}

bool run_command(Explorer& e, Command command) {
    std::vector<Command> queued = e.commands.take();
    for (const Command& earlier : queued) {
        try {
            apply_command(e, earlier);
        } catch (const std::exception& error) {
            e.session.messages.error = error.what();
        }
    }
    return apply_command(e, command);
}

}  // namespace m3055::explore
