// The explorer, top to bottom in the order of Dear ImGui's
// example_glfw_opengl3/main.cpp: the starting scene, a window with its GL
// table, ImGui on it, then a loop that sleeps until something happens and then
// draws one frame (render on demand: left alone it draws nothing).
#include "explore_ui/explore.h"

#include "analysis/brdf_views.h"
#include "analysis/plane_curve_gpu.h"
#include "explore/brdf_files.h"
#include "explore/busy.h"
#include "explore/display_renderers.h"
#include "explore/files.h"
#include "explore/keys.h"
#include "explore/operations.h"
#include "explore/practice.h"
#include "explore/nonfinite_view.h"
#include "explore/readouts.h"
#include "explore/script.h"
#include "explore/start.h"
#include "explore/state.h"
#include "explore/undo.h"
#include "explore_ui/compare_view.h"
#include "explore_ui/display_view.h"
#include "explore_ui/glfw_keys.h"
#include "explore_ui/imgui_layer.h"
#include "explore_ui/panels.h"
#include "explore_ui/readout_requests.h"
#include "explore_ui/window.h"
#include "gl/gl_api.h"
#include "image/image.h"
#include "passes/brdf_grid.h"
#include "frame/renderer.h"
#include "gl/program.h"
#include "scene/load.h"
#include "scene/presets.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>  // ClosePopupsExceptModals, GetTopMostPopupModal (1.86)

#include <cmath>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <system_error>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace m3055 {

using namespace explore;

namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// When the process started (static initialization, before main): start-up
// to the first frame is measured from here (--stats' first_frame_ms).
const std::chrono::steady_clock::time_point kProcessStart = std::chrono::steady_clock::now();

void write_stats(const std::string& path, long frames, long renders, double first_frame_ms,
                 const std::vector<double>& render_frame_ms, const Script* script) {
    nlohmann::json stats = {{"frames", frames}, {"renders", renders}, {"first_frame_ms", first_frame_ms},
                            {"render_frame_ms", render_frame_ms}};
    stats["idle"] = nlohmann::json::array();
    if (script) {
        for (const IdleRecord& r : script->idle_records()) {
            stats["idle"].push_back({{"seconds", r.seconds}, {"frames", r.frames}});
        }
        stats["script_errors"] = script->errors();
    }
    const std::string text = stats.dump(2) + "\n";
    write_file_atomic(path, text.data(), text.size());
}

// One running explorer: the state, the script, the renderers, and the frame.
class Explorer {
public:
    Explorer(const ExploreOptions& options, ExplorerState& state, std::optional<Script>& script, Window& window,
             ImGuiLayer& imgui, const GlApi& gl, FrameInfo& info)
        : options_(options), state_(state), script_(script), window_(window), imgui_(imgui), gl_(gl), info_(info) {
        try {
            // One program cache for the context: A, B, the GPU curves, the
            // BRDF views and the .brdf check compile each program once.
            programs_ = std::make_unique<ProgramCache>(gl);
            renderer_a_ = std::make_unique<Renderer>(gl, *programs_);
            renderer_b_ = std::make_unique<Renderer>(gl, *programs_);
            compare_ = std::make_unique<CompareView>(gl);
            // No stall on a new specialization (explore/display_renderers.h).
            if (!options.compile_at_once) {
                defer_compiles(*renderer_a_);
                defer_compiles(*renderer_b_);
            }
            // .brdf files: the polar plot's GPU curves and the GLSL check of a (re)loaded file.
            plane_curves_ = std::make_unique<PlaneCurves>(gl, *programs_);
            info_.plane_curves = plane_curves_.get();
            brdf_views_ = std::make_unique<BrdfViews>(gl, *programs_);
            state_.brdf_compile_check = [this](const Material& m) { return brdf_compile_error(*programs_, m); };
        } catch (const std::exception& e) {
            state_.error = e.what();
        }
        // The free area before the first frame, for a script's `display modern`.
        int window_w = 0, window_h = 0;
        window_.framebuffer_size(&window_w, &window_h);
        const Layout start = layout_for(float(window_w), float(window_h), true);
        info_.free_width = int(start.display.w);
        info_.free_height = int(start.display.h);
    }

