// bench.png: run time (x, log) against error (y, log), drawn by gnuplot.
// The plot is a gnuplot script with the data inline (bench.gp, written beside
// bench.csv so that anyone can restyle and rerun it); gnuplot turns it into
// bench.png. Without gnuplot the script is still written and one line says how
// to get the picture.
#pragma once

#include <string>
#include <vector>

namespace m3055::bench {

struct BenchResults;

// One way of rendering as the plot shows it.
struct PlotPoint {
    std::string group;  // colour, point type and legend entry ("mesh per-pixel", ...)
    std::string label;  // short text beside the point ("64x32", "ray-cast")
    double ms = 0;      // median time per frame at 512 x 320
    double error = 0;   // mean |diff| against the double reference; 0 = the reference itself
};

std::vector<PlotPoint> plot_points(const BenchResults& results);
// The `way` rows of a bench.csv (columns found by their header names).
// Throws std::runtime_error naming the file, and the line, on a malformed file.
std::vector<PlotPoint> read_plot_points(const std::string& csv_path);

// The whole gnuplot script: pngcairo 1200 x 720 into the file named by the
// gnuplot variable `out` (default "bench.png"), data inline, labels placed
// clear of the points, of each other and of the legend.
std::string gnuplot_script(const std::vector<PlotPoint>& points, const std::string& title);

// gnuplot on $PATH, or "".
std::string find_gnuplot();
// `gnuplot -e "out='OUT'" SCRIPT`, stdout and stderr into `log`; returns the
// exit status (127: it could not be started).
int run_gnuplot(const std::string& gnuplot, const std::string& script,
                const std::string& out, const std::string& log);
// The first line of `path` with text in it (gnuplot's error message).
std::string first_line(const std::string& path);

enum class PlotOutcome { drawn, no_gnuplot };
// Writes DIR/bench.gp and, when gnuplot is on $PATH, DIR/bench.png (atomically:
// gnuplot draws into a temporary file that is renamed). Throws
// std::runtime_error with gnuplot's first error line when gnuplot fails.
PlotOutcome write_plot(const std::string& dir, const std::vector<PlotPoint>& points, const std::string& title);

}  // namespace m3055::bench
