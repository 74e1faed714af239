// The report's score histogram (grading/score_histogram.h): the bins, the
// gnuplot commands, and the SVG gnuplot draws from them.
#include "grading/score_histogram.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace m3055::grading {
namespace {

TEST(ScoreHistogram, TenEqualBinsTheLastHoldsTheMaximum) {
    const std::vector<int> counts = histogram_counts({0, 9.99, 10, 59.5, 60, 99.99, 100, 100}, 100);
    ASSERT_EQ(counts.size(), std::size_t(kHistogramBins));
    EXPECT_EQ(counts, (std::vector<int>{2, 1, 0, 0, 0, 1, 1, 0, 0, 3}));
    // Scores on another scale: 3 points max, bins of 0.3.
    EXPECT_EQ(histogram_counts({0.29, 0.3, 3}, 3), (std::vector<int>{1, 1, 0, 0, 0, 0, 0, 0, 0, 1}));
    // Nothing to bin without a positive maximum.
    EXPECT_EQ(histogram_counts({1, 2}, 0), std::vector<int>(kHistogramBins, 0));
}

TEST(ScoreHistogram, CommandsColourBarsByThePassMarkAndDrawIt) {
    const std::string c = histogram_gnuplot_commands({1, 0, 0, 0, 0, 2, 0, 0, 0, 7}, 100, 55);
    EXPECT_NE(c.find("array C[10] = [1,0,0,0,0,2,0,0,0,7]"), std::string::npos) << c;
    EXPECT_NE(c.find("\"[0,10)\""), std::string::npos) << c;
    EXPECT_NE(c.find("\"[90,100]\""), std::string::npos) << c;
    // [0,10) .. [40,50) all fail: red; [50,60) holds 55: amber; from 60 green.
    const std::string red = std::to_string(0xD00000), amber = std::to_string(0xE09000), green = std::to_string(0x006600);
    EXPECT_NE(c.find("array K[10] = [" + red + "," + red + "," + red + "," + red + "," + red + "," + amber + "," + green),
              std::string::npos)
        << c;
    EXPECT_NE(c.find("set arrow from 5, graph 0 to 5, graph 1"), std::string::npos) << c;  // 55 / 10 - 0.5
    EXPECT_NE(c.find("pass: 55"), std::string::npos) << c;
    EXPECT_EQ(c.find('\n'), std::string::npos) << "one line, given to gnuplot -e";
    // Whole students on the y axis, at most 6 ticks.
    EXPECT_NE(c.find("set ytics 2;"), std::string::npos) << c;  // 7 students: 0 2 4 6 8
    EXPECT_NE(histogram_gnuplot_commands({350, 0, 0, 0, 0, 0, 0, 0, 0, 0}, 100, 60).find("set ytics 100;"), std::string::npos);
    EXPECT_NE(histogram_gnuplot_commands({1, 0, 0, 0, 0, 0, 0, 0, 0, 0}, 100, 60).find("set ytics 1;"), std::string::npos);
}

TEST(ScoreHistogram, GnuplotDrawsAnInlineSvgOrTheReportSaysWhyNot) {
    const HistogramSvg drawn = score_histogram_svg({10, 20, 95, 95}, 100, 60);
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
        EXPECT_EQ(drawn.svg, "");
        EXPECT_NE(drawn.problem.find("gnuplot is not installed"), std::string::npos) << drawn.problem;
        return;
    }
    EXPECT_EQ(drawn.problem, "");
    EXPECT_EQ(drawn.svg.rfind("<svg", 0), 0u) << "no XML prolog: the SVG goes inside the page";
    EXPECT_EQ(drawn.svg.substr(drawn.svg.size() - 6), "</svg>");
    EXPECT_NE(drawn.svg.find(">pass: 60<"), std::string::npos);
    EXPECT_EQ(drawn.svg.find("http"), std::string::npos) << "no URL in the page, not even a namespace's";
    // The same scores, the same bytes (merged shards equal an unsharded run).
    EXPECT_EQ(score_histogram_svg({10, 20, 95, 95}, 100, 60).svg, drawn.svg);
}

TEST(ScoreHistogram, WithoutGnuplotOnThePathOneLineSaysHowToGetIt) {
    const char* old = std::getenv("PATH");
    const std::string saved = old ? old : "";
    setenv("PATH", "/nonexistent-m3055-test", 1);
    const HistogramSvg drawn = score_histogram_svg({50}, 100, 60);
    setenv("PATH", saved.c_str(), 1);
    EXPECT_EQ(drawn.svg, "");
    EXPECT_EQ(drawn.problem, "No score histogram: gnuplot is not installed (Debian: apt-get install gnuplot-nox).");
}

}  // namespace
}  // namespace m3055::grading