    ~Explorer() {
        gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
        compare_.reset();  // GL objects go while the context is still current
        reference_.reset();
        practice_diff_.reset();
        practice_.reset();
        info_.plane_curves = nullptr;
        state_.brdf_compile_check = nullptr;
        plane_curves_.reset();
        brdf_views_.reset();
        renderer_b_.reset();
        renderer_a_.reset();
        programs_.reset();
    }

    // --assignment: the reference (a scene one rendered on A, which then
    // renders the student's scene) and the live grade. False (printed) on a bad reference.
    bool practise(grading::Assignment assignment) {
        try {
            if (!renderer_a_) throw std::runtime_error(state_.error);
            practice_ = std::make_unique<Practice>(std::move(assignment), renderer_a_.get(), options_.allow_brdf);
            reference_ = std::make_unique<PaneTexture>(gl_, practice_->reference_image());
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s\n", e.what());
            state_.error = e.what();  // the page shows it (an assignment picked while running)
            return false;
        }
        state_.practice = practice_->start_status();
        state_.changed();
        return true;
    }

    // The window closed, Esc, or (--exit-after-script) the script and any capture are done.
    bool done() {
        if (state_.quit) return true;
        if (window_.should_close()) {
            if (!unsaved(state_)) return true;
            window_.cancel_close();  // ask first (the unsaved-edits dialog)
            state_.quit_requested = true;
            window_.events().frames_owed = std::max(window_.events().frames_owed, 1);
        }
        return script_ && script_->finished() && options_.exit_after_script && pending_capture_.empty() &&
               (options_.capture_window.empty() || window_captured_) && !frame_needed();
    }

    // Something to draw: input to settle, a changed scene, a screenshot or a capture.
    bool frame_needed() const {
        return window_.events().frames_owed > 0 || state_.scene_changed || state_.screenshot_requested ||
               !pending_capture_.empty();
    }

    // Sleeps until there is work (an event, or a script's idle time ends), then
    // runs the script's next command.
    void wait_for_work() {
        const bool script_busy = script_ && !script_->finished() && !script_->idling();
        // Watched .brdf files: wake at least every poll period.
        const double most = brdf_files_in_use(state_).empty() ? 1e30 : kBrdfPollSeconds;
        if (frame_needed() || script_busy) window_.poll();
        else if (practice_ && practice_->settle_left(state_.practice, window_.time()) >= 0.0) grade_when_settled();
        else if (script_ && script_->idling())
            window_.wait(std::min(most, std::max(0.0, script_->idle_until() - window_.time())));
        else if (deferred_programs() > 0) compile_when_idle();
        else window_.wait(most < 1e30 ? most : -1.0);
        if (poll_brdf_files(state_, window_.time())) window_.events().frames_owed = std::max(window_.events().frames_owed, 1);
        step_script();
    }

