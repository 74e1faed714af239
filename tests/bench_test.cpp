// `m3055 bench --quick`: a smoke run that must write a well-formed table, CSV
// and plot. No timing assertions: only the shape of the output and the errors
// that do not depend on the machine.
#include "test_support.h"

#include "image/image.h"

#include <gtest/gtest.h>

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

TEST(Bench, QuickRunWritesTableCsvAndPlot) {
    TempDir dir;
    const RunResult result = run_m3055({"bench", "--quick", "--out", dir.path(), "--scenes", source_path("scenes")});
    ASSERT_EQ(result.exit_code, 0) << result.err;

    // Markdown: the three tables, each row with as many cells as its header.
    const std::string md = read_text(dir.file("bench.md"));
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
    const std::vector<std::string> lines = split(read_text(dir.file("bench.csv")), '\n');
    ASSERT_GT(lines.size(), 20u);
    const std::vector<std::string> header = csv_fields(lines[0]);
    EXPECT_EQ(header[0], "section");
    int ways = 0;
    for (std::size_t i = 1; i < lines.size(); ++i) {
        if (lines[i].empty()) continue;
        const std::vector<std::string> fields = csv_fields(lines[i]);
        ASSERT_EQ(fields.size(), header.size()) << lines[i];
        if (fields[0] != "way") continue;
        ++ways;
        const double median = std::stod(fields[4]), max_diff = std::stod(fields[10]), mean = std::stod(fields[11]);
        const double same = std::stod(fields[12]);
        EXPECT_GT(median, 0.0) << lines[i];
        EXPECT_GE(max_diff, mean) << lines[i];
        EXPECT_GE(mean, 0.0) << lines[i];
        EXPECT_GE(same, 0.0) << lines[i];
        EXPECT_LE(same, 1.0) << lines[i];
        // The exact paths match the double reference to float precision (SPEC 4: 1e-3);
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

    // Plot: a real PNG with something drawn on it.
    const Rgb8Image plot = read_png(dir.file("bench.png"));
    EXPECT_GE(plot.width, 800);
    EXPECT_GE(plot.height, 500);
    long dark = 0;
    for (std::size_t i = 0; i < plot.pixels.size(); i += 3)
        if (plot.pixels[i] < 128 && plot.pixels[i + 1] < 128 && plot.pixels[i + 2] < 128) ++dark;
    EXPECT_GT(dark, 5000);  // axes, ticks, text
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
