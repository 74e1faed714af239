// The rule vocabulary of grading (grading/rules.h) and the
// assignment loader: each rule passes and fails on a crafted scene, with the
// one-line reason; a malformed assignment is one line naming the field.
#include "grading/assignment.h"
#include "grading/grade.h"
#include "grading/grade_outputs.h"
#include "grading/rules.h"
#include "grading/submissions.h"
#include "scene/load.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace m3055;
using namespace m3055::grading;

namespace {

// The worked assignment's reference: gold metal sphere (eq. 14 holds exactly),
// warm key a = 1, white fill a = 0.3, back a = 0.7.
nlohmann::json reference_doc() {
    return nlohmann::json::parse(test::read_text(test::source_path("assignments/three-point/reference.json")));
}

Check check(const std::string& rule_json, const nlohmann::json& doc) {
    const std::string assignment = R"({"reference": "r.json", "rules": [)" + rule_json + "]}";
    const Assignment a = assignment_from_json(assignment, "a.json");
    const Scene scene = scene_from_json(doc, "s.json", LoadContext::trusted());
    return check_rule(a.rules.at(0), scene, scene_to_json(scene, PathWriting::absolute()));
}

}  // namespace

TEST(GradeRules, ModelPassesAndFails) {
    nlohmann::json doc = reference_doc();
    EXPECT_TRUE(check(R"({"rule": "model", "is": "metal", "points": 1})", doc).ok);
    const Check wrong = check(R"({"rule": "model", "is": "metal_blinn", "object": 0, "points": 1})", doc);
    EXPECT_FALSE(wrong.ok);
    EXPECT_EQ(wrong.reason, "objects[0] is metal, not metal_blinn");
    EXPECT_EQ(check(R"({"rule": "model", "is": "metal", "object": 3, "points": 1})", doc).reason,
              "no objects[3] (the scene has 1 object)");
}

TEST(GradeRules, LightCountCountsEnabledLights) {
    nlohmann::json doc = reference_doc();
    EXPECT_TRUE(check(R"({"rule": "light_count", "equals": 3, "points": 1})", doc).ok);
    doc["lights"][2]["enabled"] = false;
    const Check two = check(R"({"rule": "light_count", "equals": 3, "points": 1})", doc);
    EXPECT_FALSE(two.ok);
    EXPECT_EQ(two.reason, "2 lights enabled, not 3");
}

// With "type", only lights of that type count: "one rect softbox" is a light_count of rects.
TEST(GradeRules, LightCountCountsLightsOfATypeWhenItNamesOne) {
    nlohmann::json doc = reference_doc();
    const std::string one_rect = R"({"rule": "light_count", "equals": 1, "type": "rect", "points": 1})";
    const Check none = check(one_rect, doc);
    EXPECT_FALSE(none.ok);
    EXPECT_EQ(none.reason, "0 rect lights enabled, not 1");
    EXPECT_EQ(check(R"({"rule": "light_count", "equals": 3, "type": "directional", "points": 1})", doc).reason,
              "3 directional lights enabled");
    doc["lights"][0] = {{"name", "key"}, {"type", "rect"}, {"position", {2, 2, 2}}, {"normal", {-1, -1, -1}},
                        {"size", {1, 0.5}}, {"intensity", 2}};
    const Check rect = check(one_rect, doc);
    EXPECT_TRUE(rect.ok);
    EXPECT_EQ(rect.reason, "1 rect light enabled");
    EXPECT_EQ(check(R"({"rule": "light_count", "equals": 3, "points": 1})", doc).reason, "3 lights enabled")
        << "without a type every light counts";
    doc["lights"][0]["enabled"] = false;
    EXPECT_EQ(check(one_rect, doc).reason, "0 rect lights enabled, not 1");
    doc["lights"][0]["enabled"] = true;
    doc["lights"][0]["intensity"] = 0;
    EXPECT_FALSE(check(one_rect, doc).ok) << "a light of intensity 0 is no light";
}

