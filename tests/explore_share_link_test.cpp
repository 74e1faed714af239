// The page's share link (explore/share_link.h): every figure preset survives
// the round trip exactly, a scene with a .brdf file travels with the file, and
// a damaged or hostile link is one clear error.
#include "explore/figure_scenes.h"
#include "explore/share_link.h"
#include "scene/load.h"
#include "test_support.h"

#include "model_writer.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace m3055::explore {
namespace {

TEST(ShareLink, Base64MatchesRfc4648TestVectors) {
    EXPECT_EQ(base64_encode(""), "");
    EXPECT_EQ(base64_encode("f"), "Zg==");
    EXPECT_EQ(base64_encode("fo"), "Zm8=");
    EXPECT_EQ(base64_encode("foo"), "Zm9v");
    EXPECT_EQ(base64_encode("foobar"), "Zm9vYmFy");
    EXPECT_EQ(base64url_encode("fo"), "Zm8");  // no padding in links
    EXPECT_EQ(base64url_encode("\xfb\xff"), "-_8");
    EXPECT_EQ(base64url_decode("-_8"), "\xfb\xff");
    EXPECT_EQ(base64url_decode("Zm9vYmFy"), "foobar");
}

TEST(ShareLink, EveryFigurePresetComesBackAsTheSameScene) {
    for (const FigureScene& figure : figure_scenes()) {
        SCOPED_TRACE(figure.name);
        const Scene scene = scene_from_json(nlohmann::json::parse(figure.json), figure.name, LoadContext::trusted());
        const std::string token = share_token(scene);
        EXPECT_EQ(token.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_"),
                  std::string::npos);
        const Scene back = scene_from_json(nlohmann::json::parse(unpack_share_token(token).scene_text), "link",
                                           LoadContext::trusted());
        EXPECT_EQ(scene_to_json(back, PathWriting::absolute()), scene_to_json(scene, PathWriting::absolute()));
    }
}

TEST(ShareLink, ADamagedLinkIsOneClearError) {
    const std::string token =
        share_token(scene_from_json(nlohmann::json::parse(figure_scenes().front().json), "x", LoadContext::trusted()));
    EXPECT_THROW(unpack_share_token(token.substr(0, token.size() / 2)), std::runtime_error);
    EXPECT_THROW(unpack_share_token("abc$def"), std::runtime_error);
    EXPECT_THROW(unpack_share_token("bm90IHpsaWI"), std::runtime_error);  // "not zlib"
    try {
        unpack_share_token("abc$def");
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("share link: ", 0), 0u) << e.what();
    }
}

TEST(ShareLink, ALinkThatUnpacksPastTheLimitIsRefused) {
    const std::string zeros(kMaxSharedSceneBytes + 1, ' ');
    uLongf size = compressBound(uLong(zeros.size()));
    std::vector<Bytef> packed(size);
    ASSERT_EQ(compress2(packed.data(), &size, reinterpret_cast<const Bytef*>(zeros.data()), uLong(zeros.size()), 9), Z_OK);
    const std::string token = base64url_encode(std::string(reinterpret_cast<const char*>(packed.data()), size));
    EXPECT_LT(token.size(), 20000u);  // a short link ...
    EXPECT_THROW(unpack_share_token(token), std::runtime_error);  // ... refused, not unpacked
}

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

