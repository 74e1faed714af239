#include "grading/assignment_check.h"

#include "brdf_file/brdf_model.h"
#include "grading/image_input.h"
#include "grading/rules.h"
#include "io/message_text.h"
#include "models/model_table.h"
#include "scene/load.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace m3055::grading {

namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
    return out.empty() ? "none" : out;
}

std::vector<std::string> builtin_model_names() {
    std::vector<std::string> out;
    for (const ModelSpec& spec : model_table().models())
        if (!find_brdf_model(spec)) out.push_back(spec.name);
    return out;
}

std::vector<std::string> light_names(const Scene& scene) {
    std::vector<std::string> out;
    for (const Light& light : scene.lights)
        if (!light.name.empty()) out.push_back(text::quote(light.name));
    return out;
}

bool has_light(const Scene& scene, const std::string& name) {
    for (const Light& light : scene.lights)
        if (light.name == name) return true;
    return false;
}

// "no light named "Key" in the reference scene (its lights: ...)", and when
// one differs only by case, that light names are case-sensitive.
std::string no_light_text(const Scene& scene, const std::string& name) {
    const std::string out = "no light named " + text::quote(name) + " in the reference scene (its lights: " +
                            joined(light_names(scene)) + ")";
    for (const Light& light : scene.lights)
        if (same_but_case(light.name, name)) return out + "; light names are case-sensitive";
    return out;
}

std::string kind_of(const nlohmann::json& value) {
    if (value.is_string()) return "a string";
    if (value.is_boolean()) return "true/false";
    if (value.is_number()) return "a number";
    return value.is_array() ? "a list" : "an object";
}

// Whether `line` is an error about `field` ("FILE: rules[1]: ..." or "FILE: rules[1].object: ...").
bool about(const std::string& line, const std::string& source, const std::string& field) {
    const std::string start = source + ": " + field;
    return line.compare(0, start.size(), start) == 0 && line.size() > start.size() &&
           (line[start.size()] == '.' || line[start.size()] == ':');
}

std::string objects_text(std::size_t count) {
    return std::to_string(count) + (count == 1 ? " object" : " objects");
}

}  // namespace

