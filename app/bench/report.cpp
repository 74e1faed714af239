// bench.md and bench.csv.
#include "results.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <thread>

namespace m3055::bench {
namespace {

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

std::string ms_cell(const TimeStats& t) {
    if (!t.valid()) return "-";
    return format("%.3g", t.median_ms) + " (" + format("%.3g", t.min_ms) + "-" + format("%.3g", t.max_ms) + ")";
}

std::string error_cell(double value, bool exact) { return exact ? "0" : format("%.2e", value); }

std::string ratio_cell(double numerator, double denominator) {
    return denominator > 0 ? format("%.2f", numerator / denominator) + "x" : "-";
}

// CSV field: quoted when it holds a comma or a quote.
std::string field(const std::string& text) {
    if (text.find_first_of(",\"") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string number(double value) { return format("%.6g", value); }

}  // namespace

std::string markdown_report(const BenchResults& r) {
    std::ostringstream md;
    md << "# m3055 bench" << (r.quick ? " (--quick: few repetitions, numbers are rough)" : "") << "\n\n"
       << "Device: " << r.device << ". Frame times are glFinish-bounded, in milliseconds: median (min-max) of "
       << r.repetitions << " repetitions after " << r.warm_up << " warm-up frames at 512 x 320, "
       << r.large_repetitions << " at 1920 x 1080; a repetition renders every scene of the set once and "
       << "counts the mean per scene. Errors are at 512 x 320 against the double-precision CPU reference, "
       << "over interior pixels (away from silhouettes): max and mean |difference| of the unquantized colour, "
       << "and the share of pixels whose 5-bit display levels all match.\n\n";
    if (!r.load_before.empty())
        md << "Load average (1, 5, 15 min) before: " << r.load_before << ", after: " << r.load_after
           << " on " << std::thread::hardware_concurrency()
           << " cores; a load above the core count means other work shared the CPU and stretched the times "
              "(the min columns are the least disturbed samples).\n\n";

    md << "## Run time against error\n\n"
       << "| group | way | scenes | 512x320 ms | 1920x1080 ms | max abs diff | mean abs diff | same 5-bit level | "
          "error against |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const WayResult& w : r.ways) {
        const bool has_error = w.exact_reference || w.error.valid();
        md << "| " << w.group << " | " << w.way << " | " << w.scenes << " | " << ms_cell(w.small) << " | "
           << ms_cell(w.large) << " | " << (has_error ? error_cell(w.error.max_abs, w.exact_reference) : "-")
           << " | " << (has_error ? error_cell(w.error.mean_abs, w.exact_reference) : "-") << " | "
           << (w.exact_reference ? "100%" : (w.error.valid() ? format("%.2f%%", 100.0 * w.error.same_level_share)
                                                                : "-"))
           << " | " << w.error_against << " |\n";
    }

    if (!r.specialization.empty()) {
        md << "\n## Specialized against general programs (the paper's figure scenes, 512 x 320)\n\n"
           << "First frame = a fresh renderer's first render (compile + draw, Mesa's shader cache disabled); "
              "steady = later frames. Ratio = general / specialized (> 1: specialized is faster).\n\n"
           << "| scene | first frame, specialized | first frame, general | ratio | steady, specialized | "
              "steady, general | ratio |\n|---|---|---|---|---|---|---|\n";
        for (const auto& s : r.specialization)
            md << "| " << s.scene << " | " << ms_cell(s.first_specialized) << " | " << ms_cell(s.first_general)
               << " | " << ratio_cell(s.first_general.median_ms, s.first_specialized.median_ms) << " | "
               << ms_cell(s.steady_specialized) << " | " << ms_cell(s.steady_general) << " | "
               << ratio_cell(s.steady_general.median_ms, s.steady_specialized.median_ms) << " |\n";
        // Geometric means: the typical ratio, not dominated by the slowest scene.
        double log_first = 0, log_steady = 0;
        for (const auto& s : r.specialization) {
            log_first += std::log(s.first_general.median_ms / s.first_specialized.median_ms);
            log_steady += std::log(s.steady_general.median_ms / s.steady_specialized.median_ms);
        }
        const double n = double(r.specialization.size());
        md << "| geometric mean | | | " << format("%.2f", std::exp(log_first / n)) << "x | | | "
           << format("%.2f", std::exp(log_steady / n)) << "x |\n";
    }

    const ProcessResult& p = r.process;
    md << "\n## Whole processes\n\n| what | ms |\n|---|---|\n"
       << "| one `m3055 render` process, cold shader cache (MESA_SHADER_CACHE_DISABLE=true), median of "
       << p.cold.repetitions << " | " << ms_cell(p.cold) << " |\n"
       << "| one `m3055 render` process, warm shader cache, median of " << p.warm.repetitions << " | "
       << ms_cell(p.warm) << " |\n"
       << "| " << p.batch_scenes << " scenes: one `m3055 batch` process | " << format("%.0f", p.batch_ms) << " ("
       << format("%.1f", p.batch_scenes ? p.batch_ms / p.batch_scenes : 0) << " per scene) |\n"
       << "| " << p.batch_scenes << " scenes: " << p.batch_scenes << " `m3055 render` processes | "
       << format("%.0f", p.separate_ms) << " (" << format("%.1f", p.batch_scenes ? p.separate_ms / p.batch_scenes : 0)
       << " per scene) |\n"
       << "| batch speed-up (separate / batch; the target is >= 10x) | " << format("%.1f", p.ratio()) << "x |\n";
    md << "\nWhole bench: " << format("%.0f", r.total_seconds) << " s.\n";
    return md.str();
}

std::string csv_report(const BenchResults& r) {
    std::ostringstream csv;
    csv << "section,group,name,scenes,small_median_ms,small_min_ms,small_max_ms,large_median_ms,large_min_ms,"
           "large_max_ms,max_abs_diff,mean_abs_diff,same_level_share,error_against,label\n";
    auto times = [&](const TimeStats& t) {
        return t.valid() ? number(t.median_ms) + "," + number(t.min_ms) + "," + number(t.max_ms) : std::string(",,");
    };
    for (const WayResult& w : r.ways) {
        const bool has_error = w.exact_reference || w.error.valid();
        csv << "way," << field(w.group) << "," << field(w.way) << "," << field(w.scenes) << "," << times(w.small)
            << "," << times(w.large) << ","
            << (has_error ? number(w.error.max_abs) + "," + number(w.error.mean_abs) + "," +
                                number(w.exact_reference ? 1.0 : w.error.same_level_share)
                          : std::string(",,"))
            << "," << field(w.error_against) << "," << field(w.label) << "\n";
    }
    for (const auto& s : r.specialization) {
        const std::pair<const char*, const TimeStats*> rows[] = {{"first frame specialized", &s.first_specialized},
                                                                 {"first frame general", &s.first_general},
                                                                 {"steady specialized", &s.steady_specialized},
                                                                 {"steady general", &s.steady_general}};
        for (const auto& [name, t] : rows)
            csv << "specialization,shaders," << name << "," << field(s.scene) << "," << times(*t) << ",,,,,,,,\n";
    }
    const ProcessResult& p = r.process;
    csv << "process,process,render cold shader cache,spec_example.json," << times(p.cold) << ",,,,,,,,\n"
        << "process,process,render warm shader cache,spec_example.json," << times(p.warm) << ",,,,,,,,\n"
        << "process,batch,one batch process," << p.batch_scenes << " scenes," << number(p.batch_ms) << ",,,,,,,,,,\n"
        << "process,batch,separate render processes," << p.batch_scenes << " scenes," << number(p.separate_ms)
        << ",,,,,,,,,,\n"
        << "process,batch,speed-up separate/batch," << p.batch_scenes << " scenes," << number(p.ratio())
        << ",,,,,,,,,,\n";
    return csv.str();
}

}  // namespace m3055::bench
