#include "explore_ui/display_panes.h"

#include "explore/display_renderers.h"
#include "explore/files.h"
#include "explore/nonfinite_view.h"
#include "explore/overloaded.h"
#include "grading/ab_compare.h"
#include "passes/brdf_grid.h"
#include "passes/shader_plan.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace m3055::explore {

namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// "profile row Y bits B<TAB>R l l l ...<TAB>G ...<TAB>B ..." ("profile_b ..." for B's, dashed)
void print_profile(const RowProfile& profile, const char* name = "profile") {
    std::string line = std::string(name) + " row " + std::to_string(profile.row) + " bits " + std::to_string(profile.bits);
    const char* names[3] = {"R", "G", "B"};
    for (std::size_t c = 0; c < 3; ++c) {
        line += std::string("\t") + names[c];
        for (int level : profile.levels[c]) line += " " + std::to_string(level);
    }
    std::printf("%s\n", line.c_str());
}

}  // namespace

DisplayPanes::DisplayPanes(const GlApi& gl, bool compile_at_once) : gl_(gl) {
    // One program cache for the context: A, B, the GPU curves, the BRDF views
    // and the .brdf check compile each program once.
    programs_ = std::make_unique<ProgramCache>(gl);
    renderer_a_ = std::make_unique<Renderer>(gl, *programs_);
    renderer_b_ = std::make_unique<Renderer>(gl, *programs_);
    compare_ = std::make_unique<CompareView>(gl);
    // No stall on a new specialization (explore/display_renderers.h).
    if (!compile_at_once) {
        defer_compiles(*renderer_a_);
        defer_compiles(*renderer_b_);
    }
    plane_curves_ = std::make_unique<PlaneCurves>(gl, *programs_);
    brdf_views_ = std::make_unique<BrdfViews>(gl, *programs_);
}

DisplayPanes::~DisplayPanes() {
    // GL objects go while the context is still current, the renderers before their programs.
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    compare_.reset();
    reference_.reset();
    practice_diff_.reset();
    practice_.reset();
    plane_curves_.reset();
    brdf_views_.reset();
    renderer_b_.reset();
    renderer_a_.reset();
    programs_.reset();
}

std::string DisplayPanes::brdf_compile_error(const Material& material) {
    return m3055::brdf_compile_error(*programs_, material);
}

void DisplayPanes::practise(grading::Assignment assignment, bool allow_brdf, Explorer& explorer) {
    practice_ = std::make_unique<Practice>(std::move(assignment), renderer_a_.get(), allow_brdf);
    reference_ = std::make_unique<PaneTexture>(gl_, practice_->reference_image());
    practice_diff_stale_ = true;
    explorer.session.practice = practice_->start_status();
    explorer.session.render_needed = true;
}

DisplayPanes::Refined DisplayPanes::refined_of(const Explorer& explorer) {
    if (!explorer.view.compare) return {explorer.doc.revision, false, 0, -1};
    return {explorer.doc.revision, true, explorer.view.selected_object, selected_group(explorer)};
}

namespace {
// What decides a scene's programs beside its object shapes: its area lights'
// and shadows' defines and its models (A's, and B's in the split); "" for a
// scene without area lights or shadows (its general programs are built at start).
std::string program_shape(const Explorer& explorer) {
    const std::vector<std::string> features = area_and_shadow_defines(explorer.doc.scene.lights);
    if (features.empty()) return "";
    std::set<std::string> parts(features.begin(), features.end());
    for (const Object& object : explorer.doc.scene.objects)
        for (const Material* material : materials_of(object)) parts.insert(material->model().name);
    if (explorer.view.compare) parts.insert(explorer.doc.material_b.model().name);
    std::string shape;
    for (const std::string& part : parts) shape += part + " ";
    return shape;
}
}  // namespace

