#include "grading/grade.h"

#include "analysis/pixel_probe.h"
#include "grading/image_input.h"
#include "io/message_text.h"
#include "scene/load.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace m3055::grading {

namespace {

// The image points earned with `off` % of the pixels off: all up to the
// allowed share; with partial credit (image_zero_percent) falling linearly
// to 0 at that share, to the hundredth of a point; otherwise none.
double image_points_earned(const Assignment& assignment, double off) {
    const double allowed = assignment.image_tolerance.fail.percent, zero = assignment.image_zero_percent;
    if (off <= allowed) return assignment.image_points;
    if (zero <= allowed || off >= zero) return 0.0;
    return std::round(assignment.image_points * (zero - off) / (zero - allowed) * 100.0) / 100.0;
}

Check image_check(const Assignment& assignment, const Comparison& c, const NonFinite& nonfinite) {
    Check check;
    check.label = "image";
    check.points = assignment.image_points;
    check.ok = c.verdict != Verdict::fail;
    const double off = 100.0 * double(c.over_fail) / double(c.pixels ? c.pixels : 1);
    check.earned = check.ok ? check.points : image_points_earned(assignment, off);
    char line[200];
    std::snprintf(line, sizeof line, "%.2f %% of pixels on the reference's level, %.2f %% more than %d off (allowed %.6g %%), max %d",
                  percent_to_two_places(c.same_pixels, c.pixels), percent_to_two_places(c.over_fail, c.pixels),
                  c.thresholds.fail.levels, c.thresholds.fail.percent, c.max_levels);
    const std::string region = assignment.image_objects_only && c.pixels > 0
                                   ? "the objects' " + std::to_string(c.pixels) + " pixels: "
                                   : std::string();
    check.reason = "image: " + region + line;
    if (nonfinite.pixels > 0) {
        // Whatever levels the display gave them, values that are not numbers
        // match nothing: the check fails, with no points, partial or not.
        check.ok = false;
        check.earned = 0;
        check.reason = "image: " + nonfinite_text(nonfinite) +
                       " in the render (a material gives values that are not numbers): no image points; " + region + line;
        return check;
    }
    if (!check.ok && assignment.image_zero_percent > 0)
        check.reason += ": " + text::format_number(check.earned) + " of " + text::format_number(check.points) +
                        " points (none at " + text::format_number(assignment.image_zero_percent) + " %)";
    return check;
}

// The pixels of `image` inside `region`, in order, as one row (the
// comparison counts and shares only them).
LevelImage in_region(const LevelImage& image, const std::vector<std::uint8_t>& region) {
    LevelImage out;
    out.bits = image.bits;
    out.height = 1;
    for (std::size_t i = 0; i < region.size(); ++i) {
        if (!region[i]) continue;
        out.levels.insert(out.levels.end(), image.levels.begin() + std::ptrdiff_t(3 * i),
                          image.levels.begin() + std::ptrdiff_t(3 * i + 3));
        if (image.has_linear())
            out.linear.insert(out.linear.end(), image.linear.begin() + std::ptrdiff_t(3 * i),
                              image.linear.begin() + std::ptrdiff_t(3 * i + 3));
    }
    out.width = int(out.levels.size() / 3);
    return out;
}

void total(Grade& grade, const Assignment& assignment) {
    grade.max = assignment.max_score();
    grade.score = 0;
    for (const Check& check : grade.checks) grade.score += check.earned;
    // To the hundredth, as every output shows it: 53.12, never 53.120000000000005.
    grade.score = std::round(grade.score * 100.0) / 100.0;
    grade.max = std::round(grade.max * 100.0) / 100.0;
    grade.passed = grade.broken.empty() && grade.score >= std::round(assignment.pass_score * 100.0) / 100.0;
}

}  // namespace

std::vector<std::string> Grade::reasons() const {
    if (!broken.empty()) return {broken};
    std::vector<std::string> out;
    for (const Check& check : checks)
        if (!check.ok) out.push_back(check.label == "image" ? check.reason : check.label + ": " + check.reason);
    if (!screenshot_ok) out.push_back(screenshot);
    return out;
}