    void draw_frame() {
        const auto frame_start = std::chrono::steady_clock::now();
        const long renders_before = info_.renders;
        for (const std::string& path : window_.events().dropped) {
            const bool ok = is_brdf_path(path) ? open_brdf(state_, path) : load_scene(state_, path);
            if (!ok) state_.show_load_error = true;  // a dialog: the panel may be scrolled away
        }
        window_.events().dropped.clear();
        imgui_.new_frame();
        apply_keys();
        state_.busy = busy_line(state_, deferred_programs());
        const ImGuiIO& io = ImGui::GetIO();
        const float fb_scale = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0f;
        const int panes = 1 + (state_.compare ? 1 + (state_.compare_diff ? 1 : 0) : 0) + (practice_ ? 1 : 0) +
                          (shows_practice_difference() ? 1 : 0);
        Layout layout = layout_for_panes(io.DisplaySize.x, io.DisplaySize.y, state_.show_panels, panes,
                                         renderer_a_ ? renderer_a_->width() : state_.scene.display.width,
                                         renderer_a_ ? renderer_a_->height() : state_.scene.display.height, fb_scale,
                                         ImGui::GetTextLineHeight() + 4.0f, kSideWidth + side_extra_);
        // The plots under the side panel folded (their title bar's arrow);
        // not where the BRDF views take their place.
        const bool views_shown = state_.show_brdf_views && brdf_views_;
        if (state_.plots_folded && !views_shown) fold_plots(layout, ImGui::GetFrameHeight());
        const bool plots_were_folded = state_.plots_folded;
        note_free_area(layout, fb_scale);
        apply_mouse();
        note_hovered_row();
        if (state_.show_panels) {
            info_.side_extra = side_extra_;
            draw_side_panel(state_, info_, layout.side.x, layout.side.y, layout.side.w, layout.side.h);
            follow_side_panel_content(layout);
        }
        draw_dialogs(state_);
        // A finished edit (no widget held, no drag on the display) is one undo step.
        if (!ImGui::IsAnyItemActive() && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) commit_edits(state_);
        render_if_changed();
        // A .brdf material's NaN or infinite pixels: one line over the display (read back once a render).
        nonfinite_line_ = renderer_a_ ? nonfinite_warning(readouts_.nonfinite(state_, *renderer_a_).counts) : "";
        answer_probes();
        update_compare();  // the difference pane shows with the panels hidden too
        answer_grade_print();
        // After the render: the strip's histogram and timings are this frame's.
        if (state_.show_panels) {
            info_.histogram = renderer_a_ ? &readouts_.histogram(state_, *renderer_a_) : nullptr;
            info_.profile = renderer_a_ ? readouts_.profile(state_, *renderer_a_) : nullptr;
            info_.profile_b = profile_of_b();
            // The BRDF views (View menu) docked beside the plots, in the strip's
            // room: its right part under the display; in place of the plots
            // where they are a column or a cell (too narrow for both).
            Rect strip = layout.bottom, views = layout.bottom;
            const bool row = !layout.plots_in_cell && !layout.plots_beside && !layout.plots_under_side;
            StripShape shape = row ? StripShape::row : StripShape::column;
            if (views_shown && row) {
                views.w = std::min(460.0f, strip.w * 0.5f);
                strip.w -= views.w;
                views.x = strip.x + strip.w;
                if (strip.w < 640.0f) shape = StripShape::column;  // too narrow for three columns: one under another
            }
            // Under the side panel with the statistics in the band under the display.
            if (layout.stats.w > 0.0f) {
                shape = StripShape::plots;
                draw_stats_band(state_, info_, layout.stats.x, layout.stats.y, layout.stats.w, layout.stats.h);
            }
            if (!views_shown || row) draw_bottom_strip(state_, info_, strip.x, strip.y, strip.w, strip.h, shape);
            draw_brdf_views(state_, brdf_views_.get(), views.x, views.y, views.w, views.h);
            // Folded or unfolded: the side panel takes its new height next frame.
            if (state_.plots_folded != plots_were_folded)
                window_.events().frames_owed = std::max(window_.events().frames_owed, 2);
        }
        if (state_.screenshot_requested && renderer_a_) {
            state_.screenshot_requested = false;
            take_screenshot(state_, *renderer_a_);
        }
        draw_displays(layout, fb_scale);
        window_.set_title("M3055 material explorer - " + title_name(state_));
        present();
        info_.frame_ms = milliseconds_since(frame_start);
        if (info_.renders != renders_before && info_.render_frame_ms.size() < FrameInfo::kMaxFrameSamples)
            info_.render_frame_ms.push_back(info_.frame_ms);
        schedule_window_capture();
    }

    // Writes --stats; the process's exit status (1 after a failed script command).
    int finish() {
        int status = script_ && script_->errors() > 0 ? 1 : 0;
        if (options_.stats_path.empty()) return status;
        try {
            write_stats(options_.stats_path, info_.frames, info_.renders, first_frame_ms_, info_.render_frame_ms,
                        script_ ? &*script_ : nullptr);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s\n", e.what());
            status = 1;
        }
        return status;
    }

    // The display as `m3055 render` writes it: A rendered now with its
    // specialized program (no deferral), as F12's screenshot is; the window
    // shows it on the next frame. Throws what the render throws.
    Rgb8Image render_display_now() {
        if (!renderer_a_) throw std::runtime_error(state_.error);
        const bool deferring = renderer_a_->defers_compiles();
        renderer_a_->set_defer_compiles(false);
        try {
            renderer_a_->render(state_.scene);
        } catch (...) {
            renderer_a_->set_defer_compiles(deferring);
            throw;
        }
        renderer_a_->set_defer_compiles(deferring);
        state_.changed();  // the panes, read-outs and practice follow on the next frame
        return renderer_a_->read_display();
    }

private:
    std::size_t deferred_programs() const {
        return renderer_a_ ? explore::deferred_programs(*renderer_a_, *renderer_b_) : 0;
    }