AssignmentCheck check_assignment(const AssignmentRead& read, const LoadContext& context) {
    const Assignment& a = read.assignment;
    AssignmentCheck out;
    out.errors = read.errors;
    const std::string source = text::quote_name(a.path);
    const auto error = [&](const std::string& field, const std::string& problem) {
        const std::string line = source + ": " + field + ": " + problem;
        if (std::find(out.errors.begin(), out.errors.end(), line) == out.errors.end()) out.errors.push_back(line);
    };
    const std::vector<std::string> models = builtin_model_names();
    int bits = 5;  // an image reference is read as the M3055's 5 bits
    std::optional<Scene> scene;
    if (!a.reference.empty()) try {
            if (input_kind(a.reference) == InputKind::scene) {
                scene = load_scene_file(a.reference, context);
                bits = scene->display.bits;
                out.reference_is_scene = true;
            } else {
                read_level_image(a.reference, bits);
            }
        } catch (const std::exception& e) {
            error("reference", text::one_line(e.what()));
            out.reference_unreadable = true;
        }
    // The explorer's starting scene must load as a student's would.
    if (!a.start.empty()) try {
            load_scene_file(a.start, context);
        } catch (const std::exception& e) {
            error("start", text::one_line(e.what()));
        }
    // The image check: a tolerance every render meets makes its points a gift.
    const int top_level = (1 << bits) - 1;
    if (a.image_points > 0 && a.image_tolerance.fail.levels >= top_level && !read.has_error_at("image.fail_levels"))
        error("image.fail_levels", std::to_string(a.image_tolerance.fail.levels) + " allows every difference on the " +
                                       "reference's " + std::to_string(bits) + "-bit display (at most " +
                                       std::to_string(top_level) + " levels): every render would pass; at most " +
                                       std::to_string(top_level - 1));
    if (a.image_points > 0 && a.image_tolerance.fail.percent >= 100 && !read.has_error_at("image.fail_percent"))
        error("image.fail_percent", "100 lets every render pass; less than 100");
    if (scene && a.image_objects_only && scene->objects.empty())
        error("image.region", "\"objects\" with a reference scene without objects: no pixel would be compared");
    const nlohmann::json document = scene ? scene_to_json(*scene, PathWriting::absolute()) : nlohmann::json();
    bool unknown_model = false;
    for (std::size_t i = 0; i < a.rules.size(); ++i) {
        const Rule& rule = a.rules[i];
        const std::string field = "rules[" + std::to_string(i) + "]";
        if (read.has_error_at(field)) continue;  // said once, as the read's error
        if (rule.kind == RuleKind::model &&
            std::find(models.begin(), models.end(), rule.text) == models.end()) {
            error(field + ".is", "unknown model " + text::quote(rule.text) + ": not one of the model names below");
            unknown_model = true;
        }
        if (!scene) continue;  // an image reference: nothing to resolve the rest in
        const bool has_object = rule.kind == RuleKind::model || rule.kind == RuleKind::eq14;
        if (has_object && rule.object >= int(scene->objects.size()))
            error(field + ".object", "no objects[" + std::to_string(rule.object) + "] in the reference scene (it has " +
                                         objects_text(scene->objects.size()) + ")");
        if ((rule.kind == RuleKind::temperature || rule.kind == RuleKind::shadow) && !has_light(*scene, rule.text))
            error(field + ".light", no_light_text(*scene, rule.text));
        if (rule.kind == RuleKind::warmer) {
            if (!has_light(*scene, rule.text)) error(field + ".light", no_light_text(*scene, rule.text));
            if (!has_light(*scene, rule.other)) error(field + ".than", no_light_text(*scene, rule.other));
        }
        if (rule.kind == RuleKind::key_to_fill && (!has_light(*scene, "key") || !has_light(*scene, "fill")))
            error(field, "key_to_fill compares the lights named \"key\" and \"fill\" (case-sensitive); the reference "
                         "scene's lights are " + joined(light_names(*scene)));
        if (rule.kind == RuleKind::range || rule.kind == RuleKind::equals) {
            const nlohmann::json* value = find_scene_value(document, rule.text);
            const std::string path = text::quote(rule.text, text::kMaxPathBytes);
            if (!value)
                error(field + ".path", path + " is not in the reference scene");
            else if (rule.kind == RuleKind::range && !value->is_number())
                error(field + ".path", path + " is not a number in the reference scene");
            else if (rule.kind == RuleKind::equals && value->type() != rule.value.type())
                error(field + ".value", std::string(rule.value.is_string() ? "a string" : "true/false") + ", but " +
                                            path + " is " + kind_of(*value) + " in the reference scene");
        }
    }
    if (unknown_model) out.notes.push_back("model names: " + joined(models));
    // The reference graded against the rules: the teacher's own answer.
    out.reference_score = a.image_points;
    if (scene)
        for (std::size_t i = 0; i < a.rules.size(); ++i) {
            const Rule& rule = a.rules[i];
            const std::string field = "rules[" + std::to_string(i) + "]";
            if (read.has_error_at(field)) continue;  // not read whole: nothing to grade
            const Check check = check_rule(rule, *scene, document);
            out.reference_score += check.earned;
            // A rule with an error is said once, as the error, not again as failed.
            bool said = false;
            for (const std::string& line : out.errors) said = said || about(line, source, field);
            if (!check.ok && rule.points > 0 && !said)
                out.reference_fails.push_back(source + ": " + rule.label + ": the reference fails it: " + check.reason);
        }
    out.reference_score = std::round(out.reference_score * 100.0) / 100.0;
    return out;
}

}  // namespace m3055::grading
