// The scene files in scenes/: every one loads, the paper's figures are
// 512 x 320 at 5 bits with every sphere inside the frame, the swept
// parameters are the paper's (docs/spec.md#6-figures), and the metal weights meet eq. 14.
#include "scene/load.h"
#include "test_paths.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace m3055 {
namespace {

namespace fs = std::filesystem;

std::string scene_path(const std::string& name) {
    return std::string(M3055_SOURCE_DIR) + "/scenes/" + name;
}

std::vector<std::string> scene_files() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(scene_path("")))
        if (entry.path().extension() == ".json") names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    return names;
}

const std::vector<std::string> kFigures = {"fig05.json", "fig06.json", "fig07.json",
                                           "fig08.json", "fig09.json", "fig10.json",
                                           "fig11.json", "fig12.json", "fig13.json"};

TEST(Scenes, EveryFileLoads) {
    const auto names = scene_files();
    for (const auto& figure : kFigures)
        EXPECT_NE(std::find(names.begin(), names.end(), figure), names.end()) << figure;
    EXPECT_NE(std::find(names.begin(), names.end(), "spec_example.json"), names.end());
    for (const auto& name : names) {
        SCOPED_TRACE(name);
        EXPECT_NO_THROW(load_scene_file(scene_path(name), LoadContext::trusted())) << name;
    }
}

TEST(Scenes, FiguresAreM3055FramesWithEverySphereInside) {
    for (const auto& name : kFigures) {
        SCOPED_TRACE(name);
        const Scene scene = load_scene_file(scene_path(name), LoadContext::trusted());
        EXPECT_EQ(scene.display.width, 512);
        EXPECT_EQ(scene.display.height, 320);
        EXPECT_EQ(scene.display.bits, 5);
        ASSERT_EQ(scene.camera.projection, Projection::orthographic);
        // the docs/spec.md#3-geometry orthographic frame: half extents along r and u_cam.
        const dvec3 f = glm::normalize(scene.camera.target - scene.camera.position);
        const dvec3 r = glm::normalize(glm::cross(f, scene.camera.up));
        const dvec3 u = glm::cross(r, f);
        const double half_h = scene.camera.height / 2;
        const double half_w = half_h * 512.0 / 320.0;
        for (const auto& object : scene.objects) {
            const dvec3 offset = object.center - scene.camera.position;
            EXPECT_GT(glm::dot(offset, f), object.radius);  // in front of the camera
            EXPECT_LE(std::abs(glm::dot(offset, r)) + object.radius, half_w * 0.99);
            EXPECT_LE(std::abs(glm::dot(offset, u)) + object.radius, half_h * 0.99);
        }
    }
}

// The sorted values of one material parameter over a figure's spheres.
template <typename Get>
std::vector<double> swept(const std::string& name, Get get) {
    const Scene scene = load_scene_file(scene_path(name), LoadContext::trusted());
    std::vector<double> values;
    for (const auto& object : scene.objects) values.push_back(get(object.material));
    std::sort(values.begin(), values.end());
    return values;
}

TEST(Scenes, HighlightAndTranslucentFiguresSweepThePapersValues) {
    EXPECT_EQ(swept("fig05.json", [](const Material& m) { return m.number("m"); }),
              (std::vector<double>{2, 4, 6, 8, 10, 20, 40, 60, 80, 100}));
    EXPECT_EQ(swept("fig05.json", [](const Material& m) { return m.number("w"); }), std::vector<double>(10, 1.0));
    EXPECT_EQ(swept("fig05.json", [](const Material& m) { return m.number("d"); }), std::vector<double>(10, 0.5));
    EXPECT_EQ(swept("fig06.json", [](const Material& m) { return m.number("w"); }),
              (std::vector<double>{0.0, 0.4, 0.6, 0.8, 1.0}));
    EXPECT_EQ(swept("fig06.json", [](const Material& m) { return m.number("m"); }), std::vector<double>(5, 10));

    std::set<std::pair<double, double>> fig7;
    for (const auto& object : load_scene_file(scene_path("fig07.json"), LoadContext::trusted()).objects) {
        ASSERT_EQ(object.material.model_name(), "translucent");
        fig7.insert({object.material.number("t_p"), object.material.number("t_n")});
    }
    std::set<std::pair<double, double>> expected7;
    for (double t_p : {0.0, 0.5})
        for (double t_n : {0.2, 0.4, 0.6, 0.8, 1.0}) expected7.insert({t_p, t_n});
    EXPECT_EQ(fig7, expected7);

    EXPECT_EQ(swept("fig08.json", [](const Material& m) { return m.number("t_p"); }),
              (std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0}));
    EXPECT_EQ(swept("fig08.json", [](const Material& m) { return m.number("t_n"); }), std::vector<double>(5, 0.8));

    // Fig. 9: one opaque highlight sphere behind (further from the camera) one translucent.
    const Scene fig9 = load_scene_file(scene_path("fig09.json"), LoadContext::trusted());
    ASSERT_EQ(fig9.objects.size(), 2u);
    const Object& opaque = fig9.objects[0];
    const Object& glass = fig9.objects[1];
    EXPECT_EQ(opaque.material.model_name(), "highlight");
    ASSERT_EQ(glass.material.model_name(), "translucent");
    EXPECT_LT(opaque.center.z + opaque.radius, glass.center.z);
    // partly behind: the discs overlap in the image, but neither covers the other
    const double apart = std::hypot(opaque.center.x - glass.center.x, opaque.center.y - glass.center.y);
    EXPECT_LT(apart, opaque.radius + glass.radius);
    EXPECT_GT(apart, std::abs(opaque.radius - glass.radius));
    for (const Object* o : {&opaque, &glass}) {
        EXPECT_EQ(o->material.number("w"), 1.0);
        EXPECT_EQ(o->material.number("m"), 10.0);
    }
    EXPECT_EQ(glass.material.number("t_n"), 0.8);
    EXPECT_EQ(glass.material.number("t_p"), 1.0);
}

