#include "grading/score_histogram.h"

#include "io/find_program.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>

namespace m3055::grading {

namespace {

std::string number(double value) {
    char out[32];
    std::snprintf(out, sizeof out, "%.6g", value);
    return out;
}

// Runs `program` with `args`, stdin /dev/null, stderr discarded; returns its
// stdout and sets `status` (the exit status, or 128 + signal, or -1 when it
// could not be started).
std::string run_capturing(const std::string& program, std::vector<std::string> args, int& status) {
    status = -1;
    int out[2];
    if (pipe2(out, O_CLOEXEC) != 0) return "";
    const pid_t pid = fork();
    if (pid < 0) {
        close(out[0]);
        close(out[1]);
        return "";
    }
    if (pid == 0) {
        const int null = open("/dev/null", O_RDWR);
        if (null < 0) _exit(127);
        dup2(null, 0);
        dup2(null, 2);
        dup2(out[1], 1);
        std::vector<char*> argv;
        argv.push_back(const_cast<char*>(program.c_str()));
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(program.c_str(), argv.data());
        _exit(127);
    }
    close(out[1]);
    std::string text;
    char buffer[16384];
    for (;;) {
        const ssize_t n = read(out[0], buffer, sizeof buffer);
        if (n > 0) text.append(buffer, std::size_t(n));
        else if (n == 0 || errno != EINTR) break;
    }
    close(out[0]);
    int wstatus = 0;
    while (waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {
    }
    status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
    return text;
}

}  // namespace

std::vector<int> histogram_counts(const std::vector<double>& scores, double max) {
    std::vector<int> counts(kHistogramBins, 0);
    if (!(max > 0)) return counts;
    for (double s : scores) {
        // A score on a bar's lower bound (0.3 of 3: 0.3 / 3 * 10 = 0.99999...)
        // belongs to that bar; scores are hundredths, never 1e-9 below a bound.
        const int bin = int(std::floor(s * kHistogramBins / max + 1e-9));
        ++counts[std::size_t(std::clamp(bin, 0, kHistogramBins - 1))];
    }
    return counts;
}

std::string histogram_gnuplot_commands(const std::vector<int>& counts, double max, double pass) {
    const double width = max / kHistogramBins;
    std::string c = "set terminal svg size 460,210 font \"DejaVu Sans,11\" background rgb \"white\"; ";
    std::string n = "array C[" + std::to_string(counts.size()) + "] = [", labels = "array L[" +
                    std::to_string(counts.size()) + "] = [", colours = "array K[" + std::to_string(counts.size()) + "] = [";
    for (std::size_t i = 0; i < counts.size(); ++i) {
        const double low = double(i) * width, high = double(i + 1) * width;
        const char* sep = i ? "," : "";
        n += sep + std::to_string(counts[i]);
        labels += std::string(sep) + "\"[" + number(low) + "," + number(high) + (i + 1 == counts.size() ? "]\"" : ")\"");
        // red 0xD00000 all fail, green 0x006600 all pass, amber 0xE09000 mixed.
        const int colour = high <= pass ? 0xD00000 : low >= pass ? 0x006600 : 0xE09000;
        colours += sep + std::to_string(colour);
    }
    c += n + "]; " + labels + "]; " + colours + "]; ";
    // Whole students on the y axis: a step of 1, 2, 5, 10, 20, 50 ... giving at most 6 ticks.
    const int most = counts.empty() ? 0 : *std::max_element(counts.begin(), counts.end());
    long step = 1;
    for (long decade = 1; step * 6 < most; decade *= 10)
        for (long m : {1L, 2L, 5L})
            if ((step = m * decade) * 6 >= most) break;
    c += "set ytics " + std::to_string(step) + "; ";
    const double pass_x = pass / width - 0.5;  // bar i is centred on x = i
    c += "set style fill solid 0.85 border rgb \"#444444\"; set boxwidth 0.85; set yrange [0:*]; "
         "set offsets 0,0,graph 0.15,0; set xrange [-0.6:" + number(kHistogramBins - 0.4) + "]; "
         "set xtics nomirror scale 0 font \",9\"; set ytics nomirror; set border 3; "
         "set ylabel \"students\"; set xlabel \"score (points)\"; ";
    c += "set arrow from " + number(pass_x) + ", graph 0 to " + number(pass_x) +
         ", graph 1 nohead dt 2 lc rgb \"#333333\"; set label \"pass: " + number(pass) + "\" at " +
         number(pass_x + 0.05) + ", graph 0.95 left font \",9\"; ";
    c += "plot C using ($1-1):2:(K[$1]):xtic(L[$1]) with boxes lc rgb variable notitle, "
         "C using ($1-1):2:(sprintf(\"%d\",$2)) with labels offset 0,0.7 font \",9\" notitle";
    return c;
}

HistogramSvg score_histogram_svg(const std::vector<double>& scores, double max, double pass) {
    const std::string gnuplot = find_program("gnuplot");
    if (gnuplot.empty())
        return {"", "No score histogram: gnuplot is not installed (Debian: apt-get install gnuplot-nox)."};
    int status = -1;
    const std::string out = run_capturing(
        // -d: no gnuplotrc nor ~/.gnuplot: grading opens nothing of the teacher's home.
        gnuplot, {"-d", "-e", histogram_gnuplot_commands(histogram_counts(scores, max), max, pass), "/dev/null"}, status);
    const std::size_t begin = out.find("<svg"), end = out.rfind("</svg>");
    if (status != 0 || begin == std::string::npos || end == std::string::npos || end < begin)
        return {"", "No score histogram: " + gnuplot + " failed (exit status " + std::to_string(status) + ")."};
    std::string svg = out.substr(begin, end + 6 - begin);
    // Inline SVG in HTML needs no namespace declarations, and the page holds
    // no URL at all (nothing a reader could mistake for a network access).
    for (const char* xmlns : {"xmlns=\"http://www.w3.org/2000/svg\"", "xmlns:xlink=\"http://www.w3.org/1999/xlink\""})
        if (const std::size_t at = svg.find(xmlns); at != std::string::npos && at < svg.find('>'))
            svg.erase(at, std::string(xmlns).size());
    return {svg, ""};
}

}  // namespace m3055::grading
