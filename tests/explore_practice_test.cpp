// Practice mode's live grade (explore/practice.h), without a window or GL:
// the grade goes stale on an edit and is recomputed once the edit has
// settled, and a scene `grade` refuses scores what `grade` gives it.
#include "explore/practice.h"
#include "test_paths.h"

#include "brdf_file/brdf_model.h"
#include "image/image.h"
#include "scene/json_brdf.h"
#include "scene/presets.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace m3055::explore {
namespace {

// An assignment graded against a small PNG (an image reference needs no renderer).
grading::Assignment png_assignment() {
    const std::string png = ::testing::TempDir() + "explore_practice_reference.png";
    Rgb8Image image;
    image.width = 4;
    image.height = 2;
    image.pixels.assign(4 * 2 * 3, 128);
    write_png(png, image);
    grading::Assignment a;
    a.path = ::testing::TempDir() + "assignment.json";
    a.title = "Fig. 5 again";
    a.reference = png;
    a.image_points = 60;
    a.pass_score = 30;
    return a;
}

Scene scene_with_brdf_on_object(int index) {
    Scene scene = default_scene();
    while (int(scene.objects.size()) <= index) scene.objects.push_back(scene.objects[0]);
    const BrdfModel& model = load_brdf_model(std::string(M3055_SOURCE_DIR) + "/tests/data/brdf/blinn_phong.brdf");
    scene.objects[std::size_t(index)].material = Material(*model.spec);
    return scene;
}

TEST(ExplorePractice, StartsPendingWithTheAssignmentsTitleReferenceAndMaximum) {
    const Practice practice(png_assignment(), nullptr, false);
    const PracticeStatus status = practice.start_status();
    EXPECT_TRUE(status.active);
    EXPECT_TRUE(status.pending);
    EXPECT_FALSE(status.graded);
    EXPECT_EQ(status.title, "Fig. 5 again");
    EXPECT_EQ(status.reference, "explore_practice_reference.png");
    EXPECT_EQ(status.max, 60);
    EXPECT_EQ(practice.reference_image().width, 4);
    EXPECT_EQ(practice.reference_label(), "reference (explore_practice_reference.png)");
}

TEST(ExplorePractice, AnEditMakesTheGradeStaleAndItIsRecomputedOnlyOnceTheEditSettled) {
    Practice practice(png_assignment(), nullptr, false);
    PracticeStatus status = practice.start_status();
    status.pending = false;  // as after a grade
    EXPECT_LT(practice.settle_left(status, 10.0), 0.0) << "nothing to recompute";
    practice.scene_changed(status, 10.0);
    EXPECT_TRUE(status.pending);
    EXPECT_NEAR(practice.settle_left(status, 10.1), kSettleSeconds - 0.1, 1e-9);
    practice.scene_changed(status, 10.2);  // the slider moved again: the wait starts again
    EXPECT_NEAR(practice.settle_left(status, 10.3), kSettleSeconds - 0.1, 1e-9);
    EXPECT_EQ(practice.settle_left(status, 10.2 + kSettleSeconds), 0.0);
    EXPECT_EQ(practice.settle_left(status, 99.0), 0.0);
}

TEST(ExplorePractice, ABrdfMaterialScoresZeroWithGradesReasonUnlessAllowed) {
    const Scene scene = scene_with_brdf_on_object(1);
    const Practice strict(png_assignment(), nullptr, false);
    const std::optional<grading::Grade> refused = strict.refusal(scene, "/class/pat/scene.json");
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->score, 0);
    EXPECT_FALSE(refused->passed);
    const std::vector<std::string> reasons = refused->reasons();
    ASSERT_FALSE(reasons.empty());
    EXPECT_NE(reasons.back().find("objects[1].material.file: " + scene_json::brdf_not_allowed_reason()),
              std::string::npos)
        << reasons.back();
    const Practice allowing(png_assignment(), nullptr, true);
    EXPECT_FALSE(allowing.refusal(scene, "/class/pat/scene.json")) << "explore --allow-brdf grades it as grade --allow-brdf";
    EXPECT_FALSE(strict.refusal(default_scene(), "")) << "built-in models are graded";
}

// grade --allow-brdf reads a .brdf only in a folder submission NAME/scene.json:
// a single NAME.json (or a scene not saved yet) with one is refused, and the
// live grade says so with grade's reason.
TEST(ExplorePractice, ABrdfMaterialInASingleFileSceneIsRefusedAsGradeRefusesIt) {
    const Scene scene = scene_with_brdf_on_object(1);
    const Practice allowing(png_assignment(), nullptr, true);
    for (const std::string file : {"/class/submission.json", "", "/class/pat/scene.json.txt"}) {
        const std::optional<grading::Grade> refused = allowing.refusal(scene, file);
        ASSERT_TRUE(refused) << file;
        EXPECT_EQ(refused->score, 0);
        const std::vector<std::string> reasons = refused->reasons();
        ASSERT_FALSE(reasons.empty());
        EXPECT_NE(reasons.back().find("objects[1].material.file: a .brdf file is not accepted here: a submission that "
                                      "names a file (a .brdf material, a model) is a folder NAME/ holding scene.json "
                                      "and the file"),
                  std::string::npos)
            << reasons.back();
    }
    EXPECT_FALSE(allowing.refusal(default_scene(), "/class/submission.json")) << "no .brdf: a single file is fine";
}

// grade reads a model file only in a folder submission too: the live grade of
// a single-file scene with a mesh from a file is grade's refusal.
TEST(ExplorePractice, AModelFileInASingleFileSceneIsRefusedAsGradeRefusesIt) {
    Scene scene = default_scene();
    scene.objects.push_back(scene.objects[0]);
    scene.objects[1].shape = Shape::mesh;
    scene.objects[1].file = "vase.obj";
    const Practice practice(png_assignment(), nullptr, false);
    for (const std::string file : {"/class/submission.json", ""}) {
        const std::optional<grading::Grade> refused = practice.refusal(scene, file);
        ASSERT_TRUE(refused) << file;
        EXPECT_EQ(refused->score, 0);
        ASSERT_FALSE(refused->reasons().empty());
        EXPECT_EQ(refused->reasons().back(),
                  "objects[1].file: a model file is not accepted here: a submission that names a file (a .brdf "
                  "material, a model) is a folder NAME/ holding scene.json and the file");
    }
    EXPECT_FALSE(practice.refusal(scene, "/class/pat/scene.json")) << "a folder submission's model is graded";
    EXPECT_FALSE(practice.refusal(default_scene(), "/class/submission.json")) << "no model file: a single file is fine";
}

TEST(ExplorePractice, GradeLineIsWhatPrintGradePrints) {
    PracticeStatus status;
    status.score = 30;
    status.max = 60;
    status.passed = true;
    status.reasons = {"image: 12 pixels off", "light_count: 3 lights"};
    EXPECT_EQ(grade_line(status), "grade score=30 max=60 passed=yes\timage: 12 pixels off\tlight_count: 3 lights");
}

}  // namespace
}  // namespace m3055::explore