    // A specialized program waiting: after kIdleBeforeCompile s with no
    // input, between frames (explore/display_renderers.h).
    // Then one frame, so that "compiling..." goes without waiting for input
    // (only when a program was built: a failing compile must not spin).
    void compile_when_idle() {
        window_.wait(kIdleBeforeCompile);
        if (frame_needed()) return;  // input came: that frame first
        const std::size_t before = deferred_programs();
        try {
            render_specialized_when_idle(state_, *renderer_a_, *renderer_b_);
            gl_.Finish();
        } catch (const std::exception& e) {
            state_.error = e.what();
        }
        if (deferred_programs() < before) window_.events().frames_owed = std::max(window_.events().frames_owed, 1);
    }

    // The edit has settled (kSettleSeconds without a change, no button held):
    // grade_one on A, between frames, off the interaction path; then a frame shows it.
    void grade_when_settled() {
        const double left = practice_->settle_left(state_.practice, window_.time());
        if (left > 0.0) return window_.wait(left);
        if (ImGui::GetIO().MouseDown[0]) return window_.wait(-1.0);  // a drag held still is not over
        practice_->regrade(state_.practice, state_.scene, state_.scene_file, *renderer_a_);
        window_.events().frames_owed = std::max(window_.events().frames_owed, 1);
    }

public:
    // The grade of the scene as it is now (graded at once if stale); "" outside practice mode.
    std::string grade_now() {
        if (!practice_) return "";
        if (state_.practice.pending) practice_->regrade(state_.practice, state_.scene, state_.scene_file, *renderer_a_);
        return grade_line(state_.practice);
    }

private:

    // --script's `print_grade`.
    void answer_grade_print() {
        if (!state_.practice.print_requested) return;
        state_.practice.print_requested = false;
        if (!practice_) return;
        std::printf("%s\n", grade_now().c_str());
        std::fflush(stdout);
    }

    void step_script() {
        if (!script_ || script_->finished()) return;
        const bool was_idle = script_->idling();
        script_->step(state_, window_.time(), info_.frames, info_.free_width, info_.free_height);
        WindowEvents& events = window_.events();
        // A command asks for a frame; so does the end of a script's last idle
        // (else nothing would draw the frame that takes --capture-window and exits).
        if (!script_->idling() && (!was_idle || script_->finished()))
            events.frames_owed = std::max(events.frames_owed, 1);
        if (!script_->capture_path.empty()) {
            pending_capture_ = script_->capture_path;
            script_->capture_path.clear();
        }
    }