// eq. 14: the main highlight centre is C0 when d + sum_j w_j / m_j^2 = 1.
TEST(Scenes, MetalFiguresMeetEquation14) {
    for (const std::string name : {"fig10.json", "fig11.json"}) {
        SCOPED_TRACE(name);
        const Scene scene = load_scene_file(scene_path(name), LoadContext::trusted());
        int metals = 0;
        for (const auto& object : scene.objects) {
            if (object.material.model_name() != "metal") continue;
            ++metals;
            double centre = object.material.number("d");
            for (const Lobe& lobe : object.material.lobes()) centre += lobe.w / (lobe.m * lobe.m);
            EXPECT_NEAR(centre, 1.0, 1e-9);
        }
        EXPECT_GT(metals, 0);
    }
}

TEST(Scenes, MetalFiguresUseThePapersLights) {
    const Scene fig11 = load_scene_file(scene_path("fig11.json"), LoadContext::trusted());
    ASSERT_EQ(fig11.lights.size(), 2u);
    EXPECT_EQ(fig11.lights[0].intensity, 1.0);
    EXPECT_TRUE(fig11.lights[0].lobes.empty());  // main light: the material's Fig. 10 lobes
    EXPECT_EQ(fig11.lights[1].intensity, 0.7);
    ASSERT_EQ(fig11.lights[1].lobes.size(), 1u);
    EXPECT_EQ(fig11.lights[1].lobes[0].w, 0.01);
    EXPECT_EQ(fig11.lights[1].lobes[0].m, 0.4);
    // main light upper right, secondary left and below (towards the light, camera looks down -z)
    EXPECT_GT(fig11.lights[0].direction.x, 0);
    EXPECT_GT(fig11.lights[0].direction.y, 0);
    EXPECT_LT(fig11.lights[1].direction.x, 0);
    EXPECT_LT(fig11.lights[1].direction.y, 0);

    const Scene fig12 = load_scene_file(scene_path("fig12.json"), LoadContext::trusted());
    ASSERT_EQ(fig12.lights.size(), 2u);
    for (const auto& object : fig12.objects) {
        ASSERT_EQ(object.material.model_name(), "metal_blinn");
        EXPECT_EQ(lobes_for(fig12.lights[0], object.material)[0].m, 13);
        EXPECT_EQ(lobes_for(fig12.lights[1], object.material)[0].m, 8);
    }
    EXPECT_EQ(fig12.lights[1].intensity, 0.4);

    const Scene fig13 = load_scene_file(scene_path("fig13.json"), LoadContext::trusted());
    ASSERT_EQ(fig13.lights.size(), 2u);
    for (const auto& object : fig13.objects) {
        ASSERT_EQ(object.material.model_name(), "metal_phong");
        const LobeList main = lobes_for(fig13.lights[0], object.material);
        ASSERT_EQ(main.size(), 2u);
        EXPECT_EQ(main[0].m, 20);
        EXPECT_EQ(main[1].m, 3);
        EXPECT_NEAR(main[1].w / main[0].w, 0.8 / 0.2, 1e-12);  // the paper's 1 : 4 mix
        EXPECT_NEAR(object.material.number("d") + main[0].w + main[1].w, 1.0, 1e-12);
        EXPECT_EQ(lobes_for(fig13.lights[1], object.material)[0].m, 2);
    }
    EXPECT_EQ(fig13.lights[1].intensity, 0.4);
}

}  // namespace
}  // namespace m3055
