// scene/referenced_file.h: a file a scene names (a .brdf material's "file")
// is found from the scene file's folder inside LoadContext::folder and named
// relative to it, a confinement refuses every way out of its folder before
// the file is opened, and a written scene names it absolutely or relative to
// a folder.
#include "scene/load.h"
#include "scene/presets.h"
#include "scene/referenced_file.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace m3055 {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

// The spec's example with its first object's material from `brdf_file`.
std::string scene_naming(const std::string& brdf_file) {
    nlohmann::json doc = scene_to_json(default_scene(), PathWriting::absolute());
    doc["objects"][0]["material"] = {{"model", "brdf"}, {"file", brdf_file}};
    return doc.dump(2);
}

void write_brdf(const std::string& path) {
    test::write_text(path, test::read_text(test::source_path("tests/data/brdf/lambert.brdf")));
}

// The message load_scene_file gives, or "" when the scene loads.
std::string load_error(const std::string& path, const LoadContext& context) {
    try {
        load_scene_file(path, context);
        return "";
    } catch (const SceneError& e) {
        return e.what();
    }
}

// A class folder: alice/scene.json naming `brdf_file`, and outside.brdf beside alice/.
struct ClassFolder {
    TempDir dir;
    explicit ClassFolder(const std::string& brdf_file) {
        fs::create_directories(dir.file("alice"));
        test::write_text(dir.file("alice/scene.json"), scene_naming(brdf_file));
        write_brdf(dir.file("outside.brdf"));
    }
    LoadContext confined_to(const std::string& root) const {
        LoadContext context = LoadContext::trusted();
        context.folder = dir.path();
        context.confinement = Confinement{root, "one file has no folder"};
        return context;
    }
};

TEST(ReferencedFile, IsReadFromTheContextsFolderAndNamedRelativeToIt) {
    ClassFolder folder("shiny.brdf");
    ASSERT_FALSE(fs::exists("alice/scene.json")) << "the test needs a working folder without alice/";
    LoadContext context = LoadContext::trusted();
    context.folder = folder.dir.path();
    const std::string missing = load_error("alice/scene.json", context);
    EXPECT_EQ(missing.rfind("alice/scene.json: objects[0].material.file: alice/shiny.brdf: cannot read file: ", 0), 0u)
        << missing;
    write_brdf(folder.dir.file("alice/shiny.brdf"));
    EXPECT_EQ(load_error("alice/scene.json", context), "");
    EXPECT_EQ(load_error("alice/nothing.json", context).rfind("alice/nothing.json: cannot read file: ", 0), 0u)
        << "the scene file itself is named as given too";
}

TEST(ReferencedFile, AConfinementRefusesEveryWayOutOfItsFolder) {
    const std::string field = "alice/scene.json: objects[0].material.file: ";
    EXPECT_EQ(load_error("alice/scene.json", ClassFolder("../outside.brdf").confined_to("alice")),
              field + "must be a path inside the submission's folder, without \"..\"");
    ClassFolder absolute("");
    test::write_text(absolute.dir.file("alice/scene.json"), scene_naming(absolute.dir.file("outside.brdf")));
    EXPECT_EQ(load_error("alice/scene.json", absolute.confined_to("alice")),
              field + "must be a path inside the submission's folder, not an absolute path");
    ClassFolder linked("link.brdf");
    fs::create_symlink("../outside.brdf", linked.dir.file("alice/link.brdf"));
    EXPECT_EQ(load_error("alice/scene.json", linked.confined_to("alice")),
              field + "leads out of the submission's folder (a symbolic link): a .brdf file must be in it");
    EXPECT_EQ(load_error("alice/scene.json", linked.confined_to("")),
              field + "a .brdf file is not accepted here: one file has no folder");
    EXPECT_EQ(load_error("alice/scene.json", linked.confined_to(".")), "") << "the link stays inside the class folder";
}

TEST(ReferencedFile, ALinkInsideTheFolderIsFollowed) {
    ClassFolder folder("link.brdf");
    write_brdf(folder.dir.file("alice/real.brdf"));
    fs::create_symlink("real.brdf", folder.dir.file("alice/link.brdf"));
    EXPECT_EQ(load_error("alice/scene.json", folder.confined_to("alice")), "");
}

TEST(ReferencedFile, IsWrittenAbsolutelyOrRelativeToAFolder) {
    TempDir dir;
    const std::string inside = dir.file("mine/shiny.brdf");
    EXPECT_EQ(scene_json::written_path(inside, PathWriting::absolute()), inside);
    EXPECT_EQ(scene_json::written_path(inside, PathWriting::relative_to_folder(dir.path())), "mine/shiny.brdf");
    EXPECT_EQ(scene_json::written_path(inside, PathWriting::relative_to_folder(dir.file("other"))),
              fs::path(inside).lexically_normal().string())
        << "a file outside the folder stays absolute";
    EXPECT_EQ(scene_json::written_path("x.brdf", PathWriting::absolute()), fs::absolute("x.brdf").string());
}

}  // namespace
}  // namespace m3055
