#include "grading/comparison_json.h"

#include <cmath>
#include <cstdio>

namespace m3055::grading {

namespace {

nlohmann::json threshold_json(const Threshold& threshold) {
    return {{"levels", threshold.levels}, {"percent", threshold.percent}};
}

}  // namespace

nlohmann::json to_json(const Comparison& c) {
    nlohmann::json out = {
        {"result", to_string(c.verdict)},
        {"width", c.width},
        {"height", c.height},
        {"bits", c.bits},
        {"pixels", c.pixels},
        {"same_pixels", c.same_pixels},
        {"same_percent", 100.0 * c.same_share()},
        {"max_levels", c.max_levels},
        {"histogram", {{"r", c.histogram[0]}, {"g", c.histogram[1]}, {"b", c.histogram[2]}}},
        {"fail", threshold_json(c.thresholds.fail)},
        {"over_fail", c.over_fail},
    };
    if (!c.region.empty()) out["region"] = c.region;
    if (c.thresholds.warn) {
        out["warn"] = threshold_json(*c.thresholds.warn);
        out["over_warn"] = c.over_warn;
    }
    if (c.linear) {
        // JSON has no infinity: identical linear images give "psnr_db": null.
        const LinearStats& s = *c.linear;
        out["linear"] = {{"max_abs", s.max_abs},
                         {"mean_abs", s.mean_abs},
                         {"rms", s.rms},
                         {"psnr_db", std::isfinite(s.psnr_db) ? nlohmann::json(s.psnr_db) : nlohmann::json()}};
    }
    return out;
}

std::string summary_line(const Comparison& c) {
    char text[240];
    int n = std::snprintf(text, sizeof text, "%s: %.2f %% of pixels on the same level, %llu on another (max %d level%s)",
                          to_string(c.verdict), percent_to_two_places(c.same_pixels, c.pixels),
                          (unsigned long long)(c.pixels - c.same_pixels), c.max_levels, c.max_levels == 1 ? "" : "s");
    // With --fail-levels N > 0 a pixel fails only beyond N levels: say how many do, so that
    // the line's count is never read as the failing one.
    if (c.thresholds.fail.levels > 0 && n > 0 && n < int(sizeof text))
        std::snprintf(text + n, sizeof text - n, ", %llu more than %d level%s off", (unsigned long long)c.over_fail,
                      c.thresholds.fail.levels, c.thresholds.fail.levels == 1 ? "" : "s");
    return text;
}

}  // namespace m3055::grading
