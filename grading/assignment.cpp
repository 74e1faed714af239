#include "grading/assignment.h"

#include "grading/image_input.h"
#include "io/input_file.h"
#include "io/message_text.h"
#include "scene/json_parse.h"
#include "spectral/blackbody.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <nlohmann/json.hpp>

namespace m3055::grading {

namespace {

using nlohmann::json;

// Reads fields of one JSON object and names the path in every error.
class Fields {
public:
    Fields(const json& node, std::string source, std::string path)
        : node_(node), source_(std::move(source)), path_(std::move(path)) {
        if (!node_.is_object()) fail(path_.empty() ? "the file" : path_, "must be an object");
    }
    [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
        throw AssignmentError(source_ + ": " + field + ": " + problem);
    }
    std::string name(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
    bool has(const std::string& key) const { return node_.contains(key); }
    const json& at(const std::string& key) const {
        if (!has(key)) fail(name(key), "is required");
        return node_.at(key);
    }
    double number(const std::string& key, double low, double high, std::optional<double> fallback = {}) const {
        if (!has(key) && fallback) return *fallback;
        const json& value = at(key);
        if (!value.is_number()) fail(name(key), "must be a number");
        const double v = value.get<double>();
        if (!(v >= low && v <= high))
            fail(name(key), "must be in [" + text::format_number(low) + ", " + text::format_number(high) + "], got " +
                                text::format_number(v));
        return v;
    }
    std::string string(const std::string& key, std::optional<std::string> fallback = {}) const {
        if (!has(key) && fallback) return *fallback;
        const json& value = at(key);
        if (!value.is_string() || value.get<std::string>().empty()) fail(name(key), "must be a non-empty string");
        return value.get<std::string>();
    }
    void only(std::initializer_list<const char*> keys) const {
        for (const auto& item : node_.items()) {
            bool known = false;
            for (const char* key : keys) known = known || item.key() == key;
            if (!known) fail(name(text::cut_end(item.key())), "is not a field here");
        }
    }

private:
    const json& node_;
    std::string source_, path_;
};

RuleKind rule_kind(const Fields& fields, const std::string& key) {
    const std::string kind = fields.string(key);
    for (RuleKind k : {RuleKind::model, RuleKind::light_count, RuleKind::warmer, RuleKind::key_to_fill,
                       RuleKind::eq14, RuleKind::range, RuleKind::temperature})
        if (kind == to_string(k)) return k;
    fields.fail(fields.name(key), "unknown rule " + text::quote(kind) +
                                      " (model, light_count, warmer, key_to_fill, eq14, range, temperature)");
}

Rule load_rule(const json& node, const std::string& source, std::size_t index) {
    const std::string path = "rules[" + std::to_string(index) + "]";
    const Fields f(node, source, path);
    Rule rule;
    rule.kind = rule_kind(f, "rule");
    rule.label = f.string("name", path + " (" + to_string(rule.kind) + ")");
    rule.points = f.number("points", 0, 1e6);
    switch (rule.kind) {
        case RuleKind::model:
            f.only({"rule", "name", "points", "is", "object"});
            rule.text = f.string("is");
            rule.object = int(f.number("object", 0, 99999, -1.0));
            break;
        case RuleKind::light_count:
            f.only({"rule", "name", "points", "equals"});
            rule.min = rule.max = f.number("equals", 0, 16);
            break;
        case RuleKind::warmer:
            f.only({"rule", "name", "points", "light", "than"});
            rule.text = f.string("light");
            rule.other = f.string("than");
            break;
        case RuleKind::key_to_fill:
            f.only({"rule", "name", "points", "min", "max"});
            rule.min = f.number("min", 0, 1e12);
            rule.max = f.number("max", rule.min, 1e12);
            break;
        case RuleKind::eq14:
            f.only({"rule", "name", "points", "object", "within_percent"});
            rule.object = int(f.number("object", 0, 99999));
            rule.max = f.number("within_percent", 0, 100);
            break;
        case RuleKind::range:
            f.only({"rule", "name", "points", "path", "min", "max"});
            rule.text = f.string("path");
            rule.min = f.number("min", -1e12, 1e12);
            rule.max = f.number("max", rule.min, 1e12);
            break;
        case RuleKind::temperature:  // kelvin, within what a light's "temperature_k" may be
            f.only({"rule", "name", "points", "light", "min", "max"});
            rule.text = f.string("light");
            rule.min = f.number("min", spectral::kMinKelvin, spectral::kMaxKelvin);
            rule.max = f.number("max", rule.min, spectral::kMaxKelvin);
            break;
    }
    return rule;
}

}  // namespace

const char* to_string(RuleKind kind) {
    switch (kind) {
        case RuleKind::model: return "model";
        case RuleKind::light_count: return "light_count";
        case RuleKind::warmer: return "warmer";
        case RuleKind::key_to_fill: return "key_to_fill";
        case RuleKind::eq14: return "eq14";
        case RuleKind::range: return "range";
        case RuleKind::temperature: return "temperature";
    }
    return "?";
}

double Assignment::max_score() const {
    double total = image_points;
    for (const Rule& rule : rules) total += rule.points;
    // To the hundredth, as scores are (grade.cpp: total): 40 + 0.1 + 0.2 is
    // 40.3, so a full score passes the default "pass" (the maximum).
    return std::round(total * 100.0) / 100.0;
}

Assignment assignment_from_json(const std::string& text, const std::string& path) {
    const std::string source = text::quote_name(path);
    const json doc = scene_json::parse_document(text, source);
    const Fields top(doc, source, "");
    // A scene given where the assignment goes (an easy slip with grade --check):
    // say so, rather than that its first key is not a field here.
    if (!top.has("reference") && (top.has("objects") || top.has("lights")))
        top.fail(top.has("objects") ? "objects" : "lights",
                 "this is a scene, not an assignment (an assignment names its \"reference\" scene: docs/grading.md)");
    top.only({"title", "reference", "start", "image", "rules", "pass", "time_budget"});
    Assignment a;
    a.path = path;
    a.title = top.string("title", std::string("Assignment"));
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    a.reference = (folder / top.string("reference")).string();
    if (top.has("start")) a.start = (folder / top.string("start")).string();
    if (top.has("image")) {
        const Fields image(top.at("image"), source, "image");
        image.only({"points", "fail_levels", "fail_percent", "zero_percent", "region"});
        const std::string region = image.string("region", std::string("all"));
        if (region != "all" && region != "objects")
            image.fail("image.region", "must be \"all\" or \"objects\", got " + text::quote(region));
        a.image_objects_only = region == "objects";
        a.image_points = image.number("points", 0, 1e6);
        a.image_tolerance.fail = {int(image.number("fail_levels", 0, 255, 0.0)),
                                  image.number("fail_percent", 0, 100, 0.0)};
        if (image.has("zero_percent")) {
            a.image_zero_percent = image.number("zero_percent", 0, 100);
            if (a.image_zero_percent <= a.image_tolerance.fail.percent)
                image.fail("image.zero_percent", "must be more than image.fail_percent (" +
                                                     text::format_number(a.image_tolerance.fail.percent) + "), got " +
                                                     text::format_number(a.image_zero_percent));
        }
    }
    if (a.image_objects_only && input_kind(a.reference) != InputKind::scene)
        top.fail("image.region", "\"objects\" needs a scene as the reference (its objects say which pixels count)");
    if (top.has("rules")) {
        const json& rules = top.at("rules");
        if (!rules.is_array()) top.fail("rules", "must be an array");
        for (std::size_t i = 0; i < rules.size(); ++i) a.rules.push_back(load_rule(rules[i], source, i));
    }
    a.pass_score = top.number("pass", 0, a.max_score(), a.max_score());
    a.time_budget_s = top.number("time_budget", 0, 3600, 30.0);
    // 0 is no budget at all: one hostile scene could hold the whole run.
    if (!(a.time_budget_s > 0)) top.fail("time_budget", "must be in (0, 3600] seconds, got 0");
    return a;
}

Assignment load_assignment(const std::string& path) {
    try {
        return assignment_from_json(io::read_input_file(path), path);
    } catch (const io::InputError& e) {
        throw AssignmentError(e.what());
    }
}

}  // namespace m3055::grading
