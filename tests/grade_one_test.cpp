// grading::grade_one with a renderer the caller owns, as the explorer would
// call it: the same score and reasons `m3055 grade` writes for that student
// (it runs grade_one too), and the render left for the caller.
#include "gl/context.h"
#include "grading/grade.h"
#include "grading/grade_outputs.h"
#include "frame/renderer.h"
#include "scene/load.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace m3055 {
namespace {

TEST(GradeOne, ScoresAsGradeDoesWithTheCallersRenderer) {
    const auto context = HeadlessContext::create(Backend::automatic);
    Renderer renderer(context->gl());
    const std::string folder = test::source_path("assignments/three-point");
    const grading::Assignment assignment = grading::load_assignment(folder + "/assignment.json");
    const grading::LevelImage reference = grading::load_reference(assignment, LoadContext::trusted(), &renderer);
    EXPECT_EQ(reference.width, 512);
    EXPECT_EQ(reference.bits, 5);

    test::TempDir out;
    ASSERT_EQ(test::run_m3055({"grade", folder + "/assignment.json", folder + "/submissions", "--out", out.path()})
                  .exit_code,
              0);
    const nlohmann::json grades = nlohmann::json::parse(test::read_text(out.file("grades.json")));
    for (const nlohmann::json& student : grades["students"]) {
        if (!student["broken"].get<std::string>().empty()) continue;
        const std::string name = student["student"];
        const std::string path = folder + "/submissions/" + (name == "carol" ? "carol/scene.json" : name + ".json");
        grading::LevelImage render;
        grading::Grade grade =
            grading::grade_one(assignment, load_scene_file(path, LoadContext::trusted()), renderer, reference, &render);
        grade.student = name;
        nlohmann::json mine = grading::grade_json(grade, name);
        // The screenshot is grade's business (a file beside the scene), not grade_one's.
        mine["screenshot"] = student["screenshot"];
        EXPECT_EQ(mine["score"], student["score"]) << name;
        EXPECT_EQ(mine["checks"], student["checks"]) << name;
        EXPECT_EQ(mine["comparison"], student["comparison"]) << name;
        // The render is the one grade wrote as students/NAME.png.
        const std::vector<std::uint8_t> png = encode_png(grading::display_of(render));
        EXPECT_EQ(test::read_text(out.file("students/" + name + ".png")), std::string(png.begin(), png.end())) << name;
    }
}

}  // namespace
}  // namespace m3055