TEST(GradeRules, ShadowWantsTheNamedLightToCastShadows) {
    nlohmann::json doc = reference_doc();
    const std::string rule = R"({"rule": "shadow", "light": "key", "points": 1})";
    const Check none = check(rule, doc);
    EXPECT_FALSE(none.ok);
    EXPECT_EQ(none.reason, "\"key\" casts no shadows (its \"shadow\" is false)");
    doc["lights"][0]["shadow"] = true;
    const Check casts = check(rule, doc);
    EXPECT_TRUE(casts.ok);
    EXPECT_EQ(casts.reason, "\"key\" casts shadows");
    doc["lights"][0]["enabled"] = false;
    EXPECT_EQ(check(rule, doc).reason, "\"key\" is off (disabled or of intensity 0): it casts no shadows");
    EXPECT_EQ(check(R"({"rule": "shadow", "light": "Key", "points": 1})", doc).reason,
              "no light named \"Key\" (names are case-sensitive: the scene has \"key\")");
}

TEST(GradeRules, WarmerComparesRedMinusBlue) {
    nlohmann::json doc = reference_doc();
    const std::string rule = R"({"rule": "warmer", "light": "key", "than": "fill", "points": 1})";
    EXPECT_TRUE(check(rule, doc).ok);
    doc["lights"][0]["color"] = {1, 1, 1};  // as warm as the fill: not warmer
    EXPECT_FALSE(check(rule, doc).ok);
    doc["lights"][0].erase("name");
    EXPECT_EQ(check(rule, doc).reason, "no light named \"key\"");
}

// Kelvin lights (docs/spec.md#71-spectral-lights): two black bodies compare by
// temperature; a kelvin light against an RGB one by its spectrum's red - blue.
TEST(GradeRules, WarmerUnderstandsKelvinLights) {
    nlohmann::json doc = reference_doc();
    const std::string rule = R"({"rule": "warmer", "light": "key", "than": "fill", "points": 1})";
    doc["lights"][0].erase("color");
    doc["lights"][1].erase("color");
    doc["lights"][0]["temperature_k"] = 3200;
    doc["lights"][1]["temperature_k"] = 5600;
    const Check studio = check(rule, doc);
    EXPECT_TRUE(studio.ok);
    EXPECT_EQ(studio.reason, "\"key\" is warmer than \"fill\" (3200 K against 5600 K)");
    doc["lights"][0]["temperature_k"] = 6500;
    EXPECT_EQ(check(rule, doc).reason, "\"key\" is not warmer than \"fill\" (6500 K against 5600 K)");
    // 6500 K against an RGB fill that is orange: the fill is warmer.
    doc["lights"][1].erase("temperature_k");
    doc["lights"][1]["color"] = {1, 0.6, 0.3};
    EXPECT_FALSE(check(rule, doc).ok);
    // 2000 K (R - B about 2.5 at luminance 1) against the same orange fill (0.7).
    doc["lights"][0]["temperature_k"] = 2000;
    EXPECT_TRUE(check(rule, doc).ok);
}

TEST(GradeRules, TemperatureWantsAKelvinLightInRange) {
    nlohmann::json doc = reference_doc();
    const std::string rule = R"({"rule": "temperature", "light": "key", "min": 3000, "max": 3400, "points": 1})";
    const Check rgb = check(rule, doc);
    EXPECT_FALSE(rgb.ok);
    EXPECT_EQ(rgb.reason, "\"key\" has no \"temperature_k\" (an RGB colour), wanted [3000 K, 3400 K]");
    doc["lights"][0].erase("color");
    doc["lights"][0]["temperature_k"] = 3200;
    const Check ok = check(rule, doc);
    EXPECT_TRUE(ok.ok);
    EXPECT_EQ(ok.reason, "\"key\" is 3200 K, within [3000 K, 3400 K]");
    doc["lights"][0]["temperature_k"] = 5600;
    EXPECT_EQ(check(rule, doc).reason, "\"key\" is 5600 K, not within [3000 K, 3400 K]");
    doc["lights"][0].erase("temperature_k");
    doc["lights"][0]["illuminant"] = "A";
    EXPECT_EQ(check(rule, doc).reason, "\"key\" has no \"temperature_k\" (illuminant A), wanted [3000 K, 3400 K]");
    EXPECT_EQ(check(R"({"rule": "temperature", "light": "sun", "min": 3000, "max": 3400, "points": 1})", doc).reason,
              "no light named \"sun\"");
}

