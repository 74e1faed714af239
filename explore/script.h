// --script: a text file of UI actions, one a line, run one per frame as the
// same commands the panels and keys give (commands.h, keys.h), so a test can
// drive the explorer without a mouse. '#' starts a comment. Commands:
//
//   set PATH VALUE          a scene field, as m3055's --set (validated like a load),
//                           e.g. set objects[0].material.m 40
//   model NAME              the selected object's model (as the model selector)
//   print_models            print the model selector's entries ("model NAME<TAB>LABEL")
//   select_object I | select_light I
//   rescale_eq14            the Material panel's eq. 14 button
//   light_preset NAME       single_key, three_point_white/_warm/_cool/_studio, paper_main_secondary
//   light_angles I AZ EL    light I's azimuth/elevation sliders (degrees)
//   light_drag I X Y        a drag on light I's sphere widget, disc coordinates (y up)
//   light_name I TEXT       light I's name field (TEXT may be empty: no name)
//   add_light | remove_light I | add_object [SHAPE] | remove_object I
//   shape NAME              the selected object's shape (sphere, plane, cube, cylinder, torus)
//   figure NAME             a figure preset (fig05 ... fig13, spec_example)
//   load PATH               load a scene file (errors show in the window)
//   open_brdf PATH          File > Open BRDF: PATH on the selected object (errors show in the window)
//   add_model PATH          File > Add model...: PATH standing on the floor, selected (errors show in the window)
//   drop PATH               the command a file dropped on the window gives (.brdf, a model file, else a scene)
//   replace_file SRC DST    an editor saving DST with SRC's bytes (for the .brdf watcher)
//   brdf_views on|off       View > BRDF views (the slice, albedo and 3D lobe window)
//   spectra on|off          View > Spectra (the light's and the material's spectra, larger)
//   print_brdf              print "brdf error=TEXT<TAB>status=TEXT<TAB>error=TEXT<TAB>busy=TEXT" (the Material
//                           section's .brdf error, the status strip, the panel's general error, and
//                           "reloading FILE..." while a changed .brdf file waits to be reloaded)
//   display m3055|modern    the Display panel's two preset buttons
//   orbit DX DY | zoom STEPS   a mouse drag (pixels) / wheel steps on the display
//   projection perspective|orthographic
//   compare on|off | compare_model NAME | copy_b (the "B = copy of A" button)
//   key NAME                a key press: escape, r, f1, f12, ctrl+s, ctrl+z, ctrl+shift+z,
//                           ctrl+y, 0-9, ctrl+0-9 (as with no widget active)
//   plot_light I            the polar plot header's light
//   plot_scale fixed|model_max|log|lobe   its radial scale (lobe: the default)
//   probe X Y               print the pixel probe of display pixel (X, Y), y = 0 the top row:
//                           "probe pixel (X, Y)<TAB>linear R G B<TAB>level ...<TAB>png ...<TAB>object I (MODEL)..."
//                           (a conductor or color_spectrum material adds a field per light: "light I "NAME": C0_l ...")
//   compare_diff on|off     the A/B panel's third pane, |A - B| per channel, scaled
//   diff_scale auto|N       its scale (N a whole number in 1 ... 255)
//   print_compare           print "compare differing=N pixels=M scale=S" (pixels on another level)
//   save_difference PATH    the difference pane's image as a PNG, at display resolution
//   print_profile [Y]       hover row Y of A (optional), then print the scanline profile (and B's, "profile_b ...", in the split):
//                           "profile row Y bits B<TAB>R l l ...<TAB>G ...<TAB>B ..." (display levels)
//   click X Y               a click on display pixel (X, Y): selects the object there
//   section NAME open|closed   open or close a side panel section (its header's click);
//                           "Plane of incidence": fold the plots under the side panel (plots_under_side)
//   undo | redo             the Edit menu's entries (an error when there is nothing to undo)
//   print_grade             (--assignment) print the live grade once current, graded now if stale:
//                           "grade score=S max=M passed=yes|no<TAB>reason<TAB>..." (the reasons grade writes)
//   print_state             print "state title=...<TAB>undo=LABEL<TAB>redo=LABEL<TAB>steps=N<TAB>busy=LINE<TAB>selected=I"
//                           (LINE: what the menu bar says the explorer is busy with, "" when idle)
//   screenshot PATH         display-resolution PNG + scene JSON beside it
//   save_display PATH       A's pixels as the window shows them now, as a PNG: with area lights
//                           a preview until the display has refined (then the render's pixels)
//   screenshot_dir DIR      the folder F12 writes NAME-0001.png ... into
//   save PATH               scene JSON
//   capture PATH            a PNG of the whole window after the next frame
//   idle SECONDS            no input for that long; counts the frames drawn meanwhile
//   settle SECONDS          no input until the busy line is empty (the displays refined, programs
//                           compiled, .brdf files reloaded) after a frame, or SECONDS at most
//   quit                    quit at once (Esc asks first when there are unsaved edits)
#pragma once

#include "explore/explorer.h"

#include <string>
#include <vector>

namespace m3055::explore {

struct IdleRecord {
    double seconds = 0.0;
    long frames = 0;  // UI frames drawn while idle
};

class Script {
public:
    // Reads the file; throws std::runtime_error naming it when unreadable.
    static Script from_file(const std::string& path);

    bool finished() const { return next_ >= lines_.size() && !idling(); }
    bool idling() const { return idle_until_ > 0.0; }
    bool settling() const { return idling() && until_settled_; }
    double idle_until() const { return idle_until_; }

    // Runs the next command (or ends an idle period whose time has come).
    // `now` is glfwGetTime(), `frames` the frames drawn so far.
    void step(Explorer& explorer, double now, long frames, int free_width, int free_height);

    // Set by `capture`: the frame loop writes the window to it and clears it.
    std::string capture_path;

    int errors() const { return errors_; }
    // `idle SECONDS`: no input from now for `seconds`, counting the frames drawn;
    // `until_settled`: the idle ends sooner, once a frame has shown an empty busy line.
    void start_idle(double seconds, double now, long frames, bool until_settled = false);
    // Whether a `settle` may end now: a frame drawn since it began and nothing busy.
    bool settled(const Explorer& explorer, long frames) const;
    const std::vector<IdleRecord>& idle_records() const { return idle_records_; }

private:
    void run(Explorer& explorer, const std::string& line, double now, long frames, int free_width,
             int free_height);

    std::string path_;
    std::vector<std::string> lines_;
    std::size_t next_ = 0;
    int errors_ = 0;
    double idle_until_ = 0.0;
    double idle_seconds_ = 0.0;
    long idle_start_frames_ = 0;
    bool until_settled_ = false;
    std::vector<IdleRecord> idle_records_;
};

}  // namespace m3055::explore
