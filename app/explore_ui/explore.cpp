// The explorer, top to bottom in the order of Dear ImGui's
// example_glfw_opengl3/main.cpp: the starting scene, a window with its GL
// table, ImGui on it, then a loop that sleeps until something happens and then
// draws one frame (render on demand: left alone it draws nothing).
//
// A frame: new ImGui frame; the keys, the mouse on the display and the
// widgets give their commands; the commands are applied in order
// (explore/apply.h); a finished edit becomes an undo step; the displays are
// drawn if the document changed; the read-outs the commands asked for are
// answered; the panes and panels are drawn; the window is shown.
#include "explore_ui/explore.h"

#include "explore/add_model.h"
#include "explore/apply.h"
#include "explore/brdf_files.h"
#include "explore/busy.h"
#include "explore/explorer.h"
#include "explore/keys.h"
#include "explore/layout.h"
#include "explore/operations.h"
#include "explore/script.h"
#include "explore/start.h"
#include "explore_ui/display_panes.h"
#include "explore_ui/display_view.h"
#include "explore_ui/glfw_keys.h"
#include "explore_ui/imgui_layer.h"
#include "explore_ui/panels.h"
#include "explore_ui/window.h"
#include "gl/gl_api.h"
#include "image/image.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>  // ClosePopupsExceptModals, GetTopMostPopupModal (1.86)

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace m3055 {

using namespace explore;

// Named, not anonymous: ExplorerSession::Parts (declared in the header) holds a FrameLoop.
namespace frame_loop {

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
        for (const IdleRecord& r : script->idle_records()) stats["idle"].push_back({{"seconds", r.seconds}, {"frames", r.frames}});
        stats["script_errors"] = script->errors();
    }
    const std::string text = stats.dump(2) + "\n";
    write_file_atomic(path, text.data(), text.size());
}

// The frame loop of one running explorer: the window's input, the script,
// the panels and the display panes around the explorer's logic.
class FrameLoop {
public:
    FrameLoop(const ExploreOptions& options, Explorer& explorer, std::optional<Script>& script, Window& window,
              ImGuiLayer& imgui, const GlApi& gl, FrameInfo& info)
        : options_(options), e_(explorer), script_(script), window_(window), imgui_(imgui), gl_(gl), info_(info) {
        try {
            panes_ = std::make_unique<DisplayPanes>(gl, options.compile_at_once);
            info_.plane_curves = panes_->plane_curves();
            e_.session.platform.brdf_compile_check = [this](const Material& m) { return panes_->brdf_compile_error(m); };
        } catch (const std::exception& error) {
            e_.session.messages.error = error.what();
        }
        // The free area before the first frame, for a script's `display modern`.
        int window_w = 0, window_h = 0;
        window_.framebuffer_size(&window_w, &window_h);
        const Layout start = layout_for(float(window_w), float(window_h), true);
        info_.free_width = int(start.display.w);
        info_.free_height = int(start.display.h);
    }

    ~FrameLoop() {
        info_.plane_curves = nullptr;
        e_.session.platform.brdf_compile_check = nullptr;
        panes_.reset();  // while the context is current
    }

    DisplayPanes* panes() { return panes_.get(); }

    // --assignment: the reference and the live grade. False (printed) on a bad reference.
    bool practise(grading::Assignment assignment) {
        try {
            if (!panes_) throw std::runtime_error(e_.session.messages.error);
            panes_->practise(std::move(assignment), options_.allow_brdf, e_);
        } catch (const std::exception& error) {
            std::fprintf(stderr, "%s\n", error.what());
            e_.session.messages.error = error.what();  // the page shows it (an assignment picked while running)
            return false;
        }
        return true;
    }

    // The window closed, Esc, or (--exit-after-script) the script and any capture are done.
    bool done() {
        if (e_.session.quit) return true;
        if (window_.should_close()) {
            if (!work_unsaved(e_)) return true;
            window_.cancel_close();  // ask first (the unsaved-edits dialog)
            e_.commands.push(command::AskQuit{});
            owe_frames(1);
        }
        return script_ && script_->finished() && options_.exit_after_script && pending_capture_.empty() &&
               (options_.capture_window.empty() || window_captured_) && !frame_needed();
    }

