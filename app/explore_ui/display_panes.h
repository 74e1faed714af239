// The explorer's GPU side: one program cache for the window's context, the
// renderers of A (the scene) and B (the A/B split), the split's read-outs,
// practice mode's reference and difference panes, the display's read-outs,
// the polar plot's GPU curves and the BRDF views. The frame loop
// (explore.cpp) asks it to draw the displays when the document changed, to
// compile a waiting specialization when idle, to answer the read-outs the
// commands asked for, and to lay the panes into the window.
#pragma once

#include "analysis/brdf_views.h"
#include "analysis/plane_curve_gpu.h"
#include "explore/display_renderers.h"
#include "explore/explorer.h"
#include "explore/layout.h"
#include "explore/practice.h"
#include "explore/readouts.h"
#include "explore/refine_tiles.h"
#include "explore_ui/compare_view.h"
#include "explore_ui/display_view.h"
#include "frame/renderer.h"
#include "gl/gl_api.h"
#include "gl/program.h"
#include "grading/assignment.h"
#include "image/image.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <set>
#include <optional>
#include <string>
#include <vector>

namespace m3055::explore {

class DisplayPanes {
public:
    // The renderers and their programs (no stall on a new specialization
    // unless `compile_at_once`); throws what making them throws.
    DisplayPanes(const GlApi& gl, bool compile_at_once);
    ~DisplayPanes();
    DisplayPanes(const DisplayPanes&) = delete;
    DisplayPanes& operator=(const DisplayPanes&) = delete;

    int width() const { return renderer_a_->width(); }
    int height() const { return renderer_a_->height(); }
    PlaneCurves* plane_curves() { return plane_curves_.get(); }
    BrdfViews* brdf_views() { return brdf_views_.get(); }
    // The GLSL check of a .brdf material on this context ("" when it compiles).
    std::string brdf_compile_error(const Material& material);

    // --assignment: the reference (a scene reference is rendered once on A)
    // and the live grade; throws the loader's one-line message.
    void practise(grading::Assignment assignment, bool allow_brdf, Explorer& explorer);
    Practice* practice() { return practice_.get(); }

    // Draws A (and B in the split) when the document or the view asked for
    // it (session.render_needed); the time it took in ms (GPU finished), or
    // a negative value when nothing was drawn. A render error goes to messages.error.
    double render_if_needed(Explorer& explorer, double now);
    // After the model table changed (a .brdf file reloaded: every program is
    // stale), between frames: the general programs and the scene's own compiled
    // and the displays drawn with them, so the next frame waits for none.
    void compile_for_new_table(Explorer& explorer, double now);
    // Programs waiting to be compiled on A and B; compiles the first and
    // draws its display again (the same pixels). Returns whether one was built.
    std::size_t deferred_programs() const;
    bool compile_deferred(Explorer& explorer);
    // A preview of area lights is showing (explore/display_renderers.h): the
    // display is "refining" until refine() has drawn the render's pixels.
    bool refining() const { return refine_pending_; }
    // ... and its first pass, the preview at the display's size, is under way.
    bool sharpening() const { return refine_pending_ && refine_tiles_.sharpening(); }
    // ... the share of the display its pass under way has drawn (0 ... 1).
    double refine_progress() const { return refine_tiles_.progress(); }
    // The displays wait one frame that says "compiling..." before a render
    // that may hold them for seconds (see render_if_needed).
    bool compile_announced() const { return announce_frames_ > 0; }
    bool refine_started() const { return refine_pending_ && refine_tiles_.started(); }
    // For the statistics, what the last drawing's time was of: render_if_needed
    // drew a preview of area lights; the refine that followed has drawn the
    // render's pixels in refine_ms (its tiles together, GPU finished; negative
    // until it has).
    bool drew_preview() const { return drew_preview_; }
    double refine_ms() const { return drew_preview_ && refined_ ? refine_ms_ : -1.0; }
    // The next tile, top down (explore/refine_tiles.h), about kRefineBandMs: where the
    // preview was drawn smaller than the display, first its own pixels at the display's
    // size (a sharp approximation about a second after input stops), then the render's
    // samples; the last tile leaves the displays showing the render's pixels.
    void refine(Explorer& explorer);
    // The display as `m3055 render` writes it: A rendered now with its
    // specialized program; the window shows it on the next frame.
    Rgb8Image render_display_now(Explorer& explorer);
    // Practice mode: grade_one of the scene as it is now (a line as
    // --script's print_grade prints; "" outside practice mode).
    std::string grade_now(Explorer& explorer);
    void regrade(Explorer& explorer);