TEST(GradeRules, KeyToFillUsesTheExplorersRatio) {
    nlohmann::json doc = reference_doc();
    // Y(key) = 0.2126 + 0.7152 * 0.82 + 0.0722 * 0.6 = 0.842384, fill 0.3, facing the camera at
    // (0, 0.3, 6): cos 0.605461 for the key (1, 1, 1), 0.706259 for the fill (-1, 0.2, 1): 2.4072:1.
    const Check ok = check(R"({"rule": "key_to_fill", "min": 2, "max": 4, "points": 1})", doc);
    EXPECT_TRUE(ok.ok) << ok.reason;
    EXPECT_EQ(ok.reason.rfind("key-to-fill 2.41:1", 0), 0u) << ok.reason;
    // The edges are inclusive: a range ending just below the ratio fails.
    EXPECT_FALSE(check(R"({"rule": "key_to_fill", "min": 2, "max": 2.407, "points": 1})", doc).ok);
    EXPECT_TRUE(check(R"({"rule": "key_to_fill", "min": 2, "max": 2.4072, "points": 1})", doc).ok);
    doc["lights"][1]["intensity"] = 0.65;
    EXPECT_FALSE(check(R"({"rule": "key_to_fill", "min": 2, "max": 4, "points": 1})", doc).ok);
}

TEST(GradeRules, Eq14WithinPercent) {
    nlohmann::json doc = reference_doc();  // d + 0.013/0.04 + 0.1/0.16 = 1 exactly
    const std::string rule = R"({"rule": "eq14", "object": 0, "within_percent": 1, "points": 1})";
    EXPECT_TRUE(check(rule, doc).ok);
    doc["objects"][0]["material"]["d"] = 0.0595;  // 0.95 % over: passes
    EXPECT_TRUE(check(rule, doc).ok);
    doc["objects"][0]["material"]["d"] = 0.0605;  // 1.05 % over: fails
    EXPECT_FALSE(check(rule, doc).ok);
    doc["objects"][0]["material"] = {{"model", "highlight"}, {"color", {1, 0, 0}}};
    EXPECT_EQ(check(rule, doc).reason, "objects[0] is highlight, not a metal model");
}

TEST(GradeRules, RangeFindsDefaultsAndMissingPaths) {
    nlohmann::json doc = reference_doc();
    EXPECT_TRUE(check(R"({"rule": "range", "path": "objects[0].material.d", "min": 0, "max": 0.1, "points": 1})", doc).ok);
    EXPECT_FALSE(check(R"({"rule": "range", "path": "lights[1].intensity", "min": 0.5, "max": 1, "points": 1})", doc).ok);
    // The default of an unwritten field is what the scene means, so it counts.
    doc["lights"][1].erase("intensity");
    EXPECT_TRUE(check(R"({"rule": "range", "path": "lights[1].intensity", "min": 1, "max": 1, "points": 1})", doc).ok);
    EXPECT_EQ(check(R"({"rule": "range", "path": "objects[4].radius", "min": 0, "max": 1, "points": 1})", doc).reason,
              "objects[4].radius: not in the scene");
}

// "equals" holds a string (or true/false) at a path: an RGB "gold" is not
// the measured metal, and a light given by its colour has no illuminant.
TEST(GradeRules, EqualsComparesTheStringAtAPath) {
    nlohmann::json doc = reference_doc();
    const std::string gold =
        R"({"rule": "equals", "path": "objects[0].material.conductor", "value": "gold", "points": 1})";
    const Check rgb = check(gold, doc);  // the worked reference: an RGB gold
    EXPECT_FALSE(rgb.ok);
    EXPECT_EQ(rgb.reason, "objects[0].material.conductor: not in the scene, wanted \"gold\"");
    doc["objects"][0]["material"].erase("color");
    doc["objects"][0]["material"]["conductor"] = "gold";
    const Check measured = check(gold, doc);
    EXPECT_TRUE(measured.ok) << measured.reason;
    EXPECT_EQ(measured.reason, "objects[0].material.conductor is \"gold\"");
    doc["objects"][0]["material"]["conductor"] = "copper";
    EXPECT_EQ(check(gold, doc).reason, "objects[0].material.conductor is \"copper\", not \"gold\"");
    EXPECT_TRUE(check(R"({"rule": "equals", "path": "objects[0].material.model", "value": "metal", "points": 1})", doc).ok);
    doc["lights"][0].erase("color");
    doc["lights"][0]["illuminant"] = "A";
    EXPECT_TRUE(check(R"({"rule": "equals", "path": "lights[0].illuminant", "value": "A", "points": 1})", doc).ok);
    EXPECT_EQ(check(R"({"rule": "equals", "path": "lights[1].illuminant", "value": "A", "points": 1})", doc).reason,
              "lights[1].illuminant: not in the scene, wanted \"A\"");
    EXPECT_TRUE(check(R"({"rule": "equals", "path": "lights[1].enabled", "value": true, "points": 1})", doc).ok);
    EXPECT_EQ(check(R"({"rule": "equals", "path": "lights[0].name", "value": "Key", "points": 1})", doc).reason,
              "lights[0].name is \"key\", not \"Key\" (values are case-sensitive)");
}