    // Something to draw: input to settle, commands to apply, a changed scene, a dialog to open or a capture.
    bool frame_needed() const {
        return window_.events().frames_owed > 0 || !e_.commands.empty() || e_.session.render_needed ||
               !e_.display_requests.empty() || e_.view.dialog != Dialog::none || !pending_capture_.empty();
    }

    // Sleeps until there is work (an event, or a script's idle time ends), then
    // runs the script's next command.
    void wait_for_work() {
        const bool script_busy = script_ && !script_->finished() && !script_->idling();
        // Watched .brdf files: wake at least every poll period.
        const bool watching = e_.session.platform.watch_files && !watched_brdf_files(e_).empty();
        const double most = watching ? kBrdfPollSeconds : 1e30;
        Practice* practice = panes_ ? panes_->practice() : nullptr;
        if (frame_needed() || script_busy) window_.poll();
        else if (practice && practice->settle_left(e_.session.practice, window_.time()) >= 0.0) grade_when_settled();
        else if (!e_.session.brdf_watch.reload_pending.empty()) reload_when_idle();  // a script's idle time too
        else if (panes_ && panes_->refining()) refine_when_idle();  // a script's idle time too
        else if (script_ && script_->settled(e_, info_.frames)) window_.poll();  // its step ends the settle
        else if (script_ && script_->settling() && panes_ && panes_->deferred_programs() > 0) compile_when_idle();
        else if (script_ && script_->idling())
            window_.wait(std::min(most, std::max(0.0, script_->idle_until() - window_.time())));
        else if (panes_ && panes_->deferred_programs() > 0) compile_when_idle();
        else window_.wait(most < 1e30 ? most : -1.0);
        if (watching && poll_brdf_files(e_, window_.time())) owe_frames(1);
        step_script();
    }

    void draw_frame() {
        const auto frame_start = std::chrono::steady_clock::now();
        // 1. Input: files dropped on the window, ImGui's new frame with this frame's keys.
        for (Command& command : dropped_files_commands(window_.events().dropped)) e_.commands.push(std::move(command));
        window_.events().dropped.clear();
        imgui_.new_frame();
        apply_keys();
        e_.session.busy = busy_shown_ = busy_now();

        // 2. Where everything goes this frame (explore/layout.h).
        const ImGuiIO& io = ImGui::GetIO();
        const float fb_scale = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0f;
        Layout layout = layout_for_panes(io.DisplaySize.x, io.DisplaySize.y, e_.view.show_panels,
                                         panes_ ? panes_->pane_count(e_) : 1,
                                         panes_ ? panes_->width() : e_.doc.scene.display.width,
                                         panes_ ? panes_->height() : e_.doc.scene.display.height, fb_scale,
                                         ImGui::GetTextLineHeight() + 4.0f, kSideWidth + side_extra_);
        // The plots under the side panel folded (their title bar's arrow); not where the BRDF views take their place.
        const bool views_shown = (e_.view.show_brdf_views && panes_) || e_.view.show_spectra;
        if (e_.view.plots_folded && !views_shown) fold_plots(layout, ImGui::GetFrameHeight());
        const bool plots_were_folded = e_.view.plots_folded;
        note_free_area(layout, fb_scale);

        // 3. The mouse on the display and the side panel's widgets give their commands.
        apply_mouse();
        note_hovered_row();
        if (e_.view.show_panels) {
            info_.side_extra = side_extra_;
            draw_side_panel(e_, info_, layout.side.x, layout.side.y, layout.side.w, layout.side.h);
            follow_side_panel_content(layout);
        }
        draw_dialogs(e_);

        // 4. The commands, in order; a finished edit (no widget held, no drag on the display) is one undo step.
        apply_commands(e_);
        if (!ImGui::IsAnyItemActive() && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) commit_edits(e_);

        // 5. The displays, drawn again when the document changed, and what the commands asked of them.
        const long renders_before = info_.renders;
        if (panes_) {
            const double render_ms = panes_->render_if_needed(e_, window_.time());
            if (render_ms >= 0.0) info_.render_ms = render_ms, ++info_.renders;
            nonfinite_line_ = panes_->nonfinite_line(e_);  // a .brdf material's NaN or infinite pixels
            panes_->answer_requests(e_);
            panes_->update_read_outs(e_);  // the difference panes show with the panels hidden too
            info_.compare_count = panes_->compare_count(e_);
            info_.refining = panes_->refining();
            info_.sharpening = panes_->sharpening();
            info_.refine_started = panes_->refine_started();
            info_.refine_progress = panes_->refine_progress();
            info_.render_is_preview = panes_->drew_preview();
            info_.refine_ms = panes_->refine_ms();
        }
        // What the next frame will show beside the menu: a preview drawn above is refining from now
        // on (a script's `settle` reads it after this frame).
        e_.session.busy = busy_now();

        // 6. The plots and statistics under the display, then the display panes.
        if (e_.view.show_panels) draw_plots(layout, views_shown, plots_were_folded);
        draw_displays(layout, fb_scale);
        window_.set_title("M3055 material explorer - " + title_name(e_.doc));

        // 7. Show it (and capture it when asked).
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
        } catch (const std::exception& error) {
            std::fprintf(stderr, "%s\n", error.what());
            status = 1;
        }
        return status;
    }