    // Shortcuts, unless a widget or a dialog takes the keyboard (keys.h).
    void apply_keys() {
        const ImGuiIO& io = ImGui::GetIO();
        KeyFocus focus;
        focus.text_input = io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);
        focus.wants_keyboard = io.WantCaptureKeyboard;
        focus.item_active = ImGui::IsAnyItemActive();
        for (const WindowEvents::Key& k : window_.events().keys) {
            // Esc closes an open menu, combo or context popup first (a modal
            // dialog answers Esc itself: its Cancel); the next Esc quits.
            if (k.key == GLFW_KEY_ESCAPE && ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId) &&
                !ImGui::GetTopMostPopupModal()) {
                ImGui::ClosePopupsExceptModals();
                continue;
            }
            handle_shortcut(state_, key_press_from_glfw(k.key, k.mods), focus);
        }
        window_.events().keys.clear();
    }

    // The side panel's width follows its content: what reached past its edge
    // widens it (and its label column) from the next frame on; it never
    // narrows back, so controls do not jump as sections open and close. Not
    // measured when it is narrowed beside three panes or shares a column with
    // the plots (there it is what is left).
    void follow_side_panel_content(const Layout& layout) {
        if (layout.plots_in_cell || layout.plots_under_side) return;
        const float overflow = info_.side_overflow;
        if (overflow < 0.5f) {
            side_stuck_ = false;
            side_last_overflow_ = 0.0f;
            return;
        }
        // Content that grows with the panel (anchored to its right edge) is
        // not helped by growing it: stop, and leave it to the clip check.
        if (side_last_overflow_ > 0.0f && overflow >= side_last_overflow_ - 0.5f) side_stuck_ = true;
        side_last_overflow_ = overflow;
        if (side_stuck_ || side_extra_ >= kMaxSideExtra) return;
        side_extra_ = std::min(kMaxSideExtra, side_extra_ + std::ceil(overflow));
        window_.events().frames_owed = std::max(window_.events().frames_owed, 2);
    }

    // Room for one display (two in compare, with the gap between them), for `display modern`.
    void note_free_area(const Layout& layout, float fb_scale) {
        const int displays = state_.compare ? 2 : 1;
        info_.free_width = int((layout.display.w - (state_.compare ? kCompareGap : 0.0f)) * fb_scale) / displays;
        info_.free_height = int(layout.display.h * fb_scale);
    }

    // Orbit and zoom with the mouse over the display (not over a panel).
    void apply_mouse() {
        const ImGuiIO& io = ImGui::GetIO();
        if (io.WantCaptureMouse) return;
        // A drag orbits the camera; with Shift held it moves the selected object
        // in the view plane, under the mouse (one undo step per drag either way).
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f) && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
            if (io.KeyShift) move_object_in_view(state_, io.MouseDelta.x, io.MouseDelta.y, shown_a_.h);
            else orbit_camera(state_, io.MouseDelta.x, io.MouseDelta.y);
        }
        if (io.MouseWheel != 0.0f) zoom_camera(state_, io.MouseWheel);
        // A click (no drag) picks the object under it.
        if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && !moved_while_down_) {
            if (const auto pixel = pixel_at(state_.scene.display, shown_a_, io.MousePos.x, io.MousePos.y))
                readouts_.pick(state_, pixel->first, pixel->second);
        }
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) moved_while_down_ = false;
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left) && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f))
            moved_while_down_ = true;
    }

    // The A/B read-outs (count, difference pane) of this render, for the strip and the panes.
    void update_compare() {
        update_practice_difference();
        info_.compare_count.clear();
        if (!renderer_a_ || !state_.compare) return;
        try {
            compare_->update(state_, readouts_.display_image(*renderer_a_), *renderer_b_);
            info_.compare_count = compare_->count_label();
        } catch (const std::exception& e) {
            state_.error = e.what();
        }
    }

    // Practice mode's third pane: |your scene - reference| per channel at the
    // A/B split's automatic scale (grading/ab_compare.h), as the report shows it;
    // made again after a render. Not with the split on (A, B, |A - B| are there).
    bool shows_practice_difference() const { return practice_ && !state_.compare; }
    void update_practice_difference() {
        if (!shows_practice_difference() || !practice_diff_stale_ || !renderer_a_) return;
        practice_diff_stale_ = false;
        practice_diff_.reset();
        const Rgb8Image& mine = readouts_.display_image(*renderer_a_);
        const Rgb8Image& reference = practice_->reference_image();
        if (mine.width != reference.width || mine.height != reference.height) return;  // no pane: sizes differ
        practice_diff_scale_ = grading::auto_difference_scale(mine, reference);
        practice_diff_count_ = grading::level_difference(mine, reference, state_.scene.display.bits).differing;
        practice_diff_ = std::make_unique<PaneTexture>(gl_, grading::scaled_difference(mine, reference, practice_diff_scale_));
    }

    // B's levels on the profile's row, drawn dashed beside A's (the A/B split):
    // made again after a render or for another row, not every frame.
    const RowProfile* profile_of_b() {
        if (!state_.compare || !info_.profile || compare_->b_display().pixels.empty()) return nullptr;
        if (!profile_b_ || profile_b_->row != info_.profile->row)
            profile_b_ = row_profile(compare_->b_display(), state_.scene.display.bits, info_.profile->row);
        return &*profile_b_;
    }

    // The scanline profile follows the row under the mouse on A, and keeps the
    // last one when the mouse leaves the display.
    void note_hovered_row() {
        const ImGuiIO& io = ImGui::GetIO();
        if (io.WantCaptureMouse || ImGui::IsMouseDown(ImGuiMouseButton_Left)) return;
        if (const auto pixel = pixel_at(state_.scene.display, shown_a_, io.MousePos.x, io.MousePos.y))
            state_.profile_row = pixel->second;
    }

    // --script's `probe X Y` and `click X Y`, answered once A is rendered.
    void answer_probes() {
        if (!renderer_a_) return;
        for (const auto& [x, y] : state_.probe_requests) {
            const PixelProbe probe = readouts_.probe(state_, *renderer_a_, x, y);
            std::string line = probe.text();
            for (char& c : line) c = c == '\n' ? '\t' : c;
            std::printf("probe %s\n", line.c_str());
        }
        for (const auto& [x, y] : state_.pick_requests) readouts_.pick(state_, x, y);
        answer_readout_requests(state_, readouts_, *renderer_a_, *compare_, *renderer_b_);
        if (!state_.probe_requests.empty()) std::fflush(stdout);
        state_.probe_requests.clear();
        state_.pick_requests.clear();
    }

    // Over A (not over a panel, not dragging): the probe as a tooltip, and the selection's outline.
    void hover_readouts() {
        const ImGuiIO& io = ImGui::GetIO();
        // Only once the pointer has moved in the window: a pointer parked
        // there (a script's capture under Xvfb) is no one hovering.
        pointer_moved_ |= io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f;
        if (!renderer_a_ || !pointer_moved_ || io.WantCaptureMouse || ImGui::IsMouseDown(ImGuiMouseButton_Left)) return;
        const auto pixel = pixel_at(state_.scene.display, shown_a_, io.MousePos.x, io.MousePos.y);
        if (!pixel) return;
        if (const std::vector<int>* ids = readouts_.object_ids(state_.scene, true))
            draw_selection_outline(*ids, state_.selected_object, state_.scene.display.width,
                                   state_.scene.display.height, shown_a_);
        const PixelProbe probe = readouts_.probe(state_, *renderer_a_, pixel->first, pixel->second);
        ImGui::BeginTooltip();
        const std::string text = probe.text();
        const std::size_t mark = text.find("\nNOT FINITE");
        ImGui::TextUnformatted(text.substr(0, mark).c_str());
        // The probe marks a NaN or infinite pixel in the warning's colour.
        if (mark != std::string::npos) ImGui::TextColored(ImVec4(1.0f, 0.67f, 0.16f, 1.0f), "%s", text.c_str() + mark + 1);
        ImGui::TextDisabled("light %d; click selects the object", state_.plotted_light);
        ImGui::EndTooltip();
    }

    // The non-finite warning, on a dark band at the top of A so it reads over any picture.
    void draw_nonfinite_warning() {
        if (nonfinite_line_.empty()) return;
        ImDrawList* draw = ImGui::GetForegroundDrawList();
        const ImVec2 at(shown_a_.x + 4.0f, shown_a_.y + 4.0f);
        const ImVec2 size = ImGui::CalcTextSize(nonfinite_line_.c_str(), nullptr, false, shown_a_.w - 16.0f);
        draw->AddRectFilled(ImVec2(at.x - 2.0f, at.y - 2.0f), ImVec2(at.x + size.x + 4.0f, at.y + size.y + 2.0f),
                            IM_COL32(0, 0, 0, 210));
        draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, IM_COL32(255, 170, 40, 255), nonfinite_line_.c_str(),
                      nullptr, shown_a_.w - 16.0f);
    }

    // The scene (and B in compare) is rendered only when something changed.
    void render_if_changed() {
        if (!state_.scene_changed || !renderer_a_) return;
        state_.scene_changed = false;
        const auto start = std::chrono::steady_clock::now();
        try {
            render_displays(state_, *renderer_a_, *renderer_b_);
            readouts_.invalidate();
            compare_->invalidate();
            practice_diff_stale_ = true;
            profile_b_.reset();
            gl_.Finish();
            ++info_.renders;
            if (practice_) practice_->scene_changed(state_.practice, window_.time());
        } catch (const std::exception& e) {
            state_.error = e.what();
        }
        info_.render_ms = milliseconds_since(start);
    }

    void draw_displays(const Layout& layout, float fb_scale) {
        if (renderer_a_) {
            // A (with --assignment: the student's scene), B and |A - B| in the
            // A/B split, and the assignment's reference: one size, one magnification.
            std::vector<Pane> panes = {{renderer_a_->display_texture(),
                                        practice_ ? "your scene (Ctrl+S saves it)" : "A: the scene (saved, screenshot)"}};
            if (state_.compare) panes.push_back({renderer_b_->display_texture(), "B: selected object in material B"});
            if (state_.compare && state_.compare_diff && compare_->texture())
                panes.push_back({compare_->texture(), compare_->scale_label(state_) + ", " + compare_->pane_count_label()});
            if (practice_) panes.push_back({reference_->texture(), practice_->reference_label()});
            if (shows_practice_difference() && practice_diff_)
                panes.push_back({practice_diff_->texture(), "|yours - reference| x " + std::to_string(practice_diff_scale_) +
                                                                " (auto), " + std::to_string(practice_diff_count_) +
                                                                " px on another level"});
            info_.scale = draw_display(panes, renderer_a_->width(), renderer_a_->height(), layout.display, fb_scale,
                                       &shown_a_);
            hover_readouts();
            draw_nonfinite_warning();
        }
        if (!state_.show_panels && !state_.error.empty())
            ImGui::GetForegroundDrawList()->AddText(ImVec2(10, 10), IM_COL32(255, 110, 110, 255), state_.error.c_str());
    }

    // Clear the window, draw ImGui (the display is in its background list),
    // write a pending capture of the whole window, show it.
    void present() {
        int width = 0, height = 0;
        window_.framebuffer_size(&width, &height);
        gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);  // the renderer leaves its own bound
        gl_.Viewport(0, 0, width, height);
        gl_.ClearColor(0.11f, 0.11f, 0.13f, 1.0f);
        gl_.Clear(GL_COLOR_BUFFER_BIT);
        imgui_.render();
        if (!pending_capture_.empty()) {
            try {
                write_png(pending_capture_, read_window(gl_, width, height));
            } catch (const std::exception& e) {
                state_.error = e.what();
            }
            pending_capture_.clear();
        }
        window_.swap();
        if (info_.frames == 0) {  // start-up: the first frame shown (GL finished)
            gl_.Finish();
            first_frame_ms_ = milliseconds_since(kProcessStart);
        }
        ++info_.frames;
        window_.events().frames_owed = std::max(0, window_.events().frames_owed - 1);
    }

    // --capture-window: once the script is done and the window has settled,
    // draw one more frame and capture it.
    void schedule_window_capture() {
        const bool script_done = !script_ || script_->finished();
        const bool settled = window_.events().frames_owed == 0 && !state_.scene_changed;
        if (!script_done || !settled || options_.capture_window.empty() || window_captured_) return;
        pending_capture_ = options_.capture_window;
        window_captured_ = true;
        window_.events().frames_owed = 1;
    }

    const ExploreOptions& options_;
    ExplorerState& state_;
    std::optional<Script>& script_;
    Window& window_;
    ImGuiLayer& imgui_;
    const GlApi& gl_;
    FrameInfo& info_;
    std::unique_ptr<ProgramCache> programs_;             // the context's programs, shared by all below
    std::unique_ptr<Renderer> renderer_a_, renderer_b_;  // A, and B for the compare split
    std::unique_ptr<PlaneCurves> plane_curves_;          // the polar plot of .brdf models (GPU)
    std::unique_ptr<BrdfViews> brdf_views_;              // the "BRDF views" window's numbers (GPU)
    Readouts readouts_;      // probe, histogram, profile, pick and outline of A
    std::optional<RowProfile> profile_b_;  // B's levels on the profile's row (reset by each render)
    std::unique_ptr<CompareView> compare_;  // the A/B count and the |A - B| pane
    std::unique_ptr<Practice> practice_;  // --assignment
    std::unique_ptr<PaneTexture> reference_;  // its reference, shown beside A
    static constexpr float kMaxSideExtra = 320.0f;  // a runaway guard: no label is that long
    float side_extra_ = 0.0f;                     // follow_side_panel_content
    double first_frame_ms_ = 0.0;                 // process start to the first frame shown (--stats)
    float side_last_overflow_ = 0.0f;
    bool side_stuck_ = false;
    std::unique_ptr<PaneTexture> practice_diff_;  // |A - reference| (update_practice_difference)
    bool practice_diff_stale_ = true;
    int practice_diff_scale_ = 1;
    unsigned long long practice_diff_count_ = 0;
    Rect shown_a_;           // where A was drawn last (ImGui units)
    std::string nonfinite_line_;  // "" or the warning over A (explore/nonfinite_view.h)
    bool moved_while_down_ = false;  // the left button was dragged: no pick on release
    bool pointer_moved_ = false;     // the pointer has moved in the window at least once
    std::string pending_capture_;  // write the window here after the next frame is drawn
    bool window_captured_ = false; // --capture-window is taken once
};

}  // namespace

