#include "grading/grade_outputs.h"

#include "grading/comparison_json.h"

#include <cmath>
#include <cstdio>

namespace m3055::grading {

namespace {

using nlohmann::json;

std::string number_text(double value) {
    char out[64];
    std::snprintf(out, sizeof out, "%.10g", value);
    return out;
}

// RFC 4180 quoting; a field a spreadsheet would run as a formula (=, +, -, @)
// gets a leading apostrophe.
std::string csv_field(const std::string& text) {
    std::string value = text;
    if (!value.empty() && (value[0] == '=' || value[0] == '+' || value[0] == '-' || value[0] == '@'))
        value = "'" + value;
    if (value.find_first_of(",\"\n\r") == std::string::npos) return value;
    std::string out = "\"";
    for (char c : value) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string joined_reasons(const json& student) {
    std::string out;
    for (const json& reason : student["reasons"]) out += (out.empty() ? "" : " | ") + reason.get<std::string>();
    return out;
}

}  // namespace

json assignment_json(const Assignment& a) {
    const auto hundredths = [](double value) { return std::round(value * 100.0) / 100.0; };
    return {{"title", a.title}, {"max", hundredths(a.max_score())}, {"pass", hundredths(a.pass_score)},
            {"reference_image", "reference.png"}};
}

std::string result_of(const json& s) {
    if (s.value("missing", false)) return "missing";
    if (!s["broken"].get<std::string>().empty()) return "refused";
    return s["passed"].get<bool>() ? "pass" : "fail";
}

json grade_json(const Grade& g, const std::string& image_stem) {
    json checks = json::array();
    for (const Check& c : g.checks)
        checks.push_back({{"label", c.label}, {"points", c.points}, {"earned", c.earned}, {"ok", c.ok}, {"reason", c.reason}});
    json out = {{"student", g.student}, {"score", g.score},   {"max", g.max},       {"passed", g.passed},
                {"reasons", g.reasons()}, {"broken", g.broken}, {"checks", checks}, {"screenshot", g.screenshot},
                {"missing", g.missing},   {"notes", g.notes}};
    out["result"] = result_of(out);
    out["comparison"] = g.comparison ? to_json(*g.comparison) : json();
    out["images"] =
        image_stem.empty() ? json() : json{{"render", "students/" + image_stem + ".png"}, {"diff", "diffs/" + image_stem + ".png"}};
    return out;
}

std::string grades_csv(const GradeReport& report) {
    std::string out = "student,score,max,result,reasons,notes\n";
    for (const json& s : report.students) {
        std::string notes;
        if (s.contains("notes"))
            for (const json& note : s["notes"]) notes += (notes.empty() ? "" : " | ") + note.get<std::string>();
        out += csv_field(s["student"].get<std::string>()) + "," + number_text(s["score"].get<double>()) + "," +
               number_text(s["max"].get<double>()) + "," +
               result_of(s) + "," +
               csv_field(joined_reasons(s)) + "," + csv_field(notes) + "\n";
    }
    return out;
}

std::string grades_json(const GradeReport& report) {
    json out = {{"assignment", report.assignment}, {"folder", report.folder}, {"students", report.students}};
    // Every name and reason is valid UTF-8 already (submissions.h: shown_name,
    // text::escape); `replace` only makes sure a slip could never cost the
    // class its tables.
    return out.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

std::string gradescope_json(const GradeReport& report) {
    // Gradescope's autograder format: one test per student and check; with a
    // single student (Gradescope runs one submission at a time) also "score".
    json tests = json::array();
    for (const json& s : report.students) {
        const std::string who = s["student"].get<std::string>();
        if (!s["broken"].get<std::string>().empty()) {
            tests.push_back({{"name", who}, {"score", 0}, {"max_score", s["max"]}, {"output", s["broken"]}});
            continue;
        }
        for (const json& c : s["checks"])
            tests.push_back({{"name", who + ": " + c["label"].get<std::string>()},
                             {"score", c["earned"]},
                             {"max_score", c["points"]},
                             {"output", c["reason"]}});
    }
    json out = {{"tests", tests}};
    if (report.students.size() == 1) out["score"] = report.students[0]["score"];
    return out.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t chunk = (std::uint32_t(bytes[i]) << 16) |
                                    (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                                    (i + 2 < bytes.size() ? std::uint32_t(bytes[i + 2]) : 0);
        out += digits[(chunk >> 18) & 63];
        out += digits[(chunk >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(chunk >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[chunk & 63] : '=';
    }
    return out;
}

}  // namespace m3055::grading
