// `m3055 bench --quick`: a smoke run that must write a well-formed table, CSV
// and plot. No timing assertions: only the shape of the output and the errors
// that do not depend on the machine. The plot is gnuplot's (app/bench/plot.cpp):
// these tests also run bench without gnuplot, with a gnuplot that fails, and
// `--replot` from a CSV.
#include "test_support.h"

#include "image/image.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace m3055::test {
namespace {

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream stream(text);
    while (std::getline(stream, part, separator)) parts.push_back(part);
    if (!text.empty() && text.back() == separator) parts.push_back("");
    return parts;
}

// Splits one CSV line, honouring quoted fields.
std::vector<std::string> csv_fields(const std::string& line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
        else if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) fields.emplace_back();
        else fields.back() += c;
    }
    return fields;
}

// gnuplot on $PATH (scripts/setup installs gnuplot-nox).
bool have_gnuplot() {
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');)
        if (!dir.empty() && access((dir + "/gnuplot").c_str(), X_OK) == 0) return true;
    return false;
}

// Sets $PATH (which the m3055 child inherits) for the life of the object.
class ScopedPath {
public:
    explicit ScopedPath(const std::string& path) : old_(std::getenv("PATH") ? std::getenv("PATH") : "") {
        setenv("PATH", path.c_str(), 1);
    }
    ~ScopedPath() { setenv("PATH", old_.c_str(), 1); }

private:
    std::string old_;
};

// Pixels within `tolerance` of the colour `rgb` (0xRRGGBB).
long pixels_near(const Rgb8Image& image, unsigned rgb, int tolerance = 12) {
    const int want[3] = {int(rgb >> 16), int((rgb >> 8) & 0xff), int(rgb & 0xff)};
    long count = 0;
    for (std::size_t i = 0; i + 2 < image.pixels.size(); i += 3) {
        bool near = true;
        for (int c = 0; c < 3; ++c) near = near && std::abs(int(image.pixels[i + c]) - want[c]) <= tolerance;
        count += near;
    }
    return count;
}

// The stderr line that starts with "m3055: ", or "".
std::string m3055_line(const std::string& err) {
    for (const std::string& line : split(err, '\n'))
        if (line.rfind("m3055: ", 0) == 0) return line;
    return "";
}

// A plot with every group of the bench: the picture has the axes' text, and
// each group's colour (points, lines, labels and the legend's sample).
void expect_plot(const std::string& dir) {
    const std::string script = read_text(dir + "/bench.gp");
    for (const char* command : {"set logscale xy", "set xlabel \"time per frame", "set ylabel \"mean |error|",
                                "set label \"8x4\"", "set label \"ray-cast\"", "set key", "plot $group0"})
        EXPECT_NE(script.find(command), std::string::npos) << command;
    if (!have_gnuplot()) {
        std::cout << "gnuplot is not installed: bench.png not checked (scripts/setup installs gnuplot-nox)\n";
        return;
    }
    const Rgb8Image plot = read_png(dir + "/bench.png");
    EXPECT_EQ(plot.width, 1200);
    EXPECT_EQ(plot.height, 720);
    long dark = 0;
    for (std::size_t i = 0; i < plot.pixels.size(); i += 3)
        if (plot.pixels[i] < 128 && plot.pixels[i + 1] < 128 && plot.pixels[i + 2] < 128) ++dark;
    EXPECT_GT(dark, 5000);  // axes, ticks, text
    // ray-cast green, per-pixel blue, Gouraud orange, metals purple, shaders teal, reference red.
    for (unsigned colour : {0x008c00u, 0x1f64c8u, 0xe07000u, 0x9646beu, 0x00939au, 0xd21e1eu})
        EXPECT_GT(pixels_near(plot, colour), 60) << std::hex << colour;
}

// One `bench --quick` run (half a minute; twice that under the sanitizers) for the
// tests below: made without gnuplot on $PATH, so that it also shows what a
// machine without gnuplot gets; the picture is then drawn from its CSV by
// `--replot`, which must write the run's own script.
class QuickBench : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new TempDir;
        TempDir empty_bin;
        const ScopedPath path(empty_bin.path());
        result_ = new RunResult(run_m3055({"bench", "--quick", "--out", dir_->path(), "--scenes", source_path("scenes")}));
    }
    static void TearDownTestSuite() {
        delete result_;
        delete dir_;
    }
    static const TempDir& run_dir() { return *dir_; }
    static const RunResult& result() { return *result_; }

private:
    static TempDir* dir_;
    static RunResult* result_;
};
TempDir* QuickBench::dir_ = nullptr;
RunResult* QuickBench::result_ = nullptr;