// ---- One explorer: the starting scene, a window with its GL table, ImGui on it ----
struct ExplorerSession::Parts {
    ExploreOptions options;  // the Explorer keeps a reference
    ExplorerState state;
    std::optional<Script> script;
    std::optional<Window> window;
    GlApi gl;
    FrameInfo info;
    std::optional<ImGuiLayer> imgui;
    std::optional<Explorer> explorer;
};

std::unique_ptr<ExplorerSession> ExplorerSession::open(const ExploreOptions& options,
                                                       const std::function<void(ExplorerState&)>& prepare) {
    std::unique_ptr<ExplorerSession> session(new ExplorerSession);
    Parts& p = *session->parts_;
    p.options = options;
    // The starting scene and script (before any window, so errors are quick).
    std::optional<grading::Assignment> assignment;
    try {
        assignment = start_scene(p.state, options.scene_path, options.assignment_path);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return nullptr;
    }
    if (!options.script_path.empty()) {
        try {
            p.script = Script::from_file(options.script_path);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s\n", e.what());
            return nullptr;
        }
    }
    if (prepare) prepare(p.state);

    // A window with an OpenGL 3.3 core context (in a browser: WebGL2), and the GL table from it.
    p.window.emplace(options.window_width, options.window_height, "M3055 material explorer");
    if (!p.window->ok()) {
        std::fprintf(stderr, "%s\n", p.window->error().c_str());
        return nullptr;
    }
    std::string missing;
    if (!load_gl_api(p.gl, [](const char* name, void*) { return Window::gl_proc_address(name); }, nullptr, &missing)) {
        std::fprintf(stderr, "m3055 explore: the window's OpenGL lacks %s\n", missing.c_str());
        return nullptr;
    }
    p.info.gl_renderer = reinterpret_cast<const char*>(p.gl.GetString(GL_RENDERER));
    p.info.gl_version = reinterpret_cast<const char*>(p.gl.GetString(GL_VERSION));
    p.info.window_system = glfwGetVersionString();

    // Dear ImGui on the window (its callbacks chain to the window's).
    p.imgui.emplace(p.window->handle());
    p.explorer.emplace(p.options, p.state, p.script, *p.window, *p.imgui, p.gl, p.info);
    if (assignment && !p.explorer->practise(std::move(*assignment))) return nullptr;
    return session;
}

