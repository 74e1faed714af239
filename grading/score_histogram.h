// The score histogram at the top of report.html: ten bars
// over [0, max], drawn by gnuplot (gnuplot-nox, scripts/setup) as SVG that the
// page inlines. Without gnuplot, or when it fails, the report says so in one
// line and grading goes on: the picture is a convenience, the table holds
// every score.
#pragma once

#include <string>
#include <vector>

namespace m3055::grading {

inline constexpr int kHistogramBins = 10;

// How many of `scores` fall in each of kHistogramBins equal bins over
// [0, max]: bin i holds [i max/10, (i+1) max/10), the last one also max.
std::vector<int> histogram_counts(const std::vector<double>& scores, double max);

// The gnuplot commands (one line, ';'-separated: given with -e, no script
// file) drawing the counts as SVG on stdout: bars red where every score in
// them fails `pass`, green where every one passes, amber where they are
// mixed, the pass mark dashed.
std::string histogram_gnuplot_commands(const std::vector<int>& counts, double max, double pass);

struct HistogramSvg {
    std::string svg;      // "<svg ...>...</svg>" (no XML prolog), or ""
    std::string problem;  // when svg is "": one line saying why there is no picture
};

// Runs gnuplot (found on $PATH) on the class's scores.
HistogramSvg score_histogram_svg(const std::vector<double>& scores, double max, double pass);

}  // namespace m3055::grading