    // The read-outs the commands left (explorer.display_requests), answered
    // in order now that the displays are drawn.
    void answer_requests(Explorer& explorer);
    // After a render: the A/B count and difference pane, practice mode's difference pane.
    void update_read_outs(Explorer& explorer);
    // This frame's histogram, A's and B's profile on the hovered row, the A/B count's line.
    const LevelHistogram* histogram(const Explorer& explorer);
    const RowProfile* profile(const Explorer& explorer);
    const RowProfile* profile_of_b(const Explorer& explorer);
    std::string compare_count(const Explorer& explorer) const;
    // A's NaN and infinite pixels as one warning line ("" for none).
    std::string nonfinite_line(const Explorer& explorer);
    // The object under display pixel (x, y) of A (-1: the background).
    int pick(const Explorer& explorer, int x, int y);
    // The probe of display pixel (x, y) of A, and the object per pixel for the selection's outline.
    PixelProbe probe(const Explorer& explorer, int x, int y);
    const std::vector<int>* object_ids(const Explorer& explorer, bool allowed_to_compute);

    // The panes as the window shows them: A, B and |A - B| in the split, the
    // reference and |yours - reference| in practice mode.
    std::vector<Pane> panes(const Explorer& explorer) const;
    int pane_count(const Explorer& explorer) const;

private:
    bool shows_practice_difference(const Explorer& explorer) const { return practice_ && !explorer.view.compare; }
    void answer(Explorer& explorer, const DisplayRequest& request);
    void displays_drawn();  // the read-outs of the last drawing are stale
    void update_practice_difference(Explorer& explorer);

    const GlApi& gl_;
    std::unique_ptr<ProgramCache> programs_;             // the context's programs, shared by all below
    std::unique_ptr<Renderer> renderer_a_, renderer_b_;  // A, and B for the compare split
    std::unique_ptr<PlaneCurves> plane_curves_;          // the polar plot of .brdf models (GPU)
    std::unique_ptr<BrdfViews> brdf_views_;              // the "BRDF views" window's numbers (GPU)
    Readouts readouts_;                                  // probe, histogram, profile, pick and outline of A
    std::optional<RowProfile> profile_b_;                // B's levels on the profile's row (reset by each render)
    std::unique_ptr<CompareView> compare_;               // the A/B count and the |A - B| pane
    std::unique_ptr<Practice> practice_;                 // --assignment
    std::unique_ptr<PaneTexture> reference_;             // its reference, shown beside A
    std::unique_ptr<PaneTexture> practice_diff_;         // |A - reference|
    PreviewScale preview_scale_;   // how much smaller a preview of area lights is drawn
    bool refine_pending_ = false;  // the displays show a preview, not the render's pixels
    RefineTiles refine_tiles_;     // where the refine draws next
    bool drew_preview_ = false;    // the last render_if_needed drew a preview
    double refine_ms_ = 0.0;       // the refine's tiles so far, after that preview
    // Area lights or shadows, and the models, of the scenes drawn so far (their
    // programs are built), the one announced last, and how many frames more wait for it.
    std::set<std::string> drawn_program_shapes_;
    std::string announced_shape_;
    int announce_frames_ = 0;
    // What the displays show refined: the document's revision, and in the split
    // which object wears material B. A render asked for again (a read-out, a
    // screenshot) of the same keeps those pixels rather than draw a preview.
    struct Refined {
        std::uint64_t revision = 0;
        bool compare = false;
        int selected_object = 0, selected_group = -1;
        bool operator==(const Refined& o) const {
            return revision == o.revision && compare == o.compare && selected_object == o.selected_object &&
                   selected_group == o.selected_group;
        }
    };
    static Refined refined_of(const Explorer& explorer);
    std::optional<Refined> refined_;
    bool practice_diff_stale_ = true;
    int practice_diff_scale_ = 1;
    unsigned long long practice_diff_count_ = 0;
};

}  // namespace m3055::explore
