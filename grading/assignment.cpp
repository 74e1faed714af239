#include "grading/assignment.h"

#include "grading/image_input.h"
#include "io/input_file.h"
#include "io/message_text.h"
#include "scene/json_parse.h"
#include "spectral/blackbody.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <nlohmann/json.hpp>

namespace m3055::grading {

namespace {

using nlohmann::json;

// The problems found in one file, each once, in the order found.
class Problems {
public:
    explicit Problems(std::string source) : source_(std::move(source)) {}
    void add(const std::string& field, const std::string& problem) {
        const std::string line = source_ + ": " + field + ": " + problem;
        if (std::find(lines_.begin(), lines_.end(), line) == lines_.end()) lines_.push_back(line);
        fields_.push_back(field);
    }
    // `field` has a problem said already (a rule of no known kind): nothing more is checked in it.
    void mark(const std::string& field) { fields_.push_back(field); }
    const std::vector<std::string>& lines() const { return lines_; }
    const std::vector<std::string>& fields() const { return fields_; }

private:
    std::string source_;
    std::vector<std::string> lines_, fields_;
};

// Reads fields of one JSON object and names the path in every problem; a
// field with a problem reads as its fallback (or its range's low end), so the
// rest of the file is still read and every problem is said at once.
class Fields {
public:
    Fields(const json& node, Problems& problems, std::string path)
        : node_(node), problems_(problems), path_(std::move(path)) {
        if (!node_.is_object()) fail(path_.empty() ? "the file" : path_, "must be an object");
    }
    bool ok() const { return node_.is_object(); }
    void fail(const std::string& field, const std::string& problem) const { problems_.add(field, problem); }
    std::string name(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
    bool has(const std::string& key) const { return ok() && node_.contains(key); }
    // The value at `key`, or nullptr (a missing one said to be required).
    const json* at(const std::string& key) const {
        if (has(key)) return &node_.at(key);
        if (ok()) fail(name(key), "is required");
        return nullptr;
    }
    double number(const std::string& key, double low, double high, std::optional<double> fallback = {}) const {
        if (!has(key) && fallback) return *fallback;
        const json* value = at(key);
        if (!value) return fallback.value_or(low);
        if (!value->is_number()) {
            fail(name(key), "must be a number");
            return fallback.value_or(low);
        }
        const double v = value->get<double>();
        if (!(v >= low && v <= high)) {
            fail(name(key), "must be in [" + text::format_number(low) + ", " + text::format_number(high) + "], got " +
                                text::format_number(v));
            return fallback.value_or(low);
        }
        return v;
    }
    // A count or an index: 2.5 lights or objects[0.5] mean nothing.
    int whole(const std::string& key, int low, int high, std::optional<int> fallback = {}) const {
        const double v = number(key, low, high, fallback ? std::optional<double>(*fallback) : std::nullopt);
        if (v != std::floor(v)) {
            fail(name(key), "must be a whole number, got " + text::format_number(v));
            return fallback.value_or(low);
        }
        return int(v);
    }
    std::string string(const std::string& key, std::optional<std::string> fallback = {}) const {
        if (!has(key) && fallback) return *fallback;
        const json* value = at(key);
        if (!value) return fallback.value_or("");
        if (!value->is_string() || value->get<std::string>().empty()) {
            fail(name(key), "must be a non-empty string");
            return fallback.value_or("");
        }
        return value->get<std::string>();
    }
    void only(std::initializer_list<const char*> keys) const {
        if (!ok()) return;
        for (const auto& item : node_.items()) {
            bool known = false;
            for (const char* key : keys) known = known || item.key() == key;
            if (!known) fail(name(text::cut_end(item.key())), "is not a field here");
        }
    }

private:
    const json& node_;
    Problems& problems_;
    std::string path_;
};

constexpr RuleKind kRuleKinds[] = {RuleKind::model, RuleKind::light_count, RuleKind::warmer,
                                   RuleKind::key_to_fill, RuleKind::eq14, RuleKind::range,
                                   RuleKind::temperature, RuleKind::equals, RuleKind::shadow};

constexpr LightType kLightTypes[] = {LightType::directional, LightType::point, LightType::spot,
                                     LightType::rect,        LightType::disk,  LightType::sky};

// light_count's "type": a light type of the scene format, as a scene's lights spell it.
LightType light_type(const Fields& fields, const std::string& key) {
    const std::string type = fields.string(key);
    if (type.empty()) return LightType::directional;  // said already
    std::string known;
    for (LightType t : kLightTypes) {
        if (type == to_string(t)) return t;
        known += (known.empty() ? "" : ", ") + std::string(to_string(t));
    }
    fields.fail(fields.name(key), "unknown light type " + text::quote(type) + " (" + known + ")");
    return LightType::directional;
}

std::optional<RuleKind> rule_kind(const Fields& fields, const std::string& key) {
    const std::string kind = fields.string(key);
    if (kind.empty()) return std::nullopt;  // said already
    for (RuleKind k : kRuleKinds)
        if (kind == to_string(k)) return k;
    std::string known;
    for (RuleKind k : kRuleKinds) known += (known.empty() ? "" : ", ") + std::string(to_string(k));
    fields.fail(fields.name(key), "unknown rule " + text::quote(kind) + " (" + known + ")");
    return std::nullopt;
}

// `equals`' value: a string or a boolean. A number is a range rule's: a
// decimal must equal to the last bit (0.1 + 0.2 is not 0.3).
json equals_value(const Fields& f) {
    const json* value = f.at("value");
    if (!value) return json();
    if (value->is_string() || value->is_boolean()) return *value;
    f.fail(f.name("value"), value->is_number()
                                ? "must be a string or true/false; for a number use a \"range\" rule (min = max)"
                                : "must be a string or true/false");
    return json();
}

// A rule that is not an object or of no known kind is read as far as its
// points (so that "pass" is checked against the right maximum), `known`
// false: nothing else of it can be checked.
Rule load_rule(const json& node, Problems& problems, std::size_t index, bool& known) {
    const std::string path = "rules[" + std::to_string(index) + "]";
    const Fields f(node, problems, path);
    Rule rule;
    rule.label = path;
    known = false;
    if (!f.ok()) return rule;
    const std::optional<RuleKind> kind = rule_kind(f, "rule");
    rule.points = f.number("points", 0, 1e6);
    if (!kind) return rule;
    known = true;
    rule.kind = *kind;
    rule.label = f.string("name", path + " (" + to_string(rule.kind) + ")");
    switch (rule.kind) {
        case RuleKind::model:
            f.only({"rule", "name", "points", "is", "object"});
            rule.text = f.string("is");
            rule.object = f.whole("object", 0, 99999, -1);
            break;
        case RuleKind::light_count:
            f.only({"rule", "name", "points", "equals", "type"});
            rule.min = rule.max = f.whole("equals", 0, 16);
            rule.of_type = f.has("type");
            if (rule.of_type) rule.light_type = light_type(f, "type");
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
            rule.object = f.whole("object", 0, 99999);
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
        case RuleKind::equals:
            f.only({"rule", "name", "points", "path", "value"});
            rule.text = f.string("path");
            rule.value = equals_value(f);
            break;
        case RuleKind::shadow:
            f.only({"rule", "name", "points", "light"});
            rule.text = f.string("light");
            break;
    }
    return rule;
}

std::string more_problems(std::size_t count) {
    return " (and " + std::to_string(count) + (count == 1 ? " more problem" : " more problems") +
           ": m3055 grade --check lists them)";
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
        case RuleKind::equals: return "equals";
        case RuleKind::shadow: return "shadow";
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

AssignmentError::AssignmentError(std::vector<std::string> lines)
    : std::runtime_error(lines.empty()        ? std::string("the assignment has an error")
                         : lines.size() == 1 ? lines.front()
                                             : lines.front() + more_problems(lines.size() - 1)),
      lines_(std::move(lines)) {}

bool AssignmentRead::has_error_at(const std::string& field) const {
    for (const std::string& bad : bad_fields)
        if (bad == field || (bad.size() > field.size() && bad.compare(0, field.size(), field) == 0 &&
                             (bad[field.size()] == '.' || bad[field.size()] == '[')))
            return true;
    return false;
}

AssignmentRead read_assignment_json(const std::string& text, const std::string& path) {
    const std::string source = text::quote_name(path);
    AssignmentRead out;
    Assignment& a = out.assignment;
    a.path = path;
    json doc;
    try {
        doc = scene_json::parse_document(text, source);
    } catch (const std::exception& e) {
        out.errors = {e.what()};
        out.bad_fields = {""};
        return out;
    }
    Problems problems(source);
    const auto done = [&]() {
        out.errors = problems.lines();
        out.bad_fields = problems.fields();
        return out;
    };
    const Fields top(doc, problems, "");
    if (!top.ok()) return done();
    // A scene given where the assignment goes (an easy slip with grade --check):
    // say so, rather than that its first key is not a field here.
    if (!top.has("reference") && (top.has("objects") || top.has("lights"))) {
        top.fail(top.has("objects") ? "objects" : "lights",
                 "this is a scene, not an assignment (an assignment names its \"reference\" scene: docs/grading.md)");
        return done();
    }
    top.only({"title", "reference", "start", "image", "rules", "pass", "time_budget"});
    a.title = top.string("title", std::string("Assignment"));
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (const std::string reference = top.string("reference"); !reference.empty())
        a.reference = (folder / reference).string();
    if (top.has("start"))
        if (const std::string start = top.string("start"); !start.empty()) a.start = (folder / start).string();
    if (top.has("image")) {
        const Fields image(*top.at("image"), problems, "image");
        image.only({"points", "fail_levels", "fail_percent", "zero_percent", "region"});
        const std::string region = image.string("region", std::string("all"));
        if (region != "all" && region != "objects" && !region.empty())
            image.fail("image.region", "must be \"all\" or \"objects\", got " + text::quote(region));
        a.image_objects_only = region == "objects";
        a.image_points = image.number("points", 0, 1e6);
        a.image_tolerance.fail = {image.whole("fail_levels", 0, 255, 0), image.number("fail_percent", 0, 100, 0.0)};
        if (image.has("zero_percent")) {
            const std::size_t before = problems.fields().size();
            a.image_zero_percent = image.number("zero_percent", 0, 100);
            if (problems.fields().size() == before && a.image_zero_percent <= a.image_tolerance.fail.percent) {
                image.fail("image.zero_percent", "must be more than image.fail_percent (" +
                                                     text::format_number(a.image_tolerance.fail.percent) + "), got " +
                                                     text::format_number(a.image_zero_percent));
                a.image_zero_percent = 0;
            }
        }
    }
    if (a.image_objects_only && !a.reference.empty() && input_kind(a.reference) != InputKind::scene)
        top.fail("image.region", "\"objects\" needs a scene as the reference (its objects say which pixels count)");
    if (top.has("rules")) {
        const json& rules = *top.at("rules");
        if (!rules.is_array()) top.fail("rules", "must be an array");
        else
            for (std::size_t i = 0; i < rules.size(); ++i) {
                bool known = false;
                a.rules.push_back(load_rule(rules[i], problems, i, known));
                if (!known) problems.mark("rules[" + std::to_string(i) + "]");
            }
    }
    a.pass_score = top.number("pass", 0, a.max_score(), a.max_score());
    a.time_budget_s = top.number("time_budget", 0, 3600, 30.0);
    // 0 is no budget at all: one hostile scene could hold the whole run.
    if (!(a.time_budget_s > 0)) {
        top.fail("time_budget", "must be in (0, 3600] seconds, got 0");
        a.time_budget_s = 30;
    }
    return done();
}

AssignmentRead read_assignment(const std::string& path) {
    try {
        return read_assignment_json(io::read_input_file(path), path);
    } catch (const io::InputError& e) {
        AssignmentRead out;
        out.assignment.path = path;
        out.errors = {e.what()};
        out.bad_fields = {""};
        return out;
    }
}

Assignment assignment_from_json(const std::string& text, const std::string& path) {
    AssignmentRead read = read_assignment_json(text, path);
    if (!read.errors.empty()) throw AssignmentError(std::move(read.errors));
    return std::move(read.assignment);
}

Assignment load_assignment(const std::string& path) {
    AssignmentRead read = read_assignment(path);
    if (!read.errors.empty()) throw AssignmentError(std::move(read.errors));
    return std::move(read.assignment);
}

}  // namespace m3055::grading