private:
    double last_refine_frame_ = 0.0;  // when a refine's tile was last shown (window time)
    std::string busy_shown_;          // what the last frame's menu bar said beside the menu

    // What stands beside the menu: compiles waiting or announced, a refine, a .brdf being watched.
    std::string busy_now() const {
        return busy_line(e_.session.brdf_watch, panes_ ? panes_->deferred_programs() + panes_->compile_announced() : 0,
                         panes_ && panes_->refining());
    }
    void owe_frames(int frames) { window_.events().frames_owed = std::max(window_.events().frames_owed, frames); }

    // A specialized program waiting: after kIdleBeforeCompile s with no
    // input, between frames (explore/display_renderers.h). Then one frame,
    // so that "compiling..." goes without waiting for input (only when a
    // program was built: a failing compile must not spin).
    void compile_when_idle() {
        window_.wait(kIdleBeforeCompile);
        if (frame_needed()) return;  // input came: that frame first
        if (panes_->compile_deferred(e_)) owe_frames(1);
    }

    // A preview of area lights on the display: after kIdleBeforeRefine s with
    // no input, between frames, drawn again (a preview drawn smaller first at the
    // display's size, then with the render's samples), a tile at a time (input
    // polled between tiles), shown by a frame every kRefineFrameSeconds and at
    // the end of each pass; "refining..." goes with the last.
    void refine_when_idle() {
        if (!panes_->refine_started()) window_.wait(kIdleBeforeRefine);
        else window_.poll();
        if (frame_needed()) return;  // input came: that frame first
        // The preview's own frame was drawn before it knew it would refine: one
        // frame that says so first, as the first tile may build the render's
        // program (seconds on llvmpipe).
        if (busy_shown_ != busy_now()) {
            owe_frames(1);
            return;
        }
        const bool sharpening = panes_->sharpening();
        panes_->refine(e_);
        // Shown when the preview is whole at the display's size, and when the render's pixels are.
        if (sharpening != panes_->sharpening() || !panes_->refining() ||
            window_.time() - last_refine_frame_ >= kRefineFrameSeconds) {
            owe_frames(1);
            last_refine_frame_ = window_.time();
        }
    }

    // A changed .brdf file, after kIdleBeforeCompile s with no input, between
    // frames: re-read and checked, its programs compiled and the displays
    // drawn with them (seconds on llvmpipe); the frames before kept drawing
    // the last version, "reloading FILE..." beside the menu. Then one frame.
    void reload_when_idle() {
        window_.wait(kIdleBeforeCompile);
        if (frame_needed()) return;  // input came: that frame first
        if (reload_changed_brdf_files(e_) && panes_) panes_->compile_for_new_table(e_, window_.time());
        owe_frames(1);
    }

    // The edit has settled (kSettleSeconds without a change, no button held):
    // grade_one on A, between frames, off the interaction path; then a frame shows it.
    void grade_when_settled() {
        const double left = panes_->practice()->settle_left(e_.session.practice, window_.time());
        if (left > 0.0) return window_.wait(left);
        if (ImGui::GetIO().MouseDown[0]) return window_.wait(-1.0);  // a drag held still is not over
        panes_->regrade(e_);
        owe_frames(1);
    }

    void step_script() {
        if (!script_ || script_->finished()) return;
        const bool was_idle = script_->idling();
        script_->step(e_, window_.time(), info_.frames, info_.free_width, info_.free_height);
        // A command asks for a frame; so does the end of a script's last idle
        // (else nothing would draw the frame that takes --capture-window and exits).
        if (!script_->idling() && (!was_idle || script_->finished())) owe_frames(1);
        if (script_->settling() && !was_idle) owe_frames(1);  // the frame that shows whether anything is busy
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
            handle_shortcut(e_, key_press_from_glfw(k.key, k.mods), focus);
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
        owe_frames(2);
    }

    // Room for one display (two in compare, with the gap between them), for `display modern`.
    void note_free_area(const Layout& layout, float fb_scale) {
        const bool compare = e_.view.compare;
        const int displays = compare ? 2 : 1;
        info_.free_width = int((layout.display.w - (compare ? kCompareGap : 0.0f)) * fb_scale) / displays;
        info_.free_height = int(layout.display.h * fb_scale);
    }

    // Orbit and zoom with the mouse over the display (not over a panel).
    void apply_mouse() {
        const ImGuiIO& io = ImGui::GetIO();
        if (io.WantCaptureMouse) return;
        // A drag orbits the camera; with Shift held it moves the selected object
        // in the view plane, under the mouse (one undo step per drag either way).
        // It starts once the mouse has moved more than ImGui's drag threshold
        // (6 px) with the button down, taking the whole way from the press:
        // a click that jitters by a pixel or two is a click.
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
            ImVec2 delta = io.MouseDelta;
            if (!moved_while_down_) delta = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left);  // the drag's first frame
            moved_while_down_ = true;
            if (delta.x != 0.0f || delta.y != 0.0f) {
                if (io.KeyShift) e_.commands.push(command::MoveObjectInView{delta.x, delta.y, shown_a_.h});
                else e_.commands.push(command::OrbitCamera{delta.x, delta.y});
            }
        }
        if (io.MouseWheel != 0.0f) e_.commands.push(command::ZoomCamera{io.MouseWheel});
        // A click (no drag) picks the object under it.
        if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && !moved_while_down_) {
            if (const auto pixel = pixel_at(e_.doc.scene.display, shown_a_, io.MousePos.x, io.MousePos.y))
                e_.commands.push(DisplayRequest{command::Pick{pixel->first, pixel->second}});
        }
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) moved_while_down_ = false;
    }

    // The scanline profile follows the row under the mouse on A, and keeps the
    // last one when the mouse leaves the display.
    void note_hovered_row() {
        const ImGuiIO& io = ImGui::GetIO();
        if (io.WantCaptureMouse || ImGui::IsMouseDown(ImGuiMouseButton_Left)) return;
        if (const auto pixel = pixel_at(e_.doc.scene.display, shown_a_, io.MousePos.x, io.MousePos.y))
            e_.view.profile_row = pixel->second;
    }

    // The polar plot, the profile and the statistics: in the strip under the
    // display, or beside stacked panes, or under the side panel; the BRDF
    // views docked beside them (View menu).
    void draw_plots(const Layout& layout, bool views_shown, bool plots_were_folded) {
        info_.histogram = panes_ ? panes_->histogram(e_) : nullptr;
        info_.profile = panes_ ? panes_->profile(e_) : nullptr;
        info_.profile_b = panes_ ? panes_->profile_of_b(e_) : nullptr;
        // The BRDF views in the strip's room: its right part under the display;
        // in place of the plots where they are a column or a cell (too narrow for both).
        Rect strip = layout.bottom, views = layout.bottom;
        const bool row = !layout.plots_in_cell && !layout.plots_beside && !layout.plots_under_side;
        StripShape shape = row ? StripShape::row : StripShape::column;
        if (views_shown && row) {
            views.w = std::min(460.0f, strip.w * 0.5f);
            strip.w -= views.w;
            views.x = strip.x + strip.w;
            if (strip.w < 640.0f) shape = StripShape::column;  // too narrow for three columns: one under another
        }
        // Under the side panel with the statistics (and the profile) in the band under the display.
        if (layout.stats.w > 0.0f) {
            shape = layout.profile.w > 0.0f ? StripShape::polar : StripShape::plots;
            draw_stats_band(e_, info_, layout.stats.x, layout.stats.y, layout.stats.w, layout.stats.h);
            if (layout.profile.w > 0.0f)
                draw_profile_band(info_, layout.profile.x, layout.profile.y, layout.profile.w, layout.profile.h);
        }
        if (!views_shown || row) draw_bottom_strip(e_, info_, strip.x, strip.y, strip.w, strip.h, shape);
        draw_brdf_views(e_, panes_ ? panes_->brdf_views() : nullptr, views.x, views.y, views.w, views.h);
        draw_spectra(e_, views.x, views.y, views.w, views.h);
        // Folded or unfolded: the side panel takes its new height next frame.
        if (e_.view.plots_folded != plots_were_folded) owe_frames(2);
    }

    void draw_displays(const Layout& layout, float fb_scale) {
        if (panes_) {
            info_.scale = draw_display(panes_->panes(e_), panes_->width(), panes_->height(), layout.display, fb_scale,
                                       &shown_a_);
            hover_readouts();
            draw_nonfinite_warning();
        }
        const std::string& error = e_.session.messages.error;
        if (!e_.view.show_panels && !error.empty() && !e_.session.platform.error_line_outside)
            ImGui::GetForegroundDrawList()->AddText(ImVec2(10, 10), IM_COL32(255, 110, 110, 255), error.c_str());
    }

    // Over A (not over a panel, not dragging): the probe as a tooltip, and the selection's outline.
    void hover_readouts() {
        const ImGuiIO& io = ImGui::GetIO();
        // Only once the pointer has moved in the window: a pointer parked
        // there (a script's capture under Xvfb) is no one hovering.
        pointer_moved_ |= io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f;
        if (!pointer_moved_ || io.WantCaptureMouse || ImGui::IsMouseDown(ImGuiMouseButton_Left)) return;
        const Display& display = e_.doc.scene.display;
        const auto pixel = pixel_at(display, shown_a_, io.MousePos.x, io.MousePos.y);
        if (!pixel) return;
        if (const std::vector<int>* ids = panes_->object_ids(e_, true))
            draw_selection_outline(*ids, e_.view.selected_object, display.width, display.height, shown_a_);
        const PixelProbe probe = panes_->probe(e_, pixel->first, pixel->second);
        ImGui::BeginTooltip();
        const std::string text = probe.text();
        const std::size_t mark = text.find("\nNOT FINITE");
        ImGui::TextUnformatted(text.substr(0, mark).c_str());
        // The probe marks a NaN or infinite pixel in the warning's colour.
        if (mark != std::string::npos) ImGui::TextColored(ImVec4(1.0f, 0.67f, 0.16f, 1.0f), "%s", text.c_str() + mark + 1);
        ImGui::TextDisabled("light %d; click selects the object", e_.view.plotted_light);
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
            } catch (const std::exception& error) {
                e_.session.messages.error = error.what();
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
        const bool settled = window_.events().frames_owed == 0 && !e_.session.render_needed;
        if (!script_done || !settled || options_.capture_window.empty() || window_captured_) return;
        pending_capture_ = options_.capture_window;
        window_captured_ = true;
        window_.events().frames_owed = 1;
    }

    const ExploreOptions& options_;
    Explorer& e_;
    std::optional<Script>& script_;
    Window& window_;
    ImGuiLayer& imgui_;
    const GlApi& gl_;
    FrameInfo& info_;
    std::unique_ptr<DisplayPanes> panes_;  // null when the renderers could not be made (the error shows)
    static constexpr float kMaxSideExtra = 320.0f;  // a runaway guard: no label is that long
    float side_extra_ = 0.0f;                     // follow_side_panel_content
    float side_last_overflow_ = 0.0f;
    bool side_stuck_ = false;
    double first_frame_ms_ = 0.0;  // process start to the first frame shown (--stats)
    Rect shown_a_;                 // where A was drawn last (ImGui units)
    std::string nonfinite_line_;   // "" or the warning over A (explore/nonfinite_view.h)
    bool moved_while_down_ = false;  // the left button was dragged past the threshold: no pick on release
    bool pointer_moved_ = false;     // the pointer has moved in the window at least once
    std::string pending_capture_;    // write the window here after the next frame is drawn
    bool window_captured_ = false;   // --capture-window is taken once
};

}  // namespace frame_loop
using namespace frame_loop;