// Light names are compared exactly; a name that differs only by case says so.
TEST(GradeRules, LightNamesAreCaseSensitiveAndTheReasonSaysSo) {
    nlohmann::json doc = reference_doc();
    doc["lights"][0]["name"] = "Key";
    EXPECT_EQ(check(R"({"rule": "warmer", "light": "key", "than": "fill", "points": 1})", doc).reason,
              "no light named \"key\" (names are case-sensitive: the scene has \"Key\")");
    EXPECT_EQ(check(R"({"rule": "temperature", "light": "FILL", "min": 3000, "max": 3400, "points": 1})", doc).reason,
              "no light named \"FILL\" (names are case-sensitive: the scene has \"fill\")");
}

// A count or an index is a whole number: "equals": 2.5 lights is refused, not read as 2.
TEST(GradeAssignment, CountsIndicesAndLevelsMustBeWholeNumbers) {
    const auto lines = [](const std::string& text) {
        try {
            assignment_from_json(text, "a.json");
        } catch (const AssignmentError& e) {
            return e.lines();
        }
        return std::vector<std::string>{};
    };
    EXPECT_EQ(lines(R"({"reference": "r.json", "rules": [{"rule": "light_count", "equals": 2.5, "points": 1}]})"),
              std::vector<std::string>{"a.json: rules[0].equals: must be a whole number, got 2.5"});
    EXPECT_EQ(lines(R"({"reference": "r.json", "rules": [{"rule": "model", "is": "metal", "object": 0.5, "points": 1}]})"),
              std::vector<std::string>{"a.json: rules[0].object: must be a whole number, got 0.5"});
    EXPECT_EQ(lines(R"({"reference": "r.json", "image": {"points": 1, "fail_levels": 1.5}})"),
              std::vector<std::string>{"a.json: image.fail_levels: must be a whole number, got 1.5"});
    EXPECT_EQ(lines(R"({"reference": "r.json", "rules": [{"rule": "equals", "path": "display.bits", "value": 5, "points": 1}]})"),
              std::vector<std::string>{"a.json: rules[0].value: must be a string or true/false; for a number use a "
                                       "\"range\" rule (min = max)"});
    EXPECT_EQ(assignment_from_json(R"({"reference": "r.json", "rules": [{"rule": "light_count", "equals": 3.0, "points": 1}]})",
                                   "a.json").rules[0].min, 3);
}

// Every problem of the file at once, in the order read, each once; what() is
// the first and a count of the rest.
TEST(GradeAssignment, EveryProblemIsReportedAtOnceEachOnce) {
    try {
        assignment_from_json(R"({"reference": "r.json", "extra": 1, "image": {"points": -1, "fail_levels": 1.5},
                                "rules": [{"rule": "colour", "points": 1}, "x",
                                          {"rule": "model", "points": 1, "is": "metal", "object": -1, "also": 2}],
                                "time_budget": 0})",
                             "a.json");
        FAIL() << "no error";
    } catch (const AssignmentError& e) {
        const std::vector<std::string> expected = {
            "a.json: extra: is not a field here",
            "a.json: image.points: must be in [0, 1000000], got -1",
            "a.json: image.fail_levels: must be a whole number, got 1.5",
            "a.json: rules[0].rule: unknown rule \"colour\" (model, light_count, warmer, key_to_fill, eq14, range, "
            "temperature, equals, shadow)",
            "a.json: rules[1]: must be an object",
            "a.json: rules[2].also: is not a field here",
            "a.json: rules[2].object: must be in [0, 99999], got -1",
            "a.json: time_budget: must be in (0, 3600] seconds, got 0"};
        EXPECT_EQ(e.lines(), expected);
        EXPECT_EQ(std::string(e.what()), expected[0] + " (and 7 more problems: m3055 grade --check lists them)");
    }
}

