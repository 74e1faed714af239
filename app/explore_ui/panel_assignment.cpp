// The side panel's Assignment section (`m3055 explore --assignment`): the
// live score and the reasons `m3055 grade` would give the scene as it is now
// (practice.h computes them with grading::grade_one), and how to submit it.
#include "explore_ui/panels.h"

#include "explore_ui/narrow_panel.h"
#include "explore_ui/widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace m3055::explore {

namespace {

const ImVec4 kGood(0.45f, 0.9f, 0.45f, 1.0f), kBad(1.0f, 0.45f, 0.45f, 1.0f), kStale(0.6f, 0.6f, 0.6f, 1.0f);

// Always two lines: the controls below keep their place when a grade comes in.
void score_line(const PracticeStatus& p) {
    if (!p.graded) {
        ImGui::TextColored(kStale, "grading ...");
        ImGui::TextDisabled(" ");
        return;
    }
    const ImVec4 colour = p.pending ? kStale : p.passed ? kGood : kBad;
    // One line whatever the score: a shorter wording where the panel is narrow
    // (narrow_panel.h), the whole one in its tooltip.
    char full[96], brief[64];
    std::snprintf(full, sizeof full, "Score %g / %g  %s (pass at %g)", p.score, p.max, p.passed ? "PASS" : "FAIL",
                  p.pass_score);
    std::snprintf(brief, sizeof brief, "%g/%g %s (pass %g)", p.score, p.max, p.passed ? "PASS" : "FAIL", p.pass_score);
    const bool fits = ImGui::CalcTextSize(full).x <= ImGui::GetContentRegionAvail().x;
    ImGui::TextColored(colour, "%s", fits ? full : brief);
    if (!fits) tooltip(full);
    // One line on the narrow panel too (three panes at 1280 x 720), so the
    // two lines stay two: the longer wording goes in the tooltip there.
    const bool narrow = narrow_panel();
    if (p.pending) ImGui::TextColored(kStale, narrow ? "edited: regrading soon" : "edited: regraded when the edit settles");
    else ImGui::TextDisabled(narrow ? "graded in %.0f ms" : "graded in %.0f ms (render, compare, rules)", p.grade_ms);
    if (narrow) tooltip(p.pending ? "regraded when the edit settles" : "the time to render, compare and apply the rules");
}

// Every check with its points; a failed one in red with the reason `grade`
// writes (a passed one's in its tooltip). In a box of fixed height (two lines
// a check, the most seen; it scrolls when reasons wrap more), so a regrade
// that passes or fails a check never moves the controls below it.
void check_rows(const PracticeStatus& p) {
    static float reserved = 0.0f;
    const float line = ImGui::GetTextLineHeightWithSpacing();
    reserved = std::max(reserved, line * float(2 * std::max<std::size_t>(p.checks.size(), 1) + 1));
    ImGui::BeginChild("checks", ImVec2(0.0f, reserved), false);
    for (const grading::Check& c : p.checks) {
        ImGui::TextColored(c.ok ? kGood : kBad, "%s %g/%g", c.ok ? "ok  " : "FAIL", c.earned, c.points);
        ImGui::SameLine();
        ImGui::TextWrapped("%s", c.label.c_str());
        if (c.ok && ImGui::IsItemHovered() && !c.reason.empty()) ImGui::SetTooltip("%s", c.reason.c_str());
        if (!c.ok) {
            ImGui::Indent();
            ImGui::PushStyleColor(ImGuiCol_Text, kBad);
            ImGui::TextWrapped("%s", c.reason.c_str());
            ImGui::PopStyleColor();
            ImGui::Unindent();
        }
    }
    // A reason that is no check's (the time budget) stands alone.
    if (p.checks.empty())
        for (const std::string& reason : p.reasons) {
            ImGui::PushStyleColor(ImGuiCol_Text, kBad);
            ImGui::TextWrapped("%s", reason.c_str());
            ImGui::PopStyleColor();
        }
    ImGui::EndChild();
}

}  // namespace

void assignment_section(Explorer& explorer) {
    const PracticeStatus& p = explorer.session.practice;
    ImGui::TextWrapped("%s", p.title.c_str());
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("beside your scene: the reference (%s)", p.reference.c_str());
    ImGui::PopTextWrapPos();
    score_line(p);
    check_rows(p);
    hint("The score and reasons m3055 grade gives this scene (the same code). Save (Ctrl+S, File > Save As) "
         "writes the scene you submit.");
}

}  // namespace m3055::explore
