// What the two pages of `m3055 grade` share (report.html, feedback/NAME.html;
// grade_outputs.h): escaping, numbers, the style sheet and the magnifier.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace m3055::grading::page {

std::string escape_html(const std::string& text);
// A score as the pages show it: "53.12", "100".
std::string score_text(double value);

// The style sheet of both pages (a <style> element).
extern const char* const kStyle;
// The magnifier of both pages (its element and script): a click on an
// <img data-view="render|reference|diff"> inside an element with
// data-student shows it magnified.
extern const char* const kViewer;

// A cell with the image `png` inlined (a data: URI), for the magnifier as
// `view` (render, reference, diff); "&mdash;" when `png` is empty.
std::string inline_image_cell(const std::vector<std::uint8_t>& png, const std::string& alt, const char* view);

// A path relative to the page as a URL path: every byte but ASCII letters,
// digits, '-', '.', '_', '~' and '/' percent-encoded ("students/with%20space.png").
std::string url_path(const std::string& relative);

}  // namespace m3055::grading::page
