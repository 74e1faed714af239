// Meshes from model files in scenes (docs/shapes.md#meshes-from-files): OBJ,
// glTF and GLB loaded through the scene's LoadContext, placed by center,
// size and rotation_deg, their materials made models of the table per group
// and overridden by name; and untrusted files refused in one line naming the
// file and the field, without quoting their content.
#include "model_writer.h"
#include "test_support.h"
#include "untrusted_harness.h"

#include "geometry/mesh.h"
#include "model_file/model.h"
#include "model_file/model_limits.h"
#include "scene/load.h"
#include "scene/load_context.h"

#include "models/model_spec.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace m3055 {
namespace {

using nlohmann::json;
using test::TempDir;
namespace fs = std::filesystem;

// A scene of one mesh object `file` (and `extra` keys), written as DIR/scene.json.
std::string write_mesh_scene(const TempDir& dir, const std::string& file, const json& extra = json::object(),
                             bool with_material = true) {
    json object = {{"shape", "mesh"}, {"file", file}, {"center", {0, 0, 0}}, {"size", 2.0}};
    if (with_material) object["material"] = {{"model", "highlight"}, {"color", {0.8, 0.2, 0.2}}};
    for (const auto& [key, value] : extra.items()) {
        if (value.is_null()) object.erase(key);
        else object[key] = value;
    }
    const json scene = {{"display", {{"width", 64}, {"height", 40}, {"bits", 5}}},
                        {"camera",
                         {{"projection", "perspective"}, {"position", {0, 0, 6}}, {"target", {0, 0, 0}},
                          {"up", {0, 1, 0}}, {"fov_y_deg", 30}}},
                        {"lights", {{{"type", "directional"}, {"direction", {1, 1, 1}}}}},
                        {"objects", {object}}};
    const std::string path = dir.file("scene.json");
    test::write_text(path, scene.dump(2));
    return path;
}

// An axis-aligned box from lo to hi, 12 triangles, faces outward, flat normals.
geometry::Mesh box(dvec3 lo, dvec3 hi) {
    geometry::Mesh mesh = geometry::make_cube(dvec3(0.0), 2.0, dvec3(0.0));
    for (dvec3& p : mesh.positions) p = lo + (p + 1.0) * 0.5 * (hi - lo);
    return mesh;
}

Scene load(const std::string& path) { return load_scene_file(path, LoadContext::trusted()); }

// The load's one-line error.
std::string load_error(const std::string& path, const LoadContext& context = LoadContext::trusted()) {
    try {
        load_scene_file(path, context);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(loaded)";
}

TEST(ModelFile, ObjIsCentredScaledAndRotatedAsCubesAre) {
    TempDir dir;
    // A box in centimetres, off the origin: 40 x 20 x 10 around (100, 50, -30).
    test::write_obj(box({80, 40, -35}, {120, 60, -25}), dir.file("box.obj"));
    const Scene scene = load(write_mesh_scene(dir, "box.obj", {{"center", {1, 2, 3}}, {"size", 4.0}}));
    ASSERT_EQ(scene.objects.size(), 1u);
    const geometry::Mesh mesh = geometry::make_mesh(scene.objects[0]);
    EXPECT_EQ(mesh.triangles(), 12u);
    dvec3 lo(1e9), hi(-1e9);
    for (const dvec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    EXPECT_NEAR(lo.x, -1.0, 1e-12);
    EXPECT_NEAR(hi.x, 3.0, 1e-12);  // largest side 4, centred on 1
    EXPECT_NEAR(lo.y, 1.0, 1e-12);
    EXPECT_NEAR(hi.y, 3.0, 1e-12);
    EXPECT_NEAR(lo.z, 2.5, 1e-12);
    EXPECT_NEAR(hi.z, 3.5, 1e-12);

    // Rotated 90 degrees about y, as a cube: x becomes -z.
    const Scene turned =
        load(write_mesh_scene(dir, "box.obj", {{"center", {1, 2, 3}}, {"size", 4.0}, {"rotation_deg", {0, 90, 0}}}));
    const geometry::Mesh turned_mesh = geometry::make_mesh(turned.objects[0]);
    lo = dvec3(1e9), hi = dvec3(-1e9);
    for (const dvec3& p : turned_mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    EXPECT_NEAR(hi.z - lo.z, 4.0, 1e-9);
    EXPECT_NEAR(hi.x - lo.x, 1.0, 1e-9);
    // The bounding sphere holds the placed box: half its diagonal.
    EXPECT_NEAR(geometry::bounding_radius(turned.objects[0]), 0.5 * 4.0 * std::sqrt(40 * 40 + 20 * 20 + 10 * 10) / 40,
                1e-12);
}

TEST(ModelFile, ObjMaterialsBecomePhongPerGroupAndOverrideByName) {
    TempDir dir;
    geometry::Mesh mesh = box({0, 0, 0}, {1, 1, 1});
    mesh.groups.assign(mesh.triangles(), 0);
    for (std::size_t t = 6; t < mesh.triangles(); ++t) mesh.groups[t] = 1;
    test::write_obj(mesh, dir.file("two.obj"), true, "two.mtl");
    test::write_text(dir.file("two.mtl"),
                     "newmtl m0\nKd 0.5 0.25 0.125\nKs 0.2 0.2 0.2\nNs 40\n"
                     "newmtl m1\nKd 0.125 0.25 0.375\nKs 0 0 0\nNs 0\nmap_Kd wood.jpg\n");
    std::vector<std::string> notes;
    LoadContext context = LoadContext::trusted();
    context.note = [&](const std::string& line) { notes.push_back(line); };
    const std::string path = write_mesh_scene(dir, "two.obj", {{"material", nullptr}});
    const Scene scene = load_scene_file(path, context);
    const Object& object = scene.objects[0];
    ASSERT_EQ(object.groups.size(), 2u);
    EXPECT_EQ(object.groups[0].name, "m0");
    EXPECT_EQ(object.groups[0].material.model_name(), "phong");
    EXPECT_EQ(object.groups[0].material.vec3("kd"), dvec3(0.5, 0.25, 0.125));
    EXPECT_EQ(object.groups[0].material.vec3("ks"), dvec3(0.2));
    EXPECT_EQ(object.groups[0].material.number("shininess"), 40.0);
    // tinyobjloader's own decimal reading may be one unit in the last place off.
    EXPECT_LT(glm::length(object.groups[1].material.vec3("kd") - dvec3(0.125, 0.25, 0.375)), 1e-15);
    const geometry::Mesh placed = geometry::make_mesh(object);
    EXPECT_EQ(placed.groups, mesh.groups);
    EXPECT_EQ(&material_of(object, 1), &object.groups[1].material);
    // The texture is ignored with one note naming the file and the field.
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0].find(path + ": objects[0].file: "), 0u) << notes[0];
    EXPECT_NE(notes[0].find("textures are ignored"), std::string::npos);

    // "materials" overrides one by name: a parameter, or a whole material.
    const Scene changed = load(write_mesh_scene(
        dir, "two.obj",
        {{"material", nullptr},
         {"materials", {{"m0", {{"shininess", 80}}}, {"m1", {{"model", "highlight"}, {"color", {0.5, 0.5, 0.5}}, {"m", 20}}}}}}));
    EXPECT_EQ(changed.objects[0].groups[0].material.number("shininess"), 80.0);
    EXPECT_EQ(changed.objects[0].groups[0].material.vec3("kd"), dvec3(0.5, 0.25, 0.125));
    EXPECT_EQ(changed.objects[0].groups[1].material.model_name(), "highlight");
    // Written back: the file and only the overrides.
    const json written = scene_to_json(changed, PathWriting::relative_to_folder(dir.path()));
    EXPECT_EQ(written["objects"][0]["file"], "two.obj");
    EXPECT_EQ(written["objects"][0]["materials"].size(), 2u);
    EXPECT_FALSE(written["objects"][0].contains("material"));

    // A name the file lacks is refused, naming the file's materials.
    EXPECT_EQ(load_error(write_mesh_scene(dir, "two.obj", {{"material", nullptr}, {"materials", {{"oak", {{"m", 2}}}}}})),
              dir.file("scene.json") + ": objects[0].materials.oak: the model file has no material of this name "
                                       "(its materials: \"m0\", \"m1\")");

    // --set edits a file's material by its name.
    write_mesh_scene(dir, "two.obj", {{"material", nullptr}});
    const Scene set = load_scene_file(path, LoadContext::trusted(),
                                      {parse_override("objects[0].materials.m1.kd=[0.9,0.9,0.9]")});
    EXPECT_EQ(set.objects[0].groups[1].material.vec3("kd"), dvec3(0.9));
}

// The mesh's JSON with a material added to the primitive.
void add_gltf_material(const std::string& path, const json& material) {
    json doc = json::parse(test::read_text(path));
    doc["materials"] = json::array({material});
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    test::write_text(path, doc.dump());
}

TEST(ModelFile, GltfMaterialBecomesPrincipledAndNodeTransformsApply) {
    TempDir dir;
    const geometry::Mesh mesh = box({0, 0, 0}, {1, 1, 1});
    test::write_gltf(mesh, dir.file("box.gltf"), test::GltfBuffer::side_file);
    add_gltf_material(dir.file("box.gltf"),
                      {{"name", "gold"},
                       {"pbrMetallicRoughness",
                        {{"baseColorFactor", {1.0, 0.75, 0.25, 1.0}}, {"metallicFactor", 0.75}, {"roughnessFactor", 0.5}}}});
    const Scene scene = load(write_mesh_scene(dir, "box.gltf", {{"material", nullptr}}));
    const Object& object = scene.objects[0];
    ASSERT_EQ(object.groups.size(), 1u);
    EXPECT_EQ(object.groups[0].name, "gold");
    EXPECT_EQ(object.groups[0].material.model_name(), "principled");
    EXPECT_EQ(object.groups[0].material.vec3("base_color"), dvec3(1.0, 0.75, 0.25));
    EXPECT_EQ(object.groups[0].material.number("metallic"), 0.75);
    EXPECT_EQ(object.groups[0].material.number("roughness"), 0.5);

    // A node's scale stretches the model in the file's coordinates: x twice as long.
    json doc = json::parse(test::read_text(dir.file("box.gltf")));
    doc["nodes"][0]["scale"] = {2.0, 1.0, 1.0};
    test::write_text(dir.file("box.gltf"), doc.dump());
    const geometry::Mesh placed = geometry::make_mesh(load(write_mesh_scene(dir, "box.gltf")).objects[0]);
    dvec3 lo(1e9), hi(-1e9);
    for (const dvec3& p : placed.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    EXPECT_NEAR(hi.x - lo.x, 2.0, 1e-12);
    EXPECT_NEAR(hi.y - lo.y, 1.0, 1e-12);
}

TEST(ModelFile, WithoutNormalsACreaseAbove30DegreesStaysSharp) {
    TempDir dir;
    test::write_obj(box({0, 0, 0}, {1, 1, 1}), dir.file("box.obj"), false);
    const geometry::Mesh mesh = geometry::make_mesh(load(write_mesh_scene(dir, "box.obj")).objects[0]);
    // Every corner of every face keeps the face's own normal (90-degree edges).
    for (std::size_t t = 0; t < mesh.triangles(); ++t) {
        const dvec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                    c = mesh.positions[mesh.indices[3 * t + 2]];
        const dvec3 face = glm::normalize(glm::cross(b - a, c - a));
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(glm::dot(mesh.normals[mesh.indices[3 * t + k]], face), 1.0, 1e-12);
    }
    // A finely divided sphere without normals is smooth: the normals point from the centre.
    test::write_obj(test::integer_uv_sphere(48, 24, 1000, 1), dir.file("ball.obj"), false);
    const geometry::Mesh ball = geometry::make_mesh(load(write_mesh_scene(dir, "ball.obj")).objects[0]);
    double worst = 1.0;
    for (std::size_t i = 0; i < ball.positions.size(); ++i)
        worst = std::min(worst, glm::dot(ball.normals[i], glm::normalize(ball.positions[i])));
    EXPECT_GT(worst, 0.99);
}

TEST(ModelFile, ConcavePolygonsAreTriangulatedInside) {
    TempDir dir;
    // An L-shaped hexagon, area 3: a fan from its first corner would cover outside it.
    test::write_text(dir.file("l.obj"), "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nf 3 4 5 6 1 2\n");
    const Scene scene = load(write_mesh_scene(dir, "l.obj", {{"size", 2.0}}));
    const model_file::Model& model = *scene.objects[0].model;
    ASSERT_EQ(model.triangles(), 4u);
    double area = 0.0;
    for (std::size_t t = 0; t < model.triangles(); ++t) {
        const dvec3 a = model.positions[model.indices[3 * t]], b = model.positions[model.indices[3 * t + 1]],
                    c = model.positions[model.indices[3 * t + 2]];
        const dvec3 n = glm::cross(b - a, c - a);
        EXPECT_GT(n.z, 0.0);  // the polygon's winding kept
        area += 0.5 * glm::length(n);
    }
    EXPECT_NEAR(area, 3.0, 1e-12);
}

TEST(ModelFile, SideFilesObeyTheConfinement) {
    TempDir dir;
    fs::create_directories(dir.file("alice"));
    test::write_obj(box({0, 0, 0}, {1, 1, 1}), dir.file("alice/box.obj"), true, "../secret.mtl");
    test::write_text(dir.file("secret.mtl"), "newmtl m0\nKd 1 0 0\n");
    TempDir holder;
    const std::string scene = write_mesh_scene(holder, "box.obj", {{"material", nullptr}});
    fs::copy_file(scene, dir.file("alice/scene.json"));
    LoadContext context = LoadContext::for_class(false);
    context.folder = dir.path();
    context.confinement = Confinement{"alice", ""};
    const std::string error = load_error("alice/scene.json", context);
    EXPECT_EQ(error.find("alice/scene.json: objects[0].file: "), 0u) << error;
    EXPECT_NE(error.find("secret.mtl"), std::string::npos) << error;

    // A symbolic link to a model outside the submission is refused too.
    test::write_obj(box({0, 0, 0}, {1, 1, 1}), dir.file("outside.obj"));
    fs::create_symlink(dir.file("outside.obj"), dir.file("alice/link.obj"));
    const std::string linked = write_mesh_scene(holder, "link.obj");
    fs::copy_file(linked, dir.file("alice/scene.json"), fs::copy_options::overwrite_existing);
    const std::string link_error = load_error("alice/scene.json", context);
    EXPECT_EQ(link_error.find("alice/scene.json: objects[0].file: "), 0u) << link_error;
}

// --- Untrusted files: one line naming the scene and the field, exit 1, nothing written. ---

// Runs m3055 render on a scene naming `model` and expects a refusal whose
// line matches "m3055: SCENE: objects[0].file: 'model': <pattern>".
void expect_model_refused(const TempDir& dir, const std::string& model, const std::string& pattern) {
    const std::string scene = write_mesh_scene(dir, model);
    test::expect_refused(dir.path(), {"render", "--scene", scene, "--out", dir.file("o.png")}, 1,
                         "m3055: " + scene + ": objects[0].file: " + pattern + "\n");
}

TEST(ModelFileUntrusted, NotAModelIsRefusedWithoutQuotingIt) {
    TempDir dir;
    test::write_text(dir.file("passwd.obj"), test::read_text("/etc/passwd"));
    expect_model_refused(dir, "passwd.obj", "*holds no triangles*");
    test::write_text(dir.file("passwd.gltf"), test::read_text("/etc/passwd"));
    expect_model_refused(dir, "passwd.gltf", "*is not a glTF file (not JSON)");
    test::write_text(dir.file("passwd.glb"), test::read_text("/etc/passwd"));
    expect_model_refused(dir, "passwd.glb", "*is not a binary glTF file (.glb)");
    test::write_text(dir.file("empty.obj"), "");
    expect_model_refused(dir, "empty.obj", "*holds no triangles*");
    test::write_text(dir.file("lines.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\np 1\n");
    expect_model_refused(dir, "lines.obj", "*holds no triangles, only lines or points");
    test::write_text(dir.file("model.stl"), "solid x\n");
    expect_model_refused(dir, "model.stl", "*must end in .obj, .gltf or .glb");
}

TEST(ModelFileUntrusted, BadNumbersAndIndicesAreRefused) {
    TempDir dir;
    // tinyobjloader alone reads these as 0, and the triangle would load.
    test::write_text(dir.file("nan.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 nan\nf 1 2 3\n");
    expect_model_refused(dir, "nan.obj", "*line 3: a vertex or normal coordinate is not a finite number*");
    test::write_text(dir.file("word.obj"), "v 0 0 0\nvn 0 0 one\nv 1 0 0\nv 0 1 0\nf 1 3 4\n");
    expect_model_refused(dir, "word.obj", "*line 2: a vertex or normal coordinate is not a finite number*");
    test::write_text(dir.file("inf.obj"), "v 0 0 0\nv 1e400 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_model_refused(dir, "inf.obj", "*not a finite number");
    test::write_text(dir.file("index.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    expect_model_refused(dir, "index.obj", "*line 4: a face names vertex 9, but the file has 3 vertices");
    test::write_text(dir.file("normal.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//7\n");
    expect_model_refused(dir, "normal.obj", "*line 5: a face names normal 7, but the file has 1 normals");
    test::write_text(dir.file("relative.obj"), "v 0 0 0\nf -1 -1 -1\nv 1 0 0\nv 0 1 0\nf -1 -2 -5\n");
    expect_model_refused(dir, "relative.obj", "*line 5: a face names vertex *, but the file has 3 vertices");

    // glTF: an index past its vertices, an accessor past its buffer, a NaN position.
    const geometry::Mesh mesh = box({0, 0, 0}, {1, 1, 1});
    test::write_gltf(mesh, dir.file("base.gltf"));
    const json base = json::parse(test::read_text(dir.file("base.gltf")));
    json doc = base;
    doc["accessors"][0]["count"] = 3;  // the box's indices into 3 positions (and normals)
    doc["accessors"][1]["count"] = 3;
    test::write_text(dir.file("index.gltf"), doc.dump());
    expect_model_refused(dir, "index.gltf", "*an index is *, but its primitive has 3 vertices");
    doc = base;
    doc["accessors"][2]["count"] = 1000000;
    test::write_text(dir.file("past.gltf"), doc.dump());
    expect_model_refused(dir, "past.gltf", "*reaches past its buffer view");

    geometry::Mesh nan_mesh = mesh;
    nan_mesh.positions[3].y = std::nan("");
    test::write_glb(nan_mesh, dir.file("nan.glb"));
    expect_model_refused(dir, "nan.glb", "*not a finite number");
}

TEST(ModelFileUntrusted, GeometryExtensionsAreRefusedByName) {
    TempDir dir;
    test::write_gltf(box({0, 0, 0}, {1, 1, 1}), dir.file("base.gltf"));
    for (const std::string name : {"KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_mesh_quantization"}) {
        json doc = json::parse(test::read_text(dir.file("base.gltf")));
        doc["extensionsUsed"] = {name};
        doc["extensionsRequired"] = {name};
        test::write_text(dir.file("ext.gltf"), doc.dump());
        expect_model_refused(dir, "ext.gltf", "*requires the extension \"" + name + "\"*");
    }
}

TEST(ModelFileUntrusted, TriangleAndSizeLimits) {
    TempDir dir;
    // 4 000 001 faces: refused from the count, before they are parsed.
    {
        std::ofstream out(dir.file("many.obj"));
        out << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
        const std::string block = [] {
            std::string b;
            for (int i = 0; i < 1000; ++i) b += "f 1 2 3\n";
            return b;
        }();
        for (int i = 0; i < 4000; ++i) out << block;
        out << "f 1 2 3\n";
    }
    expect_model_refused(dir, "many.obj", "*has 4000001 faces, more than the 4000000 triangles a scene may have");
    fs::remove(dir.file("many.obj"));
    // A glTF whose one primitive claims 4 000 001 triangles of indices it does not hold.
    test::write_gltf(box({0, 0, 0}, {1, 1, 1}), dir.file("base.gltf"));
    json doc = json::parse(test::read_text(dir.file("base.gltf")));
    doc["accessors"][2]["count"] = 12000003;
    test::write_text(dir.file("claims.gltf"), doc.dump());
    expect_model_refused(dir, "claims.gltf", "*");
    // Past the size cap (a sparse file: nothing is read).
    {
        std::ofstream out(dir.file("huge.obj"));
    }
    fs::resize_file(dir.file("huge.obj"), model_file::kMaxModelBytes + 1);
    const std::string scene = write_mesh_scene(dir, "huge.obj");
    const test::RunResult run = test::run_m3055({"render", "--scene", scene, "--out", dir.file("o.png")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err.find("m3055: " + scene + ": objects[0].file: "), 0u) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1);
    EXPECT_FALSE(test::file_exists(dir.file("o.png")));
}

// What Blender reads of an OBJ, read alike: a vertex of two coordinates has
// z = 0 (Blender's importer fills what a line lacks with 0), and a `usemtl`
// naming a material no .mtl defines gives its faces the default material
// (Blender makes a default one). A missing .mtl is refused in one line
// naming it (Blender warns and goes on): a grade must not change colours
// silently because a file was not handed in.
TEST(ModelFileUntrusted, ObjLeniencyAsBlenderReadsIt) {
    TempDir dir;
    test::write_text(dir.file("two.obj"), "v 0 0 0\nv 2 0\nv 0 1 0\nf 1 2 3\n");
    const Scene two = load_scene_file(write_mesh_scene(dir, "two.obj"), LoadContext::trusted());
    ASSERT_EQ(two.objects[0].model->positions.size(), 3u);
    EXPECT_EQ(two.objects[0].model->positions[1], dvec3(2, 0, 0));

    test::write_text(dir.file("m.mtl"), "newmtl red\nKd 1 0 0\n");
    test::write_text(dir.file("unknown.obj"), "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl nosuch\nf 1 2 3\n");
    const Scene unknown = load_scene_file(write_mesh_scene(dir, "unknown.obj", json::object(), false), LoadContext::trusted());
    ASSERT_EQ(unknown.objects[0].groups.size(), 1u);
    EXPECT_EQ(unknown.objects[0].groups[0].material.model().name, "phong");
    EXPECT_EQ(unknown.objects[0].groups[0].material.vec3("kd"), Material::of("phong").vec3("kd")) << "the default";

    test::write_text(dir.file("gone.obj"), "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    expect_model_refused(dir, "gone.obj", "*gone.obj: *gone.mtl: cannot read file: No such file or directory");
}

// Every OBJ and glTF file of Debian's assimp-testmodels, the broken ones
// among them: each loads, or is refused in one line that names the scene and
// the field and quotes none of the file.
TEST(ModelFileUntrusted, AssimpTestModelsLoadOrGiveOneLine) {
    const std::string root = "/usr/share/assimp/models";
    if (!fs::is_directory(root)) GTEST_SKIP() << "assimp-testmodels is not installed (scripts/setup --for-tests installs it)";
    int loaded = 0, refused = 0;
    std::vector<std::string> must_refuse = {"invalid/empty.obj", "invalid/malformed.obj", "glTF2/wrongTypes/badArray.gltf", "glTF2/wrongTypes/badObject.gltf",
                                            "glTF2/wrongTypes/badNumber.gltf", "glTF2/wrongTypes/badString.gltf",
                                            "glTF2/wrongTypes/badUint.gltf", "glTF2/wrongTypes/badExtension.gltf",
                                            "glTF2/SchemaFailures/sceneWrongType.gltf"};
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        const std::string ext = entry.path().extension().string();
        if (!entry.is_regular_file() || (ext != ".obj" && ext != ".gltf" && ext != ".glb")) continue;
        if (fs::file_size(entry.path()) > model_file::kMaxModelBytes) continue;
        const std::string relative = fs::relative(entry.path(), root).string();
        SCOPED_TRACE(relative);
        TempDir dir;
        const std::string scene = write_mesh_scene(dir, entry.path().string());
        const std::string error = load_error(scene);
        if (error == "(loaded)") {
            ++loaded;
            EXPECT_EQ(std::count(must_refuse.begin(), must_refuse.end(), relative), 0);
            continue;
        }
        ++refused;
        EXPECT_EQ(error.find(scene + ": objects[0].file: "), 0u) << error;
        EXPECT_EQ(test::bad_lines(error + "\n"), "") << error;
        EXPECT_EQ(error.find('\n'), std::string::npos);
        // No line of the file in the message.
        std::ifstream in(entry.path());
        std::string line;
        while (std::getline(in, line))
            if (line.size() >= 12) {
                EXPECT_EQ(error.find(line), std::string::npos) << error;
            }
    }
    std::printf("assimp-testmodels: %d loaded, %d refused\n", loaded, refused);
    EXPECT_GE(loaded, 20);
    EXPECT_GE(refused, int(must_refuse.size()));
}

}  // namespace
}  // namespace m3055