TEST_F(QuickBench, WritesWellFormedTablesAndCsv) {
    ASSERT_EQ(result().exit_code, 0) << result().err;

    // Markdown: the three tables, each row with as many cells as its header.
    const std::string md = read_text(run_dir().file("bench.md"));
    for (const char* heading : {"## Run time against error", "## Specialized against general programs",
                                "## Whole processes"})
        EXPECT_NE(md.find(heading), std::string::npos) << heading;
    for (const char* way : {"exact ray-cast spheres", "UV sphere 8x4", "UV sphere 128x64", "Gouraud", "eq. 15",
                            "eq. 16", "specialized programs", "one general program", "double-precision CPU reference",
                            "batch speed-up"})
        EXPECT_NE(md.find(way), std::string::npos) << way;
    int table_rows = 0;
    std::size_t header_cells = 0;
    for (const std::string& line : split(md, '\n')) {
        if (line.rfind("|", 0) != 0) {
            header_cells = 0;
            continue;
        }
        const std::size_t cells = split(line, '|').size();
        if (header_cells == 0) header_cells = cells;
        EXPECT_EQ(cells, header_cells) << line;
        ++table_rows;
    }
    EXPECT_GT(table_rows, 20);

    // CSV: a header and rows of the same width; the error columns of the ways are numbers.
    const std::vector<std::string> lines = split(read_text(run_dir().file("bench.csv")), '\n');
    ASSERT_GT(lines.size(), 20u);
    const std::vector<std::string> header = csv_fields(lines[0]);
    EXPECT_EQ(header[0], "section");
    EXPECT_EQ(header.back(), "label");
    int ways = 0;
    for (std::size_t i = 1; i < lines.size(); ++i) {
        if (lines[i].empty()) continue;
        const std::vector<std::string> fields = csv_fields(lines[i]);
        ASSERT_EQ(fields.size(), header.size()) << lines[i];
        if (fields[0] != "way") continue;
        ++ways;
        EXPECT_FALSE(fields.back().empty()) << "no plot label: " << lines[i];
        const double median = std::stod(fields[4]), max_diff = std::stod(fields[10]), mean = std::stod(fields[11]);
        const double same = std::stod(fields[12]);
        EXPECT_GT(median, 0.0) << lines[i];
        EXPECT_GE(max_diff, mean) << lines[i];
        EXPECT_GE(mean, 0.0) << lines[i];
        EXPECT_GE(same, 0.0) << lines[i];
        EXPECT_LE(same, 1.0) << lines[i];
        // The exact paths match the double reference to float precision (docs/spec.md#4-paper-models: 1e-3);
        // the coarsest mesh cannot, its silhouette cuts through interior pixels.
        if (fields[2].rfind("exact ray-cast", 0) == 0 || fields[2].rfind("specialized", 0) == 0 ||
            fields[2].rfind("one general", 0) == 0) {
            EXPECT_LT(max_diff, 1e-3) << lines[i];
        }
        if (fields[2].rfind("UV sphere 8x4", 0) == 0) {
            EXPECT_GT(max_diff, 1e-2) << lines[i];
        }
    }
    EXPECT_GE(ways, 17);

}

TEST_F(QuickBench, WithoutGnuplotTheScriptIsWrittenAndOneLineSaysHowToPlot) {
    EXPECT_EQ(result().exit_code, 0) << result().err;
    EXPECT_TRUE(file_exists(run_dir().file("bench.gp")));
    EXPECT_FALSE(file_exists(run_dir().file("bench.png")));
    const std::string line = m3055_line(result().err);
    EXPECT_NE(line.find("gnuplot is not installed"), std::string::npos) << result().err;
    EXPECT_NE(line.find("apt-get install gnuplot-nox"), std::string::npos) << line;
    EXPECT_NE(line.find("gnuplot bench.gp"), std::string::npos) << line;
}

// The run's CSV replotted with gnuplot: the same points and plot as the
// script the run wrote (what the run's results become and what its CSV's do
// agree), and a picture with every group.
TEST_F(QuickBench, ReplotOfTheRunsCsvWritesTheRunsScriptAndDrawsIt) {
    ASSERT_TRUE(file_exists(run_dir().file("bench.csv"))) << result().err;
    TempDir dir;
    write_text(dir.file("bench.csv"), read_text(run_dir().file("bench.csv")));
    const RunResult replot = run_m3055({"bench", "--replot", "--out", dir.path()});
    ASSERT_EQ(replot.exit_code, 0) << replot.err;
    // The points and the plot command byte for byte; the labels' positions,
    // computed from them, may differ in the sixth digit (the CSV's precision).
    const auto data_and_plot = [](const std::string& script) { return script.substr(script.find("$group0 << EOD")); };
    const std::string replotted = read_text(dir.file("bench.gp")), ran = read_text(run_dir().file("bench.gp"));
    EXPECT_EQ(data_and_plot(replotted), data_and_plot(ran));
    EXPECT_EQ(std::count(replotted.begin(), replotted.end(), '\n'), std::count(ran.begin(), ran.end(), '\n'));
    expect_plot(dir.path());
    if (have_gnuplot()) EXPECT_EQ(m3055_line(replot.err), "") << replot.err;
}

