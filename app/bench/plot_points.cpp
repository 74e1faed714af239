// The plot's points: from a bench run, or from the `way` rows of a bench.csv
// (`m3055 bench --replot DIR`).
#include "plot.h"

#include "results.h"

#include <fstream>
#include <map>
#include <stdexcept>

namespace m3055::bench {
namespace {

// One CSV line split into fields; "..." may hold commas and "" for a quote.
std::vector<std::string> csv_fields(const std::string& line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
        else if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) fields.emplace_back();
        else if (c != '\r') fields.back() += c;
    }
    return fields;
}

double number_field(const std::string& text, const std::string& where) {
    try {
        std::size_t used = 0;
        const double value = std::stod(text, &used);
        if (used == text.size() && value >= 0) return value;
    } catch (const std::exception&) {
    }
    throw std::runtime_error(where + ": expected a number >= 0, got \"" + text + "\"");
}

}  // namespace

std::vector<PlotPoint> plot_points(const BenchResults& results) {
    std::vector<PlotPoint> points;
    for (const WayResult& w : results.ways) {
        if (!w.small.valid() || (!w.exact_reference && !w.error.valid())) continue;
        points.push_back({w.group, w.label, w.small.median_ms, w.exact_reference ? 0.0 : w.error.mean_abs});
    }
    return points;
}

std::vector<PlotPoint> read_plot_points(const std::string& csv_path) {
    std::ifstream file(csv_path);
    if (!file) throw std::runtime_error(csv_path + ": cannot read");
    std::string line;
    std::map<std::string, std::size_t> column;
    if (std::getline(file, line)) {
        const std::vector<std::string> header = csv_fields(line);
        for (std::size_t i = 0; i < header.size(); ++i) column[header[i]] = i;
    }
    for (const char* name : {"section", "group", "small_median_ms", "mean_abs_diff", "label"})
        if (!column.count(name))
            throw std::runtime_error(csv_path + ": no \"" + name + "\" column (not a bench.csv of this m3055?)");
    std::vector<PlotPoint> points;
    for (int number = 2; std::getline(file, line); ++number) {
        if (line.empty()) continue;
        const std::vector<std::string> fields = csv_fields(line);
        const std::string where = csv_path + ":" + std::to_string(number);
        if (fields.size() != column.size())
            throw std::runtime_error(where + ": " + std::to_string(fields.size()) + " fields, the header has " +
                                     std::to_string(column.size()));
        if (fields[column["section"]] != "way" || fields[column["small_median_ms"]].empty()) continue;
        points.push_back({fields[column["group"]], fields[column["label"]],
                          number_field(fields[column["small_median_ms"]], where + ": small_median_ms"),
                          number_field(fields[column["mean_abs_diff"]], where + ": mean_abs_diff")});
    }
    if (points.empty()) throw std::runtime_error(csv_path + ": no \"way\" rows to plot");
    return points;
}

}  // namespace m3055::bench