double DisplayPanes::render_if_needed(Explorer& explorer, double now) {
    if (!explorer.session.render_needed) return -1.0;
    explorer.session.render_needed = false;
    if (refined_ == refined_of(explorer)) return -1.0;
    // A scene with area lights or shadows has no general program standing in
    // while its own compiles (frame/renderer.h): one not drawn before in this
    // session first shows a frame that says "compiling..." (this frame, and the
    // next, which shows it), then holds the displays while llvmpipe builds it.
    // Not before the display was drawn at the scene's size (the first render):
    // there is nothing to keep showing.
    const std::string shape = program_shape(explorer);
    const Display& display = explorer.doc.scene.display;
    const bool shows_this_size = renderer_a_->width() == display.width && renderer_a_->height() == display.height;
    if (!shape.empty() && shows_this_size && announce_frames_ == 0 && !drawn_program_shapes_.count(shape) &&
        announced_shape_ != shape) {
        announced_shape_ = shape;
        announce_frames_ = 2;
    }
    if (announce_frames_ > 0) {
        --announce_frames_;
        explorer.session.render_needed = true;
        return -1.0;
    }
    refined_.reset();
    const auto start = std::chrono::steady_clock::now();
    const bool preview = preview_differs(explorer.doc.scene) || (explorer.view.compare && preview_differs(compare_scene(explorer)));
    const int divisor = preview ? preview_scale_.divisor() : 1;
    try {
        render_displays(explorer, *renderer_a_, *renderer_b_, divisor);
        displays_drawn();
        gl_.Finish();
        if (practice_) practice_->scene_changed(explorer.session.practice, now);
    } catch (const std::exception& e) {
        explorer.session.messages.error = e.what();
    }
    const double ms = milliseconds_since(start);
    if (!shape.empty()) drawn_program_shapes_.insert(shape);
    if (preview) preview_scale_.note(ms, divisor);
    refine_pending_ = drew_preview_ = preview;
    refine_ms_ = 0.0;
    refine_tiles_.start(explorer.doc.scene.display.width, explorer.doc.scene.display.height, preview && divisor > 1);
    return ms;
}

void DisplayPanes::displays_drawn() {
    readouts_.invalidate();
    compare_->invalidate();
    practice_diff_stale_ = true;
    profile_b_.reset();
}

void DisplayPanes::refine(Explorer& explorer) {
    const DisplayRegion tile = refine_tiles_.next(kRefineBandMs);
    const auto start = std::chrono::steady_clock::now();
    try {
        refine_region(explorer, *renderer_a_, *renderer_b_, tile,
                      refine_tiles_.sharpening() ? kFastSampling : kRenderSampling);
        displays_drawn();
        gl_.Finish();
    } catch (const std::exception& e) {
        explorer.session.messages.error = e.what();
        refine_pending_ = false;
        return;
    }
    const double ms = milliseconds_since(start);
    refine_tiles_.drawn(tile, ms);
    refine_ms_ += ms;
    if (!refine_tiles_.done()) return;
    refine_pending_ = false;
    refined_ = refined_of(explorer);
}

void DisplayPanes::compile_for_new_table(Explorer& explorer, double now) {
    refined_.reset();  // the same scene, other programs
    try {
        for (Renderer* r : {renderer_a_.get(), renderer_b_.get()})
            if (r->defers_compiles()) r->warm_up_general_programs();
        const bool deferring = renderer_a_->defers_compiles();
        renderer_a_->set_defer_compiles(false);
        renderer_b_->set_defer_compiles(false);
        explorer.session.render_needed = true;
        render_if_needed(explorer, now);
        renderer_a_->set_defer_compiles(deferring);
        renderer_b_->set_defer_compiles(deferring);
    } catch (const std::exception& e) {
        explorer.session.messages.error = e.what();
    }
}

std::size_t DisplayPanes::deferred_programs() const { return explore::deferred_programs(*renderer_a_, *renderer_b_); }

bool DisplayPanes::compile_deferred(Explorer& explorer) {
    const std::size_t before = deferred_programs();
    try {
        render_specialized_when_idle(explorer, *renderer_a_, *renderer_b_);
        gl_.Finish();
    } catch (const std::exception& e) {
        explorer.session.messages.error = e.what();
    }
    return deferred_programs() < before;
}

Rgb8Image DisplayPanes::render_display_now(Explorer& explorer) {
    // What `m3055 render` writes: its program and its area lights' samples.
    Renderer& a = *renderer_a_;
    const bool deferring = a.defers_compiles();
    a.set_defer_compiles(false);
    a.set_area_sampling(kRenderSampling);
    try {
        a.render(explorer.doc.scene);
    } catch (...) {
        a.set_defer_compiles(deferring);
        throw;
    }
    a.set_defer_compiles(deferring);
    explorer.session.render_needed = true;  // the panes, read-outs and practice follow on the next frame
    return a.read_display();
}

