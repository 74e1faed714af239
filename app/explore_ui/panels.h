// The explorer's ImGui windows. Each function draws one part of the UI; a
// widget edits a copy of what it shows and gives the edited value as a
// command (explore/commands.h), which the frame loop applies after the
// panels are drawn (explore/apply.h), naming the undo step.
#pragma once

#include "analysis/pixel_probe.h"
#include "explore/apply.h"
#include "explore/explorer.h"
#include "explore/files.h"
#include "explore/operations.h"

#include <string>
#include <vector>

namespace m3055 {
class BrdfViews;
class PlaneCurves;
}

namespace m3055::explore {

// What the panels show about the running program and the window.
struct FrameInfo {
    double frame_ms = 0.0;    // CPU time of the last UI frame (without waiting)
    double render_ms = 0.0;   // the last scene render (GPU finished), both halves in compare
    bool render_is_preview = false;  // ... a preview of area lights (explore/display_renderers.h)
    double refine_ms = -1.0;  // the refine after that preview, its tiles together (negative: not done)
    long frames = 0;          // UI frames drawn so far
    long renders = 0;         // scene renders so far
    bool refining = false;    // the display shows a preview of area lights, not yet the render's pixels
    bool sharpening = false;  // ... its refine's first pass: the preview at the display's size
    bool refine_started = false;   // ... its refine has drawn a tile
    double refine_progress = 0.0;  // ... the share of the display the pass under way has drawn
    // frame_ms of the frames that rendered a changed scene, the last kMaxFrameSamples
    // (--stats' render_frame_ms; the page's m3055.frameTimes(): scripts/bench-web).
    std::vector<double> render_frame_ms;
    static constexpr std::size_t kMaxFrameSamples = 4096;
    std::string gl_renderer;  // GL_RENDERER of the window's context
    std::string gl_version;   // GL_VERSION
    std::string window_system;  // glfwGetVersionString()
    int free_width = 0;       // pixels available for the display (for the "modern" preset)
    int free_height = 0;
    int scale = 1;            // whole-pixel magnification of the display
    // The side panel's label column: kLabelRoom plus what the panel grew by
    // (explore.cpp); out: how far its content reached past its edge this frame.
    float side_extra = 0.0f;
    float side_overflow = 0.0f;
    const LevelHistogram* histogram = nullptr;  // of A's display, this frame
    const RowProfile* profile = nullptr;        // A's levels on the last hovered row (none yet: nullptr)
    const RowProfile* profile_b = nullptr;      // B's on the same row in the A/B split (else nullptr)
    std::string compare_count;                  // the A/B split's "N of M pixels on another level", or ""
    PlaneCurves* plane_curves = nullptr;        // the polar plot's curves on the GPU (null: the CPU's)
};

// Left column: display, material, lights, objects and figures, camera, compare, file.
void draw_side_panel(Explorer& explorer, FrameInfo& info, float x, float y, float width,
                     float height);
// Bottom strip: the polar plot of the selected material and the frame statistics.
// Its shape (explore/layout.h): three columns under the display, or the three
// one under another (beside stacked panes, in the free cell beside the third
// of three panes, or beside the docked BRDF views), or the polar plot over
// the profile alone (under the side panel, the statistics in a band of their
// own under the display: draw_stats_band).
enum class StripShape { row, column, plots, polar };
void draw_bottom_strip(Explorer& explorer, const FrameInfo& info, float x, float y,
                       float width, float height, StripShape shape = StripShape::row);
// The statistics in three columns side by side (timings and scale, the
// level histogram, the last message), in the band under the display.
void draw_stats_band(const Explorer& explorer, const FrameInfo& info, float x, float y, float width, float height);
// The scanline profile alone, in the band under the display (beside the statistics).
void draw_profile_band(const FrameInfo& info, float x, float y, float width, float height);

// The side panel's menu bar (File, Edit: undo/redo by name) and the modal
// dialogs (unsaved edits on quit, Save As, a failed drop): dialogs.cpp.
void draw_menu_bar(Explorer& explorer);
void draw_dialogs(Explorer& explorer);
// File > Open BRDF's dialog, and the Material section's note on a .brdf
// material (its file, the last error in red): panel_brdf.cpp.
void open_brdf_dialog(Explorer& explorer);
void brdf_material_note(const Explorer& explorer, const Material& material);
// File > Add model...'s dialog: a model file's path (model_dialog.cpp).
void add_model_dialog(Explorer& explorer);
// The "Spectra" window (View menu): the Spectra section's plot, larger, docked as the BRDF views are.
void draw_spectra(Explorer& explorer, float x, float y, float width, float height);
// The "BRDF views" window: slice, albedo and 3D lobe of the selected material (panel_brdf_views.cpp).
void draw_brdf_views(Explorer& explorer, BrdfViews* views, float x, float y, float width, float height);

// Sections of the side panel (one file each).
void display_section(Explorer& explorer, const FrameInfo& info);
void material_section(Explorer& explorer);
void lights_section(Explorer& explorer);
// The selected light's spectrum and the selected material's R(lambda) (panel_spectra.cpp).
void spectra_section(Explorer& explorer);
void objects_section(Explorer& explorer);
void camera_section(Explorer& explorer);
void compare_section(Explorer& explorer);
void file_section(Explorer& explorer);
// --assignment: the live score and reasons (panel_assignment.cpp).
void assignment_section(Explorer& explorer);
// The Lights panel's top-down light plot and key-to-fill ratio (a drag turns a light: edit_light).
void light_plot(Explorer& explorer);
// The bottom strip's polar plot with its header (light, radial scale): panel_plot.cpp.
// `curves`: the GPU's curves (.brdf models need them), else the CPU reference's.
void plot_section(Explorer& explorer, PlaneCurves* curves, float width, float height);

}  // namespace m3055::explore