LevelImage load_reference(const Assignment& assignment, const LoadContext& context, Renderer* renderer,
                          Rgb8Image* display) {
    if (input_kind(assignment.reference) != InputKind::scene) {
        LevelImage image = read_level_image(assignment.reference, 5);
        // A PNG is shown as it is, a PFM as the display would show it.
        if (display) *display = input_kind(assignment.reference) == InputKind::png ? read_png(assignment.reference) : display_of(image);
        return image;
    }
    const Scene scene = load_scene_file(assignment.reference, context);
    if (!renderer) throw std::logic_error("load_reference: a scene reference needs a renderer");
    renderer->set_deadline(std::nullopt);
    renderer->render(scene);
    Rgb8Image shown = renderer->read_display();
    LevelImage image = levels_from_png(shown, scene.display.bits);
    if (assignment.image_objects_only) {
        // The pixels the objects cover, as the CPU picker (the explorer's probe) sees them.
        const std::vector<int> ids = ScenePicker(scene).object_ids();
        image.region.resize(ids.size());
        for (std::size_t i = 0; i < ids.size(); ++i) image.region[i] = ids[i] >= 0 ? 1 : 0;
    }
    if (display) *display = std::move(shown);
    return image;
}

Grade grade_scene(const Assignment& assignment, const Scene& scene, const LevelImage& reference,
                  const LevelImage& render, const NonFinite& nonfinite) {
    Grade grade;
    try {
        Thresholds tolerance;
        tolerance.fail = assignment.image_tolerance.fail;
        const bool whole = std::count(reference.region.begin(), reference.region.end(), 1) == 0;
        const bool region = !whole && reference.width == render.width && reference.height == render.height &&
                            reference.bits == render.bits;
        grade.comparison = region ? compare_levels(in_region(reference, reference.region),
                                                   in_region(render, reference.region), tolerance)
                                  : compare_levels(reference, render, tolerance);
        if (region) {
            // The region's pixels were compared as one row: the display's own size is the one to report.
            grade.comparison->width = reference.width;
            grade.comparison->height = reference.height;
            grade.comparison->region = "objects";
        }
        grade.checks.push_back(image_check(assignment, *grade.comparison, nonfinite));
    } catch (const CompareError& e) {
        // A student's display of another size or depth is their mistake, not an error of the run.
        grade.checks.push_back({"image", assignment.image_points, 0.0, false, std::string("image: ") + e.what() +
                                                                         " (A the reference, B the submission)"});
    }
    const nlohmann::json document = scene_to_json(scene, PathWriting::absolute());
    for (const Rule& rule : assignment.rules) grade.checks.push_back(check_rule(rule, scene, document));
    total(grade, assignment);
    return grade;
}

Grade grade_one(const Assignment& assignment, const Scene& scene, Renderer& renderer, const LevelImage& reference,
                LevelImage* render_out, Rgb8Image* display_out) {
    renderer.render(scene);
    Rgb8Image display = renderer.read_display();
    LevelImage render = levels_from_png(display, scene.display.bits);  // the levels the display shows
    const NonFinite nonfinite = may_render_nonfinite(scene) ? count_nonfinite(renderer.read_raw()) : NonFinite{};
    Grade grade = grade_scene(assignment, scene, reference, render, nonfinite);
    if (render_out) *render_out = std::move(render);
    if (display_out) *display_out = std::move(display);
    return grade;
}

Grade broken_grade(const Assignment& assignment, const std::string& student, const std::string& reason) {
    Grade grade;
    grade.student = student;
    grade.broken = reason;
    total(grade, assignment);
    return grade;
}

void check_screenshot(Grade& grade, const LevelImage& screenshot, const LevelImage& render,
                      const std::string& screenshot_name) {
    try {
        const Comparison c = compare_levels(render, screenshot);
        grade.screenshot_ok = c.same_pixels == c.pixels;
        grade.screenshot = screenshot_name + (grade.screenshot_ok ? ": is the render of the scene"
                                                                  : ": is not the render of the scene: " +
                                                                        std::to_string(c.pixels - c.same_pixels) +
                                                                        " pixels differ");
    } catch (const CompareError& e) {
        grade.screenshot_ok = false;
        grade.screenshot = screenshot_name + ": is not the render of the scene: " + e.what() + " (A the render)";
    }
}

}  // namespace m3055::grading