void DisplayPanes::regrade(Explorer& explorer) {
    practice_->regrade(explorer.session.practice, explorer.doc.scene, explorer.doc.file, *renderer_a_);
}

std::string DisplayPanes::grade_now(Explorer& explorer) {
    if (!practice_) return "";
    if (explorer.session.practice.pending) regrade(explorer);
    return grade_line(explorer.session.practice);
}

// ---- Read-outs ---------------------------------------------------------------------------

void DisplayPanes::answer(Explorer& explorer, const DisplayRequest& request) {
    const View& view = explorer.view;
    const Display& display = explorer.doc.scene.display;
    std::visit(Overloaded{
                   [&](const command::Probe& p) {
                       std::string line = probe(explorer, p.x, p.y).text();
                       for (char& c : line) c = c == '\n' ? '\t' : c;
                       std::printf("probe %s\n", line.c_str());
                   },
                   [&](const command::Pick& p) {
                       const int object = pick(explorer, p.x, p.y);
                       if (object >= 0) explorer.view.selected_object = object;
                   },
                   [&](const command::PrintProfile&) {
                       const RowProfile* a = readouts_.profile(display, view.profile_row, *renderer_a_);
                       if (!a) throw std::runtime_error("print_profile: no row hovered yet");
                       print_profile(*a);
                       if (view.compare) {  // B's row, as the plot draws it dashed
                           compare_->update(explorer, readouts_.display_image(*renderer_a_), *renderer_b_);
                           print_profile(row_profile(compare_->b_display(), display.bits, a->row), "profile_b");
                       }
                   },
                   [&](const command::PrintCompare&) {
                       if (!view.compare) throw std::runtime_error("print_compare: the A/B split is off");
                       compare_->update(explorer, readouts_.display_image(*renderer_a_), *renderer_b_);
                       const grading::LevelDifference& d = compare_->difference();
                       std::printf("compare differing=%llu pixels=%llu scale=%d\n",
                                   static_cast<unsigned long long>(d.differing),
                                   static_cast<unsigned long long>(d.pixels), compare_->scale_used());
                   },
                   [&](const command::SaveDifference& s) {
                       if (!view.compare) throw std::runtime_error("save_difference: the A/B split is off");
                       if (!view.compare_diff) throw std::runtime_error("save_difference: the difference pane is off");
                       compare_->update(explorer, readouts_.display_image(*renderer_a_), *renderer_b_);
                       write_png(s.path, compare_->difference_image());
                   },
                   [&](const command::PrintGrade&) {
                       if (!practice_) return;
                       std::printf("%s\n", grade_now(explorer).c_str());
                   },
                   [&](const command::Screenshot& s) {
                       // A refined display holds the render's pixels (practice's grading draws with A too).
                       const bool shows_render = !practice_ && refined_ == refined_of(explorer);
                       const auto start = std::chrono::steady_clock::now();
                       const bool drawn = take_screenshot(explorer, *renderer_a_, s.path, shows_render);
                       if (shows_render || !drawn) return;
                       displays_drawn();
                       // A's display now holds the render's pixels: alone on screen, it is the
                       // refined display, which the refine under way would only draw again
                       // (20 s for the softbox on llvmpipe, after the screenshot's own).
                       if (!practice_ && !explorer.view.compare && refine_pending_) {
                           refine_pending_ = false;
                           refine_ms_ = milliseconds_since(start);
                           refined_ = refined_of(explorer);
                       }
                   },
                   [&](const command::SaveDisplay& s) { write_png(s.path, renderer_a_->read_display()); },
               },
               request);
}

void DisplayPanes::answer_requests(Explorer& explorer) {
    std::vector<DisplayRequest> requests = std::exchange(explorer.display_requests, {});
    for (const DisplayRequest& request : requests) {
        try {
            answer(explorer, request);
        } catch (const std::exception& e) {
            explorer.session.messages.error = e.what();
            std::fprintf(stderr, "%s\n", e.what());
        }
    }
    if (!requests.empty()) std::fflush(stdout);
}

void DisplayPanes::update_read_outs(Explorer& explorer) {
    update_practice_difference(explorer);
    if (!explorer.view.compare) return;
    try {
        compare_->update(explorer, readouts_.display_image(*renderer_a_), *renderer_b_);
    } catch (const std::exception& e) {
        explorer.session.messages.error = e.what();
    }
}

