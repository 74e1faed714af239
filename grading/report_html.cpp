// report.html of `m3055 grade` (grade_outputs.h): one page a teacher opens
// from disk or prints, beside the images it shows (students/, diffs/,
// reference.png): a class of 1000 is a page of 1.5 MB, not one of 55 MB with
// every image inlined. Pixelated scaling keeps the display's dots visible.
#include "grading/grade_outputs.h"

#include "grading/diff_image.h"
#include "grading/page_parts.h"
#include "grading/score_histogram.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace m3055::grading {

namespace {

using nlohmann::json;
using page::escape_html;
using page::score_text;
using page::kStyle;
using page::kViewer;

// Click a header to sort by that column; numbers numerically (data-sort).
// The filter (all / not passed / fail / refused / missing) and the search box hide rows.
constexpr const char* kScript = R"(<script>
function m3055filter(){var f=document.getElementById('filter').value,q=document.getElementById('search').value.toLowerCase();
[].forEach.call(document.querySelectorAll('#grades tbody tr'),function(r){
var ok=(f==='all'||r.dataset.status===f||(f==='not-passed'&&r.dataset.status!=='pass'))&&r.cells[0].textContent.toLowerCase().indexOf(q)>=0;
r.classList.toggle('hidden',!ok);});
var n=document.querySelectorAll('#grades tbody tr:not(.hidden)').length;document.getElementById('shown').textContent=n+(n===1?' row':' rows');}
document.getElementById('filter').addEventListener('change',m3055filter);
document.getElementById('search').addEventListener('input',m3055filter);
m3055filter();
document.querySelectorAll('th[data-col]').forEach(function(th){th.addEventListener('click',function(){
var col=+th.dataset.col,body=document.querySelector('#grades tbody'),rows=[].slice.call(body.rows);
var dir=th.dataset.dir==='asc'?-1:1;th.dataset.dir=dir===1?'asc':'desc';
rows.sort(function(a,b){var x=a.cells[col].dataset.sort,y=b.cells[col].dataset.sort;
var nx=parseFloat(x),ny=parseFloat(y);var r=isNaN(nx)||isNaN(ny)?x.localeCompare(y):nx-ny;return dir*r;});
rows.forEach(function(r){body.appendChild(r);});});});
</script>
)";

// An <img> of the output folder's file `name`: loaded when it nears the view
// (`lazy`), its size known before (the row's height does not jump), for the
// magnifier as `view` (render, reference, diff); "" when it is not there.
std::string linked_image(const std::string& name, const ImageSizes& image_size, const std::string& alt,
                         const char* view, bool lazy, const std::string& attributes = "") {
    const std::optional<ImageSize> size = name.empty() ? std::nullopt : image_size(name);
    if (!size) return "";
    return "<img " + attributes + "alt=\"" + escape_html(alt) + "\" data-view=\"" + view + "\" width=\"" +
           std::to_string(size->width) + "\" height=\"" +
           std::to_string(size->height) + "\"" + (lazy ? " loading=\"lazy\" decoding=\"async\"" : "") + " src=\"" +
           escape_html(page::url_path(name)) + "\">";
}

std::string image_cell(const std::string& name, const ImageSizes& image_size, const std::string& alt, const char* view) {
    const std::string image = linked_image(name, image_size, alt, view, true);
    return image.empty() ? "<td>&mdash;</td>" : "<td>" + image + "</td>";
}

std::string student_row(const json& s, const std::vector<std::string>& labels, const ImageSizes& image_size) {
    const std::string name = s["student"].get<std::string>();
    const double score = s["score"].get<double>();
    const std::string status = result_of(s);
    std::string row = "<tr data-status=\"" + status + "\" data-student=\"" + escape_html(name) + "\"><td class=\"name\" data-sort=\"" + escape_html(name) + "\">" +
                      escape_html(name) + "</td>";
    row += "<td class=\"num\" data-sort=\"" + score_text(score) + "\">" + score_text(score) + " / " +
           score_text(s["max"].get<double>()) + "</td>";
    row += "<td data-sort=\"" + status + "\" class=\"result " + status + "\">" + status + "</td>";
    // One column a check: passed or not, and the points.
    for (const std::string& label : labels) {
        const json* found = nullptr;
        for (const json& c : s["checks"])
            if (c["label"] == label) found = &c;
        if (!found) {
            row += "<td class=\"check\" data-sort=\"-1\">&mdash;</td>";
            continue;
        }
        const bool ok = (*found)["ok"].get<bool>();
        row += std::string("<td class=\"check ") + (ok ? "ok" : "no") + "\" data-sort=\"" +
               score_text((*found)["earned"].get<double>()) + "\" title=\"" +
               escape_html((*found)["reason"].get<std::string>()) + "\">" + (ok ? "&#10004; " : "&#10008; ") +
               score_text((*found)["earned"].get<double>()) + "/" + score_text((*found)["points"].get<double>()) + "</td>";
    }
    const bool images = s["images"].is_object();
    row += image_cell(images ? s["images"]["render"].get<std::string>() : "", image_size, name + ": render", "render") +
           image_cell(images ? s["images"]["diff"].get<std::string>() : "", image_size, name + ": difference", "diff");
    row += "<td class=\"reasons\" data-sort=\"\"><ul>";
    for (const json& reason : s["reasons"]) row += "<li>" + escape_html(reason.get<std::string>()) + "</li>";
    if (s["reasons"].empty()) row += "<li>all checks passed</li>";
    if (s.contains("notes"))
        for (const json& note : s["notes"]) row += "<li class=\"note\">note: " + escape_html(note.get<std::string>()) + "</li>";
    return row + "</ul></td></tr>\n";
}