ExplorerSession::ExplorerSession() : parts_(std::make_unique<Parts>()) {}

ExplorerSession::~ExplorerSession() {
    // In reverse order of making: the GL objects while the context is current.
    parts_->explorer.reset();
    parts_->imgui.reset();
    parts_->window.reset();
}

// One turn of the frame loop: sleep until something happens (in a browser:
// return at once, the page calls again on its next animation frame), then
// draw one frame when one is due.
bool ExplorerSession::step() {
    Explorer& explorer = *parts_->explorer;
    if (explorer.done()) return false;
    explorer.wait_for_work();
    if (explorer.frame_needed()) explorer.draw_frame();
    return true;
}

bool ExplorerSession::idle() const { return !parts_->explorer->frame_needed(); }

int ExplorerSession::finish() { return parts_->explorer->finish(); }

ExplorerState& ExplorerSession::state() { return parts_->state; }

long ExplorerSession::renders() const { return parts_->info.renders; }

const std::vector<double>& ExplorerSession::render_frame_ms() const { return parts_->info.render_frame_ms; }

Rgb8Image ExplorerSession::render_display_now() { return parts_->explorer->render_display_now(); }

std::string ExplorerSession::grade_now() { return parts_->explorer->grade_now(); }

bool ExplorerSession::practise(grading::Assignment assignment) {
    return parts_->explorer->practise(std::move(assignment));
}

int run_explorer(const ExploreOptions& options) {
    const std::unique_ptr<ExplorerSession> session = ExplorerSession::open(options);
    if (!session) return 1;
    // The frame loop: sleep until something happens, then draw one frame.
    while (session->step()) {
    }
    return session->finish();
}

}  // namespace m3055
