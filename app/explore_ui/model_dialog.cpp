// File > Add model...'s dialog: a path field (explore_ui/path_dialog.h); the
// page opens the browser's file chooser instead, whose picked file is added by its extension.
#include "explore_ui/panels.h"

#include "explore/add_model.h"
#include "explore/apply.h"
#include "explore_ui/path_dialog.h"

namespace m3055::explore {

void add_model_dialog(Explorer& explorer) {
    Messages& messages = explorer.session.messages;
    path_dialog(explorer, {"Add model", Dialog::add_model,
                           "A Wavefront .obj (with its .mtl) or glTF .gltf/.glb file, added standing on the floor.",
                           "Add", &explorer.view.model_path, &messages.load_error,
                           [&] { return run_command(explorer, command::AddModel{explorer.view.model_path}); },
                           [&] {
                               // The dialog showed why the model was not added; the File section's
                               // "Could not load" is about scenes, and the model is not a problem now.
                               if (messages.error == messages.load_error) messages.error.clear();
                               messages.load_error.clear();
                           }});
}

}  // namespace m3055::explore
