// m3055 plot spectrum (app/cmd_plot.cpp, app/plot_spectrum.cpp): the PNG and
// its gnuplot script hold the numbers of scene/spectrum_view.h for the light
// and material the options name; a bad option is one line, exit 1, no file.
#include "scene/load.h"
#include "scene/spectrum_view.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace m3055 {
namespace {

using test::run_m3055;

// The data blocks of a .gp script: lines of two numbers, a block ended by "e".
std::vector<std::vector<std::pair<double, double>>> data_blocks(const std::string& script) {
    std::vector<std::vector<std::pair<double, double>>> blocks(1);
    std::istringstream lines(script);
    for (std::string line; std::getline(lines, line);) {
        if (line == "e") {
            blocks.emplace_back();
            continue;
        }
        std::istringstream in(line);
        double nm = 0, value = 0;
        if (in >> nm >> value && (in >> std::ws).eof()) blocks.back().push_back({nm, value});
    }
    blocks.pop_back();
    return blocks;
}

void expect_curves(const std::string& gp, const SpectrumView& view) {
    const auto blocks = data_blocks(test::read_text(gp));
    ASSERT_EQ(blocks.size(), view.curves.reflectance.empty() ? 1u : 2u);
    ASSERT_EQ(blocks[0].size(), view.curves.nm.size());
    for (std::size_t i = 0; i < blocks[0].size(); ++i) {
        EXPECT_EQ(blocks[0][i].first, view.curves.nm[i]);
        EXPECT_NEAR(blocks[0][i].second, view.curves.light[i], 1e-8 * view.curves.light[i]);
        if (blocks.size() == 2) {
            EXPECT_NEAR(blocks[1][i].second, view.curves.reflectance[i], 1e-8);
        }
    }
}

TEST(PlotSpectrum, AKelvinLightAndAConductorGiveTheirCurves) {
    test::TempDir dir;
    const auto r = run_m3055({"plot", "spectrum", "--kelvin", "3200", "--conductor", "gold", "--out", dir.file("s.png")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(test::read_text(dir.file("s.png")).substr(0, 8), "\x89PNG\r\n\x1a\n");
    Light light;
    light.temperature_k = 3200.0;
    Material gold = Material::of("metal");
    gold.set_choice("conductor", "gold");
    expect_curves(dir.file("s.gp"), spectrum_view(&light, &gold));
    EXPECT_NE(test::read_text(dir.file("s.gp")).find("light: black body 3200 K"), std::string::npos);
}

TEST(PlotSpectrum, TheScenesLightAndObjectAreThoseTheOptionsPick) {
    test::TempDir dir;
    const std::string scene_file = test::source_path("screenshots/spectral_gold.json");
    const auto r = run_m3055({"plot", "spectrum", "--scene", scene_file, "--light", "1", "--object", "1", "--out",
                              dir.file("s.png")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Scene scene = load_scene_file(scene_file, LoadContext::trusted());
    ASSERT_GE(scene.lights.size(), 2u);
    expect_curves(dir.file("s.gp"), spectrum_view(&scene.lights[1], &scene.objects[1].material));
    // With a light of its own (--illuminant) the scene's material stays.
    const auto a = run_m3055({"plot", "spectrum", "--scene", scene_file, "--object", "1", "--illuminant", "A", "--out",
                              dir.file("a.png")});
    ASSERT_EQ(a.exit_code, 0) << a.err;
    Light illuminant_a;
    illuminant_a.illuminant = "A";
    expect_curves(dir.file("a.gp"), spectrum_view(&illuminant_a, &scene.objects[1].material));
}

TEST(PlotSpectrum, AnRgbColourPlotsTheLightAloneAndSaysWhy) {
    test::TempDir dir;
    const auto r = run_m3055({"plot", "spectrum", "--scene", test::source_path("scenes/fig10.json"), "--out",
                              dir.file("s.png")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string gp = test::read_text(dir.file("s.gp"));
    EXPECT_NE(gp.find("an RGB colour, no spectrum"), std::string::npos);
    EXPECT_EQ(data_blocks(gp).size(), 1u);
}

TEST(PlotSpectrum, BadOptionsAreOneLineExitOneAndWriteNothing) {
    test::TempDir dir;
    const std::string scene_file = test::source_path("screenshots/spectral_gold.json");
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--kelvin", "50"}, "plot spectrum: --kelvin: must be in [1000, 40000], got 50"},
        {{"--conductor", "platinum"}, "plot spectrum: --conductor platinum: not a measured metal (aluminium,"},
        {{"--illuminant", "Q"}, "plot spectrum: --illuminant Q: not a CIE illuminant (A, B,"},
        {{"--kelvin", "3000", "--illuminant", "A"}, "plot spectrum: give --kelvin or --illuminant, not both"},
        {{"--scene", scene_file, "--light", "7"}, "plot spectrum: --light 7: " + scene_file + " has lights 0 to 2"},
        {{"--scene", scene_file, "--object", "-1"}, "plot spectrum: --object -1: " + scene_file + " has objects 0 to 1"},
        {{"--object", "1"}, "plot spectrum: --light and --object pick from a --scene; give one"},
    };
    for (const auto& [args, message] : cases) {
        std::vector<std::string> command = {"plot", "spectrum", "--out", dir.file("bad.png")};
        command.insert(command.end(), args.begin(), args.end());
        const auto r = run_m3055(command);
        EXPECT_EQ(r.exit_code, 1) << message;
        EXPECT_EQ(r.err.find("m3055: " + message), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.file("bad.png")));
        EXPECT_FALSE(std::filesystem::exists(dir.file("bad.gp")));
    }
}

}  // namespace
}  // namespace m3055