// The checks' labels, in the assignment's order (the first graded student's).
std::vector<std::string> check_labels(const GradeReport& report) {
    std::vector<std::string> labels;
    for (const json& s : report.students)
        if (s["checks"].is_array() && !s["checks"].empty()) {
            for (const json& c : s["checks"]) labels.push_back(c["label"].get<std::string>());
            break;
        }
    return labels;
}

std::string percent_text(std::size_t part, std::size_t whole) {
    if (whole == 0) return "&mdash;";
    char out[32];
    std::snprintf(out, sizeof out, "%.0f %%", 100.0 * double(part) / double(whole));
    return out;
}

// The class at a glance: counts, mean, median, pass rate, each check's pass rate.
std::string class_summary(const GradeReport& report, const std::vector<std::string>& labels, const std::string& reference_figure) {
    std::size_t graded = 0, refused = 0, missing = 0, passed = 0, failed = 0;
    std::vector<double> scores;
    std::map<std::string, std::size_t> check_passed, check_total;
    for (const json& s : report.students) {
        if (s.value("missing", false)) {
            ++missing;
            continue;
        }
        scores.push_back(s["score"].get<double>());
        passed += s["passed"].get<bool>() ? 1 : 0;
        if (!s["broken"].get<std::string>().empty()) {
            ++refused;
            continue;
        }
        ++graded;
        failed += s["passed"].get<bool>() ? 0 : 1;
        for (const json& c : s["checks"]) {
            ++check_total[c["label"].get<std::string>()];
            check_passed[c["label"].get<std::string>()] += c["ok"].get<bool>() ? 1 : 0;
        }
    }
    double mean = 0, median = 0;
    if (!scores.empty()) {
        for (double v : scores) mean += v;
        mean = std::round(mean / double(scores.size()) * 100.0) / 100.0;
        std::sort(scores.begin(), scores.end());
        const std::size_t n = scores.size();
        median = n % 2 ? scores[n / 2] : (scores[n / 2 - 1] + scores[n / 2]) / 2.0;
        median = std::round(median * 100.0) / 100.0;
    }
    const json& a = report.assignment;
    const HistogramSvg histogram = score_histogram_svg(scores, a["max"].get<double>(), a["pass"].get<double>());
    std::string out = "<section id=\"summary\"><h2>Class summary</h2><div id=\"top\"><div><table><tbody>\n";
    const auto row = [&](const std::string& id, const std::string& name, const std::string& value) {
        out += "<tr><th>" + name + "</th><td class=\"num\" id=\"" + id + "\">" + value + "</td></tr>\n";
    };
    row("count-graded", "graded", std::to_string(graded));
    row("count-failed", "fail (graded, below the pass score)", std::to_string(failed));
    row("count-refused", "refused (not graded: the submission could not be; 0 points)", std::to_string(refused));
    row("count-missing", "missing (on the roster, no submission)", std::to_string(missing));
    row("mean", "mean score (of the submissions)", scores.empty() ? "&mdash;" : score_text(mean));
    row("median", "median score", scores.empty() ? "&mdash;" : score_text(median));
    row("pass-rate", "passed", std::to_string(passed) + " of " + std::to_string(scores.size()) + " (" +
                                   percent_text(passed, scores.size()) + ")");
    out += "</tbody></table>\n</div>";
    // The scores' distribution (gnuplot's SVG inline), or one line saying why not.
    out += histogram.svg.empty() ? "<p id=\"histogram\" class=\"note\">" + escape_html(histogram.problem) + "</p>\n"
                                 : "<figure id=\"histogram\">" + histogram.svg + "<figcaption>Scores of the " +
                                       std::to_string(scores.size()) + (scores.size() == 1 ? " submission" : " submissions") +
                                       "</figcaption></figure>\n";
    out += reference_figure + "<table id=\"check-rates\"><thead><tr><th>check</th><th>passed (of the graded)</th></tr>"
           "</thead><tbody>\n";
    for (const std::string& label : labels)
        out += "<tr><td>" + escape_html(label) + "</td><td class=\"num\">" + std::to_string(check_passed[label]) +
               " of " + std::to_string(check_total[label]) + " (" + percent_text(check_passed[label], check_total[label]) +
               ")</td></tr>\n";
    return out + "</tbody></table></div></section>\n";
}

