// report.html of `m3055 grade` (grade_outputs.h): one page a teacher opens
// from disk or prints. Images are data: URIs so the page can be mailed or
// uploaded alone; pixelated scaling keeps the display's dots visible.
#include "grading/grade_outputs.h"

#include <cstdio>

namespace m3055::grading {

namespace {

using nlohmann::json;

std::string escape_html(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string score_text(double value) {
    char out[64];
    std::snprintf(out, sizeof out, "%.6g", value);
    return out;
}

constexpr const char* kStyle = R"(<style>
body{font-family:sans-serif;margin:1.5em;color:#111}
table{border-collapse:collapse;width:100%}
th,td{border:1px solid #999;padding:4px 6px;vertical-align:top;text-align:left}
th{background:#eee;cursor:pointer}
td.num{text-align:right;white-space:nowrap}
img{width:256px;image-rendering:pixelated;display:block}
.pass{color:#060;font-weight:bold}.fail{color:#a00;font-weight:bold}.note{color:#555;font-style:italic}
ul{margin:0;padding-left:1.2em}
@media print{th{cursor:auto}tr{break-inside:avoid}img{width:200px}body{margin:0}}
</style>
)";

// Click a header to sort by that column; numbers numerically (data-sort).
constexpr const char* kScript = R"(<script>
document.querySelectorAll('th[data-col]').forEach(function(th){th.addEventListener('click',function(){
var col=+th.dataset.col,body=document.querySelector('#grades tbody'),rows=[].slice.call(body.rows);
var dir=th.dataset.dir==='asc'?-1:1;th.dataset.dir=dir===1?'asc':'desc';
rows.sort(function(a,b){var x=a.cells[col].dataset.sort,y=b.cells[col].dataset.sort;
var nx=parseFloat(x),ny=parseFloat(y);var r=isNaN(nx)||isNaN(ny)?x.localeCompare(y):nx-ny;return dir*r;});
rows.forEach(function(r){body.appendChild(r);});});});
</script>
)";

std::string image_cell(const std::vector<std::uint8_t>& png, const std::string& alt) {
    if (png.empty()) return "<td>&mdash;</td>";
    return "<td><img alt=\"" + escape_html(alt) + "\" src=\"data:image/png;base64," + base64(png) + "\"></td>";
}

std::string student_row(const json& s,
                        const std::function<std::vector<std::uint8_t>(const std::string&)>& image_bytes) {
    const std::string name = s["student"].get<std::string>();
    const bool passed = s["passed"].get<bool>();
    const double score = s["score"].get<double>();
    std::string row = "<tr><td data-sort=\"" + escape_html(name) + "\">" + escape_html(name) + "</td>";
    row += "<td class=\"num\" data-sort=\"" + score_text(score) + "\">" + score_text(score) + " / " +
           score_text(s["max"].get<double>()) + "</td>";
    const char* result = s.value("missing", false) ? "missing" : passed ? "pass" : "fail";
    row += std::string("<td data-sort=\"") + result + "\" class=\"" + (passed ? "pass" : "fail") + "\">" + result + "</td>";
    std::vector<std::uint8_t> render, diff;
    if (!s["images"].is_null()) {
        render = image_bytes(s["images"]["render"].get<std::string>());
        diff = image_bytes(s["images"]["diff"].get<std::string>());
    }
    row += image_cell(render, name + ": render") + image_cell(diff, name + ": difference");
    row += "<td data-sort=\"\"><ul>";
    for (const json& reason : s["reasons"]) row += "<li>" + escape_html(reason.get<std::string>()) + "</li>";
    if (s["reasons"].empty()) row += "<li>all checks passed</li>";
    if (s.contains("notes"))
        for (const json& note : s["notes"]) row += "<li class=\"note\">note: " + escape_html(note.get<std::string>()) + "</li>";
    return row + "</ul></td></tr>\n";
}

// What the class folder held that was not graded, and byte-identical submissions.
std::string folder_sections(const json& folder) {
    std::string out;
    if (!folder["ignored"].empty()) {
        out += "<details id=\"ignored\" open><summary>Not graded: " + std::to_string(folder["ignored"].size()) +
               (folder["ignored"].size() == 1 ? " entry" : " entries") + " of the submissions folder</summary><ul>\n";
        for (const json& entry : folder["ignored"])
            out += "<li><code>" + escape_html(entry["name"].get<std::string>()) + "</code>: " +
                   escape_html(entry["why"].get<std::string>()) + "</li>\n";
        out += "</ul></details>\n";
    }
    if (!folder["identical"].empty()) {
        out += "<details id=\"identical\" open><summary>Byte-identical submissions (information, no penalty)</summary><ul>\n";
        for (const json& group : folder["identical"]) {
            std::string names;
            for (const json& name : group) names += (names.empty() ? "" : ", ") + escape_html(name.get<std::string>());
            out += "<li>" + names + "</li>\n";
        }
        out += "</ul></details>\n";
    }
    return out;
}

}  // namespace

std::string report_html(const GradeReport& report,
                        const std::function<std::vector<std::uint8_t>(const std::string&)>& image_bytes) {
    const json& a = report.assignment;
    const std::string title = a["title"].get<std::string>();
    std::size_t passed = 0, missing = 0;
    for (const json& s : report.students) {
        passed += s["passed"].get<bool>() ? 1 : 0;
        missing += s.value("missing", false) ? 1 : 0;
    }
    const std::size_t submitted = report.students.size() - missing;
    std::string page = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" +
                       escape_html(title) + ": grades</title>\n" + kStyle + "</head><body>\n";
    page += "<h1>" + escape_html(title) + "</h1>\n<p>" + std::to_string(submitted) +
            (submitted == 1 ? " submission, " : " submissions, ") + std::to_string(passed) + " passed (at least " +
            score_text(a["pass"].get<double>()) + " of " + score_text(a["max"].get<double>()) + " points)" +
            (missing ? "; " + std::to_string(missing) + " on the roster with no submission" : std::string()) +
            ". Click a column's header to sort.</p>\n";
    const std::vector<std::uint8_t> reference = image_bytes(a["reference_image"].get<std::string>());
    if (!reference.empty())
        page += "<figure><img alt=\"reference\" src=\"data:image/png;base64," + base64(reference) +
                "\"><figcaption>The reference</figcaption></figure>\n";
    page += folder_sections(report.folder);
    page += "<table id=\"grades\"><thead><tr><th data-col=\"0\">Student</th><th data-col=\"1\">Score</th>"
            "<th data-col=\"2\">Result</th><th>Render</th><th>Levels off the reference</th><th>Reasons</th>"
            "</tr></thead><tbody>\n";
    for (const json& s : report.students) page += student_row(s, image_bytes);
    page += "</tbody></table>\n";
    page += kScript;
    return page + "</body></html>\n";
}

}  // namespace m3055::grading