TEST(GradeAssignment, ErrorsNameTheField) {
    const auto error = [](const std::string& text) {
        try {
            assignment_from_json(text, "a.json");
        } catch (const std::exception& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error(R"({})"), "a.json: reference: is required");
    EXPECT_EQ(error(R"({"reference": "r.json", "rules": [{"rule": "colour", "points": 1}]})"),
              "a.json: rules[0].rule: unknown rule \"colour\" (model, light_count, warmer, key_to_fill, eq14, range, "
              "temperature, equals, shadow)");
    EXPECT_EQ(error(R"({"reference": "r.json", "rules": [{"rule": "light_count", "equals": 1, "type": "square",
                                                          "points": 1}]})"),
              "a.json: rules[0].type: unknown light type \"square\" (directional, point, spot, rect, disk, sky)");
    EXPECT_EQ(error(R"({"reference": "r.json", "rules": [{"rule": "light_count", "equals": 1, "type": 3, "points": 1}]})"),
              "a.json: rules[0].type: must be a non-empty string");
    EXPECT_EQ(error(R"({"reference": "r.json", "rules": [{"rule": "light_count", "equals": 1, "type": "Rect",
                                                          "points": 1}]})"),
              "a.json: rules[0].type: unknown light type \"Rect\" (directional, point, spot, rect, disk, sky)");
    EXPECT_EQ(error(R"({"reference": "r.json", "rules": [{"rule": "shadow", "points": 1}]})"),
              "a.json: rules[0].light: is required");
    EXPECT_EQ(error(R"({"reference": "r.json", "rules": [{"rule": "shadow", "light": "key", "type": "rect", "points": 1}]})"),
              "a.json: rules[0].type: is not a field here");
    EXPECT_EQ(error(R"({"reference": "r.json", "rules": [{"rule": "shadow", "light": "", "points": 1}]})"),
              "a.json: rules[0].light: must be a non-empty string");
    EXPECT_EQ(error(R"({"reference": "r.json", "rules": [{"rule": "temperature", "light": "key", "min": 500,
                                                          "max": 3400, "points": 1}]})"),
              "a.json: rules[0].min: must be in [1000, 40000], got 500");
    EXPECT_EQ(error(R"({"reference": "r.json", "rules": [{"rule": "eq14", "object": 0, "within_percent": 1}]})"),
              "a.json: rules[0].points: is required");
    EXPECT_EQ(error(R"({"reference": "r.json", "image": {"points": 10, "fail_levels": -1}})"),
              "a.json: image.fail_levels: must be in [0, 255], got -1");
    EXPECT_EQ(error(R"({"reference": "r.json", "extra": 1})"), "a.json: extra: is not a field here");
    EXPECT_EQ(error(R"({"background": [0, 0, 0], "objects": [], "lights": []})"),
              "a.json: objects: this is a scene, not an assignment (an assignment names its \"reference\" scene: "
              "docs/grading.md)");
    EXPECT_EQ(error(R"({"reference": "r.json", "image": {"points": 10}, "pass": 11})"),
              "a.json: pass: must be in [0, 10], got 11");
}

// "start" (the explorer's starting scene) is optional and, like the reference, relative to the assignment.
TEST(GradeAssignment, StartIsOptionalAndBesideTheAssignment) {
    EXPECT_EQ(assignment_from_json(R"({"reference": "r.json"})", "hw/a.json").start, "");
    EXPECT_EQ(assignment_from_json(R"({"reference": "r.json", "start": "s.json"})", "hw/a.json").start, "hw/s.json");
    EXPECT_THROW(assignment_from_json(R"({"reference": "r.json", "start": ""})", "a.json"), std::exception);
}

// Partial credit for the image: full up to fail_percent, none from zero_percent, linear between.
TEST(GradeScore, ImagePartialCreditFallsLinearlyToZeroPercent) {
    const std::string image = R"("image": {"points": 40, "fail_levels": 1, "fail_percent": 1)";
    const Assignment partial = assignment_from_json(R"({"reference": "r.json", )" + image + R"(, "zero_percent": 9}})", "a.json");
    const Assignment whole = assignment_from_json(R"({"reference": "r.json", )" + image + "}}", "a.json");
    const Scene scene = scene_from_json(reference_doc(), "s.json", LoadContext::trusted());
    LevelImage reference;
    reference.width = 100;
    reference.height = 1;
    reference.levels.assign(300, 3);
    const auto with_off = [&](int pixels) {  // `pixels` of 100 two levels off
        LevelImage render = reference;
        for (int p = 0; p < pixels; ++p) render.levels[3 * std::size_t(p)] = 5;
        return render;
    };
    EXPECT_EQ(grade_scene(partial, scene, reference, with_off(1)).checks[0].earned, 40);  // 1 %: allowed
    const Grade half = grade_scene(partial, scene, reference, with_off(5));                // 5 %: (9 - 5) / (9 - 1)
    EXPECT_EQ(half.checks[0].earned, 20);
    EXPECT_FALSE(half.checks[0].ok);
    EXPECT_NE(half.reasons()[0].find(": 20 of 40 points (none at 9 %)"), std::string::npos) << half.reasons()[0];
    EXPECT_EQ(grade_scene(partial, scene, reference, with_off(9)).checks[0].earned, 0);
    EXPECT_EQ(grade_scene(whole, scene, reference, with_off(5)).checks[0].earned, 0);  // all or nothing without it
    EXPECT_THROW(assignment_from_json(R"({"reference": "r.json", )" + image + R"(, "zero_percent": 1}})", "a.json"),
                 AssignmentError);
}

