// The view: how the explorer shows the document, none of it saved or undone.
// What is selected, which panes and plots show and how, the side panel's
// sections, the dialogs' fields. Widgets may set these directly; the keys,
// the script and the page set them through commands (explore/commands.h).
#pragma once

#include "analysis/plane_curve.h"

#include <map>
#include <string>

namespace m3055::explore {

// The title of the plots' window (polar plot, profile, statistics).
inline constexpr const char* kPlotsTitle = "Plane of incidence";

// The modal dialogs, opened by the frame after a command asks for one.
enum class Dialog { none, unsaved_edits, save_as, load_error, open_brdf, add_model };

struct View {
    int selected_object = 0;  // whose material the Material panel edits
    int selected_group = 0;   // which of a model file's materials, when it is a mesh with several
    int selected_light = 0;   // the light last edited in the Lights panel
    int plotted_light = 0;    // the polar plot's light: picked in the plot's own header only
    int dragged_light = -1;   // the light whose arrow is being dragged on the light plot (-1: none)

    // The polar plot's radial scale: chosen by the user and kept.
    RadialScale plot_scale = RadialScale::lobe;
    double plot_top = 1.0;  // fixed: the outer circle; log: the outer circle's value

    // A/B compare: the selected object rendered a second time in the document's material B.
    bool compare = false;
    bool compare_diff = false;  // a third pane: |A - B| per channel, scaled
    int diff_scale = 0;         // its whole scale, 1 ... 255; 0: automatic (grading/ab_compare.h)

    int profile_row = -1;  // the scanline profile's row: the last display row hovered on A (-1: none yet)

    bool show_panels = true;  // F1
    bool show_brdf_views = false;  // View > BRDF views (one docked view at a time: it or the spectra)
    bool show_spectra = false;     // View > Spectra
    bool views_log = true;         // its slice's colour: logarithmic
    float lobe_yaw = 0.6f, lobe_pitch = 0.5f;  // its 3D lobe's turn (radians)
    // The plots under the side panel folded to their title bar (explore/layout.h, plots_under_side).
    bool plots_folded = false;
    // Side panel sections to open (true) or close by name, next frame (--script's `section`).
    std::map<std::string, bool> section_requests;

    Dialog dialog = Dialog::none;  // to open next frame
    // The dialogs' and the File section's text fields.
    std::string save_path = "m3055-scene.json";  // Save As
    std::string save_as_error;  // what the Save As dialog's last Save said (not an older error)
    std::string load_path;                       // File > load
    std::string brdf_path;                       // File > Open BRDF
    std::string model_path;                      // File > Add model
};

}  // namespace m3055::explore