fs::path fresh_folder(const std::string& name) {
    const fs::path dir = fs::path(::testing::TempDir()) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string token_of_text(const std::string& text) {
    uLongf size = compressBound(uLong(text.size()));
    std::vector<Bytef> packed(size);
    EXPECT_EQ(compress2(packed.data(), &size, reinterpret_cast<const Bytef*>(text.data()), uLong(text.size()), 9), Z_OK);
    return base64url_encode(std::string(reinterpret_cast<const char*>(packed.data()), size));
}

std::string refusal(const std::string& token) {
    try {
        unpack_share_token(token);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

// A scene whose material is a .brdf file (in a subfolder, too)
// travels with the file; unpacked into another folder it loads as the same scene.
TEST(ShareLink, ASceneWithBrdfFilesCarriesThemAndComesBackTheSame) {
    const fs::path from = fresh_folder("share_link_from"), to = fresh_folder("share_link_to");
    const std::string lambert = read(m3055::test::source_path("tests/data/brdf/lambert.brdf"));
    ASSERT_FALSE(lambert.empty());
    fs::create_directories(from / "mine");
    { std::ofstream(from / "mine" / "shiny.brdf", std::ios::binary) << lambert << "\n# mine\n"; }
    { std::ofstream(from / "lambert.brdf", std::ios::binary) << lambert; }
    nlohmann::json doc = nlohmann::json::parse(figure_scenes().front().json);
    nlohmann::json first = doc["objects"][0], second = first;
    first["material"] = {{"model", "brdf"}, {"file", "lambert.brdf"}};
    second["material"] = {{"model", "brdf"}, {"file", "mine/shiny.brdf"}};
    doc["objects"] = {first, second, first};
    { std::ofstream(from / "scene.json") << doc.dump(2); }
    const Scene scene = load_scene_file((from / "scene.json").string(), LoadContext::trusted());

    const SharedScene shared = unpack_share_token(share_token(scene, from.string()));
    ASSERT_EQ(shared.files.size(), 2u) << "each file once";
    EXPECT_EQ(shared.files[0].name, "lambert.brdf");
    EXPECT_EQ(shared.files[0].text, lambert);
    EXPECT_EQ(shared.files[1].name, "mine/shiny.brdf");
    EXPECT_EQ(shared.files[1].text, lambert + "\n# mine\n");
    const nlohmann::json back_doc = nlohmann::json::parse(shared.scene_text);
    EXPECT_EQ(back_doc["objects"][1]["material"]["file"], "mine/shiny.brdf");

    for (const SharedFile& file : shared.files) {
        fs::create_directories((to / file.name).parent_path());
        std::ofstream(to / file.name, std::ios::binary) << file.text;
    }
    { std::ofstream(to / "scene.json") << shared.scene_text; }
    const Scene back = load_scene_file((to / "scene.json").string(), LoadContext::trusted());
    EXPECT_EQ(scene_to_json(back, PathWriting::relative_to_folder(to.string())),
              scene_to_json(scene, PathWriting::relative_to_folder(from.string())));
}

TEST(ShareLink, ABrdfFileOutsideTheFolderCannotBeShared) {
    const fs::path dir = fresh_folder("share_link_outside");
    { std::ofstream(dir / "lambert.brdf", std::ios::binary) << read(m3055::test::source_path("tests/data/brdf/lambert.brdf")); }
    nlohmann::json doc = nlohmann::json::parse(figure_scenes().front().json);
    doc["objects"][0]["material"] = {{"model", "brdf"}, {"file", "lambert.brdf"}};
    { std::ofstream(dir / "scene.json") << doc.dump(2); }
    const Scene scene = load_scene_file((dir / "scene.json").string(), LoadContext::trusted());
    EXPECT_THROW(share_token(scene, (dir / "elsewhere").string()), std::runtime_error);
    EXPECT_THROW(share_token(scene), std::runtime_error) << "no folder: absolute paths, nothing to carry";
}

// A scene with a mesh from a model file travels with it and the files it
// names (the vase's .mtl); unpacked into another folder it loads as the same scene.
TEST(ShareLink, ASceneWithAModelFileCarriesItAndItsMtl) {
    const fs::path from = fresh_folder("share_link_model_from"), to = fresh_folder("share_link_model_to");
    fs::create_directories(from / "meshes");
    for (const char* name : {"vase.obj", "vase.mtl"})
        fs::copy_file(m3055::test::source_path(std::string("scenes/models/") + name), from / "meshes" / name);
    nlohmann::json doc = nlohmann::json::parse(figure_scenes().front().json);
    doc["objects"].push_back({{"shape", "mesh"}, {"file", "meshes/vase.obj"}, {"center", {0, 0, 0}}, {"size", 1},
                              {"materials", {{"rim", {{"shininess", 300}}}}}});
    { std::ofstream(from / "scene.json") << doc.dump(2); }
    const Scene scene = load_scene_file((from / "scene.json").string(), LoadContext::trusted());

    const SharedScene shared = unpack_share_token(share_token(scene, from.string()));
    ASSERT_EQ(shared.files.size(), 2u);
    EXPECT_EQ(shared.files[0].name, "meshes/vase.mtl");
    EXPECT_EQ(shared.files[1].name, "meshes/vase.obj");
    EXPECT_EQ(shared.files[1].text, read((from / "meshes" / "vase.obj").string()));
    for (const SharedFile& file : shared.files) {
        fs::create_directories((to / file.name).parent_path());
        std::ofstream(to / file.name, std::ios::binary) << file.text;
    }
    { std::ofstream(to / "scene.json") << shared.scene_text; }
    const Scene back = load_scene_file((to / "scene.json").string(), LoadContext::trusted());
    EXPECT_EQ(scene_to_json(back, PathWriting::relative_to_folder(to.string())),
              scene_to_json(scene, PathWriting::relative_to_folder(from.string())));
}

// A glTF with its buffer in a side .bin (binary: base64url in the bundle) travels byte for byte.
TEST(ShareLink, AGltfAndItsBinaryBufferTravelByteForByte) {
    const fs::path dir = fresh_folder("share_link_gltf");
    test::write_gltf(test::integer_uv_sphere(8, 4, 10.0, 10.0), (dir / "ball.gltf").string(), test::GltfBuffer::side_file);
    nlohmann::json doc = nlohmann::json::parse(figure_scenes().front().json);
    doc["objects"].push_back({{"shape", "mesh"}, {"file", "ball.gltf"}, {"center", {0, 0, 0}}, {"size", 1}});
    { std::ofstream(dir / "scene.json") << doc.dump(2); }
    const Scene scene = load_scene_file((dir / "scene.json").string(), LoadContext::trusted());
    const SharedScene shared = unpack_share_token(share_token(scene, dir.string()));
    ASSERT_EQ(shared.files.size(), 2u);
    for (const SharedFile& file : shared.files) EXPECT_EQ(file.text, read((dir / file.name).string())) << file.name;
    EXPECT_NE(shared.files[0].name.find(".bin"), std::string::npos) << shared.files[0].name;
}

// A model file outside the page's folder cannot travel: one line naming it.
TEST(ShareLink, AModelFileOutsideTheFolderIsRefusedWithALineNamingIt) {
    const fs::path dir = fresh_folder("share_link_model");
    { std::ofstream(dir / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"; }
    nlohmann::json doc = nlohmann::json::parse(figure_scenes().front().json);
    doc["objects"].push_back({{"shape", "mesh"}, {"file", "tri.obj"}, {"center", {0, 0, 0}}, {"size", 1}});
    { std::ofstream(dir / "scene.json") << doc.dump(2); }
    const Scene scene = load_scene_file((dir / "scene.json").string(), LoadContext::trusted());
    try {
        share_token(scene, (dir / "elsewhere").string());
        ADD_FAILURE() << "a model file outside the folder made a link";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("model file"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("tri.obj"), std::string::npos) << e.what();
    }
}

// A hostile or damaged bundle: one line, and no file name that leaves the folder.
TEST(ShareLink, ABundleWithABadPartIsRefusedWithOneLine) {
    const nlohmann::json scene = nlohmann::json::parse(figure_scenes().front().json);
    auto bundle = [&](const nlohmann::json& files) {
        return token_of_text(nlohmann::json{{"m3055_share", 1}, {"scene", scene}, {"brdf_files", files}}.dump());
    };
    EXPECT_EQ(refusal(bundle({{"ok.brdf", "x"}})), "");
    for (const char* name : {"../up.brdf", "/abs.brdf", "a/../b.brdf", "not-brdf.json", "a//b.brdf", "a\\b.brdf", ""}) {
        SCOPED_TRACE(name);
        const std::string why = refusal(bundle({{name, "x"}}));
        EXPECT_EQ(why.rfind("share link: brdf_files: ", 0), 0u) << why;
        EXPECT_EQ(why.find('\n'), std::string::npos);
    }
    EXPECT_EQ(refusal(bundle({{"ok.brdf", 3}})), "share link: brdf_files: \"ok.brdf\" is not text");
    EXPECT_EQ(refusal(token_of_text(R"({"m3055_share": 1, "scene": []})")).rfind("share link: not a scene with its", 0), 0u);
    const std::string good = bundle({{"ok.brdf", "x"}});
    EXPECT_EQ(refusal(good.substr(0, good.size() - 3)).rfind("share link: ", 0), 0u) << "cut short";
}

}  // namespace
}  // namespace m3055::explore