// The difference image's legend again in the column's header, for the
// thumbnails (the image's own legend is readable at the feedback page's and
// the magnifier's sizes, not at a thumbnail's).
std::string html_legend() {
    static const char* const labels[kDiffClasses] = {"0", "1", "2", "3", "4-7", "8+"};
    static const int levels_off[kDiffClasses] = {0, 1, 2, 3, 4, 8};  // one of each class
    std::string out;
    for (int k = 0; k < kDiffClasses; ++k) {
        std::uint8_t rgb[3];
        diff_colour(levels_off[k], rgb);
        char colour[8];
        std::snprintf(colour, sizeof colour, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
        out += std::string("<span class=\"swatch\" style=\"background:") + colour + "\"></span>" + labels[k];
    }
    return out;
}

// A list open on the page when short; a long one (a class that hands in one
// template) folded, so the grades stay near the top.
const char* open_if_short(const json& list) { return list.size() <= 10 ? " open" : ""; }

// What the class folder held that was not graded, and byte-identical submissions.
std::string folder_sections(const json& folder) {
    std::string out;
    if (!folder["ignored"].empty()) {
        out += std::string("<details id=\"ignored\"") + open_if_short(folder["ignored"]) + "><summary>Not graded: " + std::to_string(folder["ignored"].size()) +
               (folder["ignored"].size() == 1 ? " entry" : " entries") + " of the submissions folder</summary><ul>\n";
        for (const json& entry : folder["ignored"])
            out += "<li><code>" + escape_html(entry["name"].get<std::string>()) + "</code>: " +
                   escape_html(entry["why"].get<std::string>()) + "</li>\n";
        out += "</ul></details>\n";
    }
    if (!folder["identical"].empty()) {
        out += std::string("<details id=\"identical\"") + open_if_short(folder["identical"]) + "><summary>Byte-identical submissions: " +
               std::to_string(folder["identical"].size()) + (folder["identical"].size() == 1 ? " group" : " groups") +
               " (information, no penalty)</summary><ul>\n";
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

std::string report_html(const GradeReport& report, const ImageSizes& image_size) {
    const json& a = report.assignment;
    const std::string title = a["title"].get<std::string>();
    std::map<std::string, std::size_t> results;  // pass, fail, refused, missing
    for (const json& s : report.students) ++results[result_of(s)];
    const std::size_t missing = results["missing"], submitted = report.students.size() - missing;
    std::string page = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" +
                       escape_html(title) + ": grades</title>\n" + kStyle + "</head><body>\n";
    page += "<h1>" + escape_html(title) + "</h1>\n<p>" + std::to_string(submitted) +
            (submitted == 1 ? " submission: " : " submissions: ") + std::to_string(results["pass"]) +
            " passed (at least " + score_text(a["pass"].get<double>()) + " of " + score_text(a["max"].get<double>()) +
            " points), " + std::to_string(results["fail"]) + " failed, " + std::to_string(results["refused"]) +
            " refused (not graded)" +
            (missing ? "; " + std::to_string(missing) + " on the roster with no submission" : std::string()) +
            ". Click a column's header to sort, a picture to magnify it.</p>\n";
    const std::string reference = linked_image(a["reference_image"].get<std::string>(), image_size, "reference",
                                               "reference", false, "id=\"reference-image\" ");
    const std::string reference_figure =
        reference.empty() ? std::string() : "<figure>" + reference + "<figcaption>The reference</figcaption></figure>\n";
    const std::vector<std::string> labels = check_labels(report);
    page += class_summary(report, labels, reference_figure);
    page += folder_sections(report.folder);
    page += "<div id=\"controls\"><label>Show <select id=\"filter\"><option value=\"all\">all</option>"
            "<option value=\"not-passed\">not passed</option><option value=\"fail\">fail</option>"
            "<option value=\"refused\">refused</option>"
            "<option value=\"missing\">missing</option></select></label> "
            "<label>Search <input id=\"search\" type=\"search\" placeholder=\"student name\"></label> "
            "<span id=\"shown\"></span></div>\n";
    page += "<table id=\"grades\"><thead><tr><th data-col=\"0\">Student</th><th data-col=\"1\">Score</th>"
            "<th data-col=\"2\">Result</th>";
    for (std::size_t i = 0; i < labels.size(); ++i)
        page += "<th data-col=\"" + std::to_string(3 + i) + "\">" + escape_html(labels[i]) + "</th>";
    page += "<th>Render (click to magnify)</th><th>Levels off the reference<br>" + html_legend() +
            "</th><th>Reasons</th></tr></thead><tbody>\n";
    for (const json& s : report.students) page += student_row(s, labels, image_size);
    page += "</tbody></table>\n";
    page += kScript;
    page += kViewer;
    return page + "</body></html>\n";
}

}  // namespace m3055::grading