// ---- One explorer: the starting scene, a window with its GL table, ImGui on it ----
struct ExplorerSession::Parts {
    ExploreOptions options;  // the frame loop keeps a reference
    Explorer explorer;
    std::optional<Script> script;
    std::optional<Window> window;
    GlApi gl;
    FrameInfo info;
    std::optional<ImGuiLayer> imgui;
    std::optional<FrameLoop> loop;
};

std::unique_ptr<ExplorerSession> ExplorerSession::open(const ExploreOptions& options,
                                                       const std::function<void(Explorer&)>& prepare) {
    std::unique_ptr<ExplorerSession> session(new ExplorerSession);
    Parts& p = *session->parts_;
    p.options = options;
    // The starting scene and script (before any window, so errors are quick).
    std::optional<grading::Assignment> assignment;
    try {
        assignment = start_scene(p.explorer, options.scene_path, options.assignment_path);
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
    if (prepare) prepare(p.explorer);

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

    // Dear ImGui on the window (its callbacks chain to the window's), then the frame loop.
    p.imgui.emplace(p.window->handle());
    p.loop.emplace(p.options, p.explorer, p.script, *p.window, *p.imgui, p.gl, p.info);
    if (assignment && !p.loop->practise(std::move(*assignment))) return nullptr;
    return session;
}

ExplorerSession::ExplorerSession() : parts_(std::make_unique<Parts>()) {}

ExplorerSession::~ExplorerSession() {
    // In reverse order of making: the GL objects while the context is current.
    parts_->loop.reset();
    parts_->imgui.reset();
    parts_->window.reset();
}

// One turn of the frame loop: sleep until something happens (in a browser:
// return at once, the page calls again on its next animation frame), then
// draw one frame when one is due.
bool ExplorerSession::step() {
    FrameLoop& loop = *parts_->loop;
    if (loop.done()) return false;
    loop.wait_for_work();
    if (loop.frame_needed()) loop.draw_frame();
    return true;
}

bool ExplorerSession::idle() const { return !parts_->loop->frame_needed(); }

double ExplorerSession::asked_sleep() const { return idle() ? parts_->window->asked_sleep() : 0.0; }

int ExplorerSession::finish() { return parts_->loop->finish(); }

Explorer& ExplorerSession::explorer() { return parts_->explorer; }

long ExplorerSession::renders() const { return parts_->info.renders; }

const std::vector<double>& ExplorerSession::render_frame_ms() const { return parts_->info.render_frame_ms; }

Rgb8Image ExplorerSession::render_display_now() {
    DisplayPanes* panes = parts_->loop->panes();
    if (!panes) throw std::runtime_error(parts_->explorer.session.messages.error);
    return panes->render_display_now(parts_->explorer);
}

std::string ExplorerSession::grade_now() {
    DisplayPanes* panes = parts_->loop->panes();
    return panes ? panes->grade_now(parts_->explorer) : "";
}

bool ExplorerSession::practise(grading::Assignment assignment) { return parts_->loop->practise(std::move(assignment)); }

int run_explorer(const ExploreOptions& options) {
    const std::unique_ptr<ExplorerSession> session = ExplorerSession::open(options);
    if (!session) return 1;
    // The frame loop: sleep until something happens, then draw one frame.
    while (session->step()) {
    }
    return session->finish();
}

}  // namespace m3055
