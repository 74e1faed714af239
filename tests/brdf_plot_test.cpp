// m3055 plot (app/cmd_plot.cpp, app/plot_views.cpp): each view writes a PNG
// and its gnuplot script; the polar data of Lambert is the semicircle of
// radius kd/pi, and the albedo curve of a .brdf file without its 1/pi is pi.
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

namespace {

using m3055::test::run_m3055;

// The numbers of the data lines of a .gp script (lines of 2 to 4 numbers).
std::vector<std::vector<double>> data_rows(const std::string& script) {
    std::vector<std::vector<double>> rows;
    std::istringstream lines(script);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream in(line);
        std::vector<double> row;
        for (double x; in >> x;) row.push_back(x);
        if (in.eof() && row.size() >= 2) rows.push_back(row);
    }
    return rows;
}

TEST(BrdfPlot, EveryViewWritesAPngAndItsScript) {
    m3055::test::TempDir dir;
    const std::string brdf = m3055::test::source_path("tests/data/brdf/ggx_schlick.brdf");
    for (const char* view : {"polar", "slice", "albedo", "lobe"}) {
        const std::string png = dir.file(std::string(view) + ".png");
        const auto r = run_m3055({"plot", "--view", view, "--out", png, brdf, "--log"});
        ASSERT_EQ(r.exit_code, 0) << view << r.err;
        EXPECT_EQ(m3055::test::read_text(png).substr(0, 8), "\x89PNG\r\n\x1a\n") << view;
        EXPECT_GT(std::filesystem::file_size(png), 10000u) << view;
        EXPECT_GT(data_rows(m3055::test::read_text(dir.file(std::string(view) + ".gp"))).size(), 80u) << view;
    }
}

TEST(BrdfPlot, LambertsPolarCurveIsASemicircleOfRadiusKdOverPi) {
    m3055::test::TempDir dir;
    const auto r = run_m3055({"plot", "--view", "polar", "--out", dir.file("p.png"), "lambert", "--set", "kd=[0.5,0.25,0.1]"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto rows = data_rows(m3055::test::read_text(dir.file("p.gp")));
    ASSERT_GE(rows.size(), 300u);
    for (const auto& row : rows) EXPECT_NEAR(std::hypot(row[0], row[1]), 0.5 / M_PI, 1e-5);
}

TEST(BrdfPlot, AlbedoOfAFileWithoutOneOverPiIsPi) {
    m3055::test::TempDir dir;
    const auto r = run_m3055({"plot", "--view", "albedo", "--out", dir.file("a.png"),
                              m3055::test::source_path("tests/data/brdf/broken_no_pi.brdf")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto rows = data_rows(m3055::test::read_text(dir.file("a.gp")));
    ASSERT_EQ(rows.size(), 90u);
    for (const auto& row : rows) EXPECT_NEAR(row[1], M_PI, 1e-3) << row[0];
}

TEST(BrdfPlot, BadTargetIsOneLineAndNoFile) {
    m3055::test::TempDir dir;
    const auto r = run_m3055({"plot", "--out", dir.file("p.png"), "plastic"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "m3055: no model named \"plastic\" (nor a .brdf file)\n");
    EXPECT_FALSE(std::filesystem::exists(dir.file("p.png")));
}

}  // namespace

namespace {

TEST(BrdfBench, QuickRunWritesTheTable) {
    m3055::test::TempDir dir;
    const auto r = run_m3055({"bench", "--quick", "--brdf", m3055::test::source_path("tests/data/brdf"), "--out", dir.path()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string md = m3055::test::read_text(dir.file("brdf.md"));
    for (const char* row : {"| Lambert |", "| Blinn-Phong n 32 |", "| GGX + Schlick m 0.3 |"})
        EXPECT_NE(md.find(row), std::string::npos) << md;
}

}  // namespace