// Practice mode's third pane: |your scene - reference| per channel at the
// A/B split's automatic scale (grading/ab_compare.h), as the report shows it;
// made again after a render. Not with the split on (A, B, |A - B| are there).
void DisplayPanes::update_practice_difference(Explorer& explorer) {
    if (!shows_practice_difference(explorer) || !practice_diff_stale_) return;
    practice_diff_stale_ = false;
    practice_diff_.reset();
    const Rgb8Image& mine = readouts_.display_image(*renderer_a_);
    const Rgb8Image& reference = practice_->reference_image();
    if (mine.width != reference.width || mine.height != reference.height) return;  // no pane: sizes differ
    practice_diff_scale_ = grading::auto_difference_scale(mine, reference);
    practice_diff_count_ = grading::level_difference(mine, reference, explorer.doc.scene.display.bits).differing;
    practice_diff_ = std::make_unique<PaneTexture>(gl_, grading::scaled_difference(mine, reference, practice_diff_scale_));
}

const LevelHistogram* DisplayPanes::histogram(const Explorer& explorer) {
    return &readouts_.histogram(explorer.doc.scene.display, *renderer_a_);
}

const RowProfile* DisplayPanes::profile(const Explorer& explorer) {
    return readouts_.profile(explorer.doc.scene.display, explorer.view.profile_row, *renderer_a_);
}

// B's levels on the profile's row, drawn dashed beside A's (the A/B split):
// made again after a render or for another row, not every frame.
const RowProfile* DisplayPanes::profile_of_b(const Explorer& explorer) {
    const RowProfile* a = profile(explorer);
    if (!explorer.view.compare || !a || compare_->b_display().pixels.empty()) return nullptr;
    if (!profile_b_ || profile_b_->row != a->row)
        profile_b_ = row_profile(compare_->b_display(), explorer.doc.scene.display.bits, a->row);
    return &*profile_b_;
}

std::string DisplayPanes::compare_count(const Explorer& explorer) const {
    return explorer.view.compare ? compare_->count_label() : "";
}

std::string DisplayPanes::nonfinite_line(const Explorer& explorer) {
    return nonfinite_warning(readouts_.nonfinite(explorer.doc.scene, *renderer_a_).counts);
}

int DisplayPanes::pick(const Explorer& explorer, int x, int y) { return readouts_.pick(explorer.doc.scene, x, y); }

PixelProbe DisplayPanes::probe(const Explorer& explorer, int x, int y) {
    return readouts_.probe(explorer, *renderer_a_, x, y);
}

const std::vector<int>* DisplayPanes::object_ids(const Explorer& explorer, bool allowed_to_compute) {
    return readouts_.object_ids(explorer.doc.scene, allowed_to_compute);
}

// ---- Panes -------------------------------------------------------------------------------

int DisplayPanes::pane_count(const Explorer& explorer) const {
    const View& view = explorer.view;
    return 1 + (view.compare ? 1 + (view.compare_diff ? 1 : 0) : 0) + (practice_ ? 1 : 0) +
           (shows_practice_difference(explorer) ? 1 : 0);
}

std::vector<Pane> DisplayPanes::panes(const Explorer& explorer) const {
    // A (with --assignment: the student's scene), B and |A - B| in the A/B
    // split, and the assignment's reference: one size, one magnification.
    const View& view = explorer.view;
    std::vector<Pane> panes = {{renderer_a_->display_texture(),
                                practice_ ? "your scene (Ctrl+S saves it)" : "A: the scene (saved, screenshot)"}};
    if (view.compare) panes.push_back({renderer_b_->display_texture(), "B: selected object in material B"});
    if (view.compare && view.compare_diff && compare_->texture())
        panes.push_back({compare_->texture(), compare_->scale_label(view) + ", " + compare_->pane_count_label()});
    if (practice_) panes.push_back({reference_->texture(), practice_->reference_label()});
    if (shows_practice_difference(explorer) && practice_diff_)
        panes.push_back({practice_diff_->texture(), "|yours - reference| x " + std::to_string(practice_diff_scale_) +
                                                        " (auto), " + std::to_string(practice_diff_count_) +
                                                        " px on another level"});
    return panes;
}

}  // namespace m3055::explore