// A few `way` rows in bench.csv's columns (any order; others ignored).
const char* const kSmallCsv =
    "section,name,group,small_median_ms,mean_abs_diff,label,extra\n"
    "way,a,exact ray-cast,1.8,2.5e-08,ray-cast,x\n"
    "way,b,mesh per-pixel,2.1,0.014,8x4,x\n"
    "way,c,mesh per-pixel,6.2,3.1e-05,128x64,x\n"
    "way,\"d, quoted\",CPU reference,12.8,0,CPU double,x\n"
    "process,e,batch,760,,,x\n";

TEST(Bench, ReplotRedrawsThePlotFromTheCsv) {
    TempDir dir;
    write_text(dir.file("bench.csv"), kSmallCsv);
    const RunResult result = run_m3055({"bench", "--replot", "--out", dir.path()});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.out, "");  // nothing measured, no table
    const std::string script = read_text(dir.file("bench.gp"));
    for (const char* label : {"ray-cast", "8x4", "128x64", "CPU double"})
        EXPECT_NE(script.find("set label \"" + std::string(label) + "\""), std::string::npos) << label;
    EXPECT_NE(script.find("set xrange [1:100]"), std::string::npos) << script;  // 1.8 ... 12.8 ms
    EXPECT_NE(script.find("\"10^{-8}\" 1e-8"), std::string::npos) << script;    // 2.5e-8 ... 0.014
    if (have_gnuplot()) {
        const Rgb8Image plot = read_png(dir.file("bench.png"));
        EXPECT_GT(pixels_near(plot, 0x1f64c8u), 60);  // the per-pixel meshes' line and points
        EXPECT_EQ(pixels_near(plot, 0xe07000u), 0);   // no Gouraud rows, no orange
    }
}

TEST(Bench, ReplotOfABadCsvIsOneLineNamingTheFile) {
    TempDir dir;
    write_text(dir.file("bench.csv"), "section,group,name\nway,a,b\n");
    RunResult result = run_m3055({"bench", "--replot", "--out", dir.path()});
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find("bench.csv: no \"small_median_ms\" column"), std::string::npos) << result.err;

    write_text(dir.file("bench.csv"), std::string(kSmallCsv) + "way,f,shaders,fast,0.1,g,x\n");
    result = run_m3055({"bench", "--replot", "--out", dir.path()});
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.err.find("bench.csv:7: small_median_ms: expected a number"), std::string::npos) << result.err;
    EXPECT_FALSE(file_exists(dir.file("bench.png")));
}

// A gnuplot that fails: its message in one line, exit 1, no bench.png and no
// temporary file left in the folder.
TEST(Bench, FailingGnuplotIsOneLineAndLeavesNoFile) {
    TempDir dir, bin;
    write_text(bin.file("gnuplot"), "#!/bin/sh\necho 'bench.gp line 3: unknown terminal' >&2\nexit 1\n");
    ASSERT_EQ(chmod(bin.file("gnuplot").c_str(), 0755), 0);
    write_text(dir.file("bench.csv"), kSmallCsv);
    RunResult result;
    {
        const ScopedPath path(bin.path());
        result = run_m3055({"bench", "--replot", "--out", dir.path()});
    }
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find("gnuplot failed"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("unknown terminal"), std::string::npos) << result.err;
    std::vector<std::string> left;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path())) left.push_back(entry.path().filename());
    std::sort(left.begin(), left.end());
    EXPECT_EQ(left, (std::vector<std::string>{"bench.csv", "bench.gp"}));
}

TEST(Bench, MissingScenesFolderIsOneLine) {
    TempDir dir;
    const RunResult result = run_m3055({"bench", "--quick", "--out", dir.path(), "--scenes", dir.file("none")});
    EXPECT_NE(result.exit_code, 0);
    EXPECT_NE(result.err.find("none/"), std::string::npos) << result.err;
    EXPECT_FALSE(file_exists(dir.file("bench.md")));
}

}  // namespace
}  // namespace m3055::test
