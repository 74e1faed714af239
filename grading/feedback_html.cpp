// feedback/NAME.html of `m3055 grade` (grade_outputs.h): one page to hand
// back to one student, self-contained (its images inlined as data: URIs), so
// it can be mailed or uploaded alone.
#include "grading/grade_outputs.h"

#include "grading/page_parts.h"

namespace m3055::grading {

std::string feedback_html(const GradeReport& report, const nlohmann::json& s,
                          const std::function<std::vector<std::uint8_t>(const std::string&)>& image_bytes) {
    using nlohmann::json;
    using page::escape_html;
    using page::inline_image_cell;
    using page::kStyle;
    using page::kViewer;
    using page::score_text;
    const json& a = report.assignment;
    const std::string name = s["student"].get<std::string>();
    const std::string title = a["title"].get<std::string>();
    const std::string result = result_of(s);
    // The result's word, said to the student.
    const std::string said = result == "pass"      ? "passed"
                             : result == "fail"    ? "failed"
                             : result == "refused" ? "refused (not graded: the reason is below)"
                                                   : "no submission";
    std::string page = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + escape_html(title) +
                       ": " + escape_html(name) + "</title>\n" + kStyle + "</head><body>\n";
    page += "<h1>" + escape_html(title) + "</h1>\n<h2 id=\"student\">" + escape_html(name) + "</h2>\n";
    page += "<p id=\"score\" class=\"" + result + "\">" + score_text(s["score"].get<double>()) + " of " +
            score_text(s["max"].get<double>()) + " points: " + said + " (" +
            score_text(a["pass"].get<double>()) + " to pass)</p>\n";
    page += "<p>Click a picture to magnify it and flip between your render, the reference and the difference.</p>\n";
    page += "<table class=\"shots\" data-student=\"" + escape_html(name) +
            "\"><thead><tr><th>Your render</th><th>The reference</th><th>Levels off the reference</th></tr></thead>"
            "<tbody><tr>";
    std::vector<std::uint8_t> render, diff;
    if (s["images"].is_object()) {
        render = image_bytes(s["images"]["render"].get<std::string>());
        diff = image_bytes(s["images"]["diff"].get<std::string>());
    }
    std::string reference = inline_image_cell(image_bytes(a["reference_image"].get<std::string>()), "the reference", "reference");
    if (reference.rfind("<td><img ", 0) == 0) reference.insert(9, "id=\"reference-image\" ");
    page += inline_image_cell(render, "your render", "render") + reference + inline_image_cell(diff, "levels off the reference", "diff");
    page += "</tr></tbody></table>\n<h3>Checks</h3>\n<ul id=\"checks\">\n";
    if (!s["broken"].get<std::string>().empty())
        page += "<li class=\"fail\">" + escape_html(s["broken"].get<std::string>()) + "</li>\n";
    for (const json& c : s["checks"]) {
        // A reason starts with its check's name ("image: 86.89 % ..."): shown once.
        const std::string label = c["label"].get<std::string>();
        std::string reason = c["reason"].get<std::string>();
        if (reason.rfind(label + ": ", 0) == 0) reason.erase(0, label.size() + 2);
        page += std::string("<li class=\"") + (c["ok"].get<bool>() ? "pass" : "fail") + "\">" +
                (c["ok"].get<bool>() ? "&#10004; " : "&#10008; ") + escape_html(label) + ": " +
                score_text(c["earned"].get<double>()) + " of " + score_text(c["points"].get<double>()) + " &mdash; " +
                escape_html(reason) + "</li>\n";
    }
    if (!s["screenshot"].get<std::string>().empty())
        page += "<li>" + escape_html(s["screenshot"].get<std::string>()) + "</li>\n";
    return page + "</ul>\n" + kViewer + "</body></html>\n";
}

}  // namespace m3055::grading