TEST(GradeScore, PointsAddUpAndPassNeedsThePassScore) {
    const Assignment a = assignment_from_json(
        R"({"reference": "r.json", "image": {"points": 40},
            "rules": [{"rule": "light_count", "equals": 3, "points": 10}, {"rule": "light_count", "equals": 2, "points": 5}],
            "pass": 50})",
        "a.json");
    const Scene scene = scene_from_json(reference_doc(), "s.json", LoadContext::trusted());
    LevelImage image;
    image.width = image.height = 2;
    image.levels.assign(12, 3);
    const Grade grade = grade_scene(a, scene, image, image);
    EXPECT_EQ(grade.score, 50);
    EXPECT_EQ(grade.max, 55);
    EXPECT_TRUE(grade.passed);
    ASSERT_EQ(grade.reasons().size(), 1u);
    EXPECT_EQ(grade.reasons()[0], "rules[1] (light_count): 3 lights enabled, not 2");
    const Grade broken = broken_grade(a, "x", "x.json: invalid JSON");
    EXPECT_EQ(broken.score, 0);
    EXPECT_FALSE(broken.passed);
}

TEST(GradeShards, EveryItemInExactlyOneShard) {
    std::vector<Submission> all(11);
    for (std::size_t i = 0; i < all.size(); ++i) all[i].student = std::to_string(i);
    std::size_t total = 0;
    for (int k = 1; k <= 4; ++k) total += take_shard(all, {k, 4}).size();
    EXPECT_EQ(total, 11u);
    EXPECT_EQ(take_shard(all, {2, 4})[1].student, "5");
    EXPECT_THROW(parse_shard("0/4"), std::invalid_argument);
    EXPECT_THROW(parse_shard("5/4"), std::invalid_argument);
    EXPECT_THROW(parse_shard("1/4x"), std::invalid_argument);
    EXPECT_EQ(parse_shard("3/4").k, 3);
}

TEST(GradeOutputs, NamesAndReasonsAreEscapedInHtmlAndCsv) {
    GradeReport report;
    report.assignment = {{"title", "<T>"}, {"max", 10}, {"pass", 5}, {"reference_image", "reference.png"}};
    report.students.push_back({{"student", "<b>x&y</b>"},
                               {"score", 0},
                               {"max", 10},
                               {"passed", false},
                               {"reasons", {"=cmd(), \"quoted\"\nsecond line"}},
                               {"broken", "x"},
                               {"checks", nlohmann::json::array()},
                               {"images", nullptr}});
    const std::string html = report_html(report, [](const std::string&) { return std::optional<ImageSize>{}; });
    EXPECT_EQ(html.find("<b>x"), std::string::npos);
    EXPECT_NE(html.find("&lt;b&gt;x&amp;y&lt;/b&gt;"), std::string::npos);
    EXPECT_NE(html.find("<title>&lt;T&gt;: grades</title>"), std::string::npos);
    const std::string csv = grades_csv(report);
    // One record: the newline stays inside quotes, the formula is defused, quotes doubled.
    EXPECT_EQ(csv, "student,score,max,result,reasons,notes\n<b>x&y</b>,0,10,refused,\"'=cmd(), \"\"quoted\"\"\nsecond line\",\n");
}

TEST(GradeOutputs, Base64) {
    EXPECT_EQ(base64({}), "");
    EXPECT_EQ(base64({'M'}), "TQ==");
    EXPECT_EQ(base64({'M', 'a'}), "TWE=");
    EXPECT_EQ(base64({'M', 'a', 'n'}), "TWFu");
}
