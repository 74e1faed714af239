// File > Add model... and a dropped model file (explore/add_model.h), without
// a window: the model stands on the floor in view, selected, one undo step;
// its file's materials are edited by name; a save names the file relative to
// the scene; a bad file is one line and changes nothing.
#include "explore_started.h"
#include "explore/add_model.h"
#include "explore/operations.h"
#include "geometry/mesh.h"
#include "test_paths.h"
#include "test_support.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace m3055::explore {
namespace {

namespace fs = std::filesystem;

using test::run;
using test::started;

fs::path fresh_folder(const std::string& name) {
    const fs::path dir = fs::path(::testing::TempDir()) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// The vase (scenes/models/) copied into `dir`, its .mtl beside it.
fs::path copied_vase(const fs::path& dir) {
    for (const char* name : {"vase.obj", "vase.mtl"})
        fs::copy_file(m3055::test::source_path(std::string("scenes/models/") + name), dir / name);
    return dir / "vase.obj";
}

// The lowest y of the placed model's triangles.
double lowest_y(const Object& object) {
    const geometry::Mesh mesh = geometry::make_mesh(object);
    double low = 1e300;
    for (const dvec3& p : mesh.positions) low = std::min(low, p.y);
    return low;
}

// The placed model's extent in x.
std::pair<double, double> x_range(const Object& object) {
    const geometry::Mesh mesh = geometry::make_mesh(object);
    double low = 1e300, high = -1e300;
    for (const dvec3& p : mesh.positions) low = std::min(low, p.x), high = std::max(high, p.x);
    return {low, high};
}

TEST(ExploreAddModel, StandsOnTheFloorSelectedAsOneUndoStep) {
    const fs::path dir = fresh_folder("explore_add_model_floor");
    const fs::path vase = copied_vase(dir);
    Explorer explorer = started();
    ASSERT_TRUE(run(explorer, command::AddObject{Shape::plane}));  // a floor under the sphere: y = -1
    commit_edits(explorer);
    const double floor = explorer.doc.scene.objects.back().center.y;
    ASSERT_LT(floor, -0.5);
    const std::size_t before = explorer.doc.scene.objects.size();
    ASSERT_TRUE(run(explorer, command::AddModel{vase.string()})) << explorer.session.messages.error;
    commit_edits(explorer);
    ASSERT_EQ(explorer.doc.scene.objects.size(), before + 1);
    const Object& added = explorer.doc.scene.objects.back();
    EXPECT_EQ(added.shape, Shape::mesh);
    EXPECT_EQ(explorer.view.selected_object, int(before));
    EXPECT_NEAR(lowest_y(added), floor, 1e-4) << "its bottom on the floor plane";
    EXPECT_GT(added.size, 0.3);
    EXPECT_EQ(explorer.doc.history.undo_label(), "add model vase.obj");
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_EQ(explorer.doc.scene.objects.size(), before) << "one undo step removes it";
    explorer.view.selected_object = 0;
    ASSERT_TRUE(run(explorer, command::Redo{}));
    EXPECT_EQ(explorer.doc.scene.objects.size(), before + 1);
    EXPECT_EQ(explorer.view.selected_object, int(before)) << "redone, it is selected again";
}

TEST(ExploreAddModel, WithoutAPlaneTheFloorIsYZeroAndItOverlapsNothing) {
    const fs::path dir = fresh_folder("explore_add_model_no_plane");
    Explorer explorer = started();  // the spec example: one sphere at the origin, no plane
    ASSERT_TRUE(run(explorer, command::AddModel{copied_vase(dir).string()})) << explorer.session.messages.error;
    const Object& sphere = explorer.doc.scene.objects.front();
    const Object& added = explorer.doc.scene.objects.back();
    EXPECT_NEAR(lowest_y(added), 0.0, 1e-4);
    const auto [low_x, high_x] = x_range(added);
    EXPECT_TRUE(low_x > sphere.center.x + sphere.radius || high_x < sphere.center.x - sphere.radius)
        << "beside the sphere, not in it: x in [" << low_x << ", " << high_x << "]";
}

// The vase scene: its vase fills the view; a second one stands beside it, in view, not inside it.
TEST(ExploreAddModel, BesideAModelThatFillsTheView) {
    const fs::path dir = fresh_folder("explore_add_model_beside");
    const fs::path vase = copied_vase(dir);
    fs::copy_file(m3055::test::source_path("scenes/models/vase.json"), dir / "vase.json");
    Explorer explorer = started();
    ASSERT_TRUE(run(explorer, command::LoadScene{(dir / "vase.json").string()})) << explorer.session.messages.load_error;
    ASSERT_TRUE(run(explorer, command::AddModel{vase.string()})) << explorer.session.messages.error;
    const Object& first = explorer.doc.scene.objects[1];
    const Object& added = explorer.doc.scene.objects[2];
    const auto [first_low, first_high] = x_range(first);
    const auto [low, high] = x_range(added);
    EXPECT_TRUE(low >= first_high || high <= first_low) << "[" << low << ", " << high << "] beside [" << first_low
                                                          << ", " << first_high << "]";
    EXPECT_NEAR(lowest_y(added), -1.0, 1e-4) << "on the floor plane";
}

// The three-point floor scene (a turned cube, a cylinder, a torus, spheres): the
// vase stands clear of every one of them, not inside the turned cube.
TEST(ExploreAddModel, ClearOfEveryObjectOfTheThreePointFloor) {
    const fs::path dir = fresh_folder("explore_add_model_three_point");
    const fs::path vase = copied_vase(dir);
    Explorer explorer = started();
    ASSERT_TRUE(run(explorer, command::LoadScene{m3055::test::source_path("scenes/three_point_floor.json")}))
        << explorer.session.messages.load_error;
    ASSERT_TRUE(run(explorer, command::AddModel{vase.string()})) << explorer.session.messages.error;
    const std::vector<Object>& objects = explorer.doc.scene.objects;
    const auto box = [](const Object& o) {
        if (o.shape == Shape::sphere) return std::make_pair(o.center - dvec3(o.radius), o.center + dvec3(o.radius));
        dvec3 lo(1e300), hi(-1e300);
        for (const dvec3& p : geometry::make_mesh(o).positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        return std::make_pair(lo, hi);
    };
    const auto [lo, hi] = box(objects.back());
    for (std::size_t i = 0; i + 1 < objects.size(); ++i) {
        if (objects[i].shape == Shape::plane) continue;
        const auto [other_lo, other_hi] = box(objects[i]);
        const bool apart = lo.x >= other_hi.x || hi.x <= other_lo.x || lo.y >= other_hi.y || hi.y <= other_lo.y ||
                           lo.z >= other_hi.z || hi.z <= other_lo.z;
        EXPECT_TRUE(apart) << "the vase's box meets object " << i << "'s";
    }
}

TEST(ExploreAddModel, TheFilesMaterialsAreEditedByName) {
    const fs::path dir = fresh_folder("explore_add_model_materials");
    Explorer explorer = started();
    ASSERT_TRUE(run(explorer, command::AddModel{copied_vase(dir).string()}));
    const int index = explorer.view.selected_object;
    const Object& added = explorer.doc.scene.objects[std::size_t(index)];
    ASSERT_EQ(added.groups.size(), 2u);
    EXPECT_EQ(added.groups[0].name, "glaze");
    EXPECT_EQ(added.groups[1].name, "rim");
    explorer.view.selected_group = 1;
    EXPECT_EQ(selected_group(explorer), 1);
    Material rim = *selected_material(explorer);
    EXPECT_EQ(rim.number("shininess"), 200.0) << "the rim's own Ns";
    rim.set_number("shininess", 300.0);
    ASSERT_TRUE(run(explorer, command::SetMaterial{index, rim, "", selected_group(explorer)}));
    commit_edits(explorer);
    const Object& edited = explorer.doc.scene.objects[std::size_t(index)];
    EXPECT_EQ(edited.groups[1].material.number("shininess"), 300.0);
    EXPECT_TRUE(edited.groups[1].overridden);
    EXPECT_EQ(edited.groups[0].material.number("shininess"), 60.0) << "the glaze untouched";
    EXPECT_EQ(explorer.doc.history.undo_label(), "objects[1].materials.rim.shininess 200 -> 300");
}

TEST(ExploreAddModel, SavingNamesTheFileRelativeToTheScene) {
    const fs::path dir = fresh_folder("explore_add_model_save");
    Explorer explorer = started();
    ASSERT_TRUE(run(explorer, command::AddModel{copied_vase(dir).string()}));
    explorer.view.selected_group = 1;
    Material rim = *selected_material(explorer);
    rim.set_number("shininess", 300.0);
    ASSERT_TRUE(run(explorer, command::SetMaterial{explorer.view.selected_object, rim, "", 1}));
    const fs::path scene = dir / "with_vase.json";
    ASSERT_TRUE(run(explorer, command::SaveTo{scene.string()})) << explorer.session.messages.error;
    std::ifstream in(scene);
    const nlohmann::json saved = nlohmann::json::parse(in);
    const nlohmann::json& mesh = saved["objects"].back();
    EXPECT_EQ(mesh["file"], "vase.obj");
    EXPECT_EQ(mesh["materials"]["rim"]["shininess"], 300.0);
    EXPECT_FALSE(mesh["materials"].contains("glaze")) << "only the overrides";

    Explorer loaded = started();
    ASSERT_TRUE(run(loaded, command::LoadScene{scene.string()})) << loaded.session.messages.load_error;
    EXPECT_EQ(loaded.doc.scene.objects.back().groups[1].material.number("shininess"), 300.0);
}

TEST(ExploreAddModel, ABadFileIsOneLineAndChangesNothing) {
    const fs::path dir = fresh_folder("explore_add_model_bad");
    {
        std::ofstream out(dir / "broken.obj");
        out << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n";
    }
    Explorer explorer = started();
    const std::size_t before = explorer.doc.scene.objects.size();
    const auto revision = explorer.doc.revision;
    EXPECT_FALSE(run(explorer, command::AddModel{(dir / "broken.obj").string(), true}));
    EXPECT_EQ(explorer.doc.scene.objects.size(), before);
    EXPECT_EQ(explorer.doc.revision, revision);
    const std::string& error = explorer.session.messages.load_error;
    EXPECT_NE(error.find("broken.obj"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_EQ(error.find("objects[0]"), std::string::npos) << "not the place in a scene the user never wrote: " << error;
    EXPECT_EQ(explorer.view.dialog, Dialog::load_error) << "a drop shows it in a dialog";
}

TEST(ExploreAddModel, ADropAddsAModelOpensABrdfAndLoadsAScene) {
    EXPECT_TRUE(std::holds_alternative<command::AddModel>(dropped_file_command("/x/Model.GLB")));
    EXPECT_TRUE(std::holds_alternative<command::AddModel>(dropped_file_command("a.gltf")));
    EXPECT_TRUE(std::holds_alternative<command::AddModel>(dropped_file_command("a.obj")));
    EXPECT_TRUE(std::holds_alternative<command::OpenBrdf>(dropped_file_command("a.brdf")));
    EXPECT_TRUE(std::holds_alternative<command::LoadScene>(dropped_file_command("a.json")));
    const std::vector<Command> together = dropped_files_commands({"/d/vase.mtl", "/d/vase.obj"});
    ASSERT_EQ(together.size(), 1u) << "the .mtl dropped with its model is the model's";
    EXPECT_TRUE(std::holds_alternative<command::AddModel>(together[0]));
    EXPECT_EQ(dropped_files_commands({"/d/vase.mtl"}).size(), 1u) << "alone, it is tried as a scene (and refused)";
}

}  // namespace
}  // namespace m3055::explore
