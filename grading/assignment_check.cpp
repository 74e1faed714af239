#include "grading/assignment_check.h"

#include "brdf_file/brdf_model.h"
#include "grading/image_input.h"
#include "grading/rules.h"
#include "io/message_text.h"
#include "models/model_table.h"
#include "scene/load.h"

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

std::string objects_text(std::size_t count) {
    return std::to_string(count) + (count == 1 ? " object" : " objects");
}

}  // namespace

AssignmentCheck check_assignment(const Assignment& a, const LoadContext& context) {
    AssignmentCheck out;
    const std::string source = text::quote_name(a.path);
    const auto error = [&](const std::string& field, const std::string& problem) {
        out.errors.push_back(source + ": " + field + ": " + problem);
    };
    const std::vector<std::string> models = builtin_model_names();
    int bits = 5;  // an image reference is read as the M3055's 5 bits
    std::optional<Scene> scene;
    if (input_kind(a.reference) == InputKind::scene) {
        scene = load_scene_file(a.reference, context);
        bits = scene->display.bits;
        out.reference_is_scene = true;
    }
    // The image check: a tolerance every render meets makes its points a gift.
    const int top_level = (1 << bits) - 1;
    if (a.image_points > 0 && a.image_tolerance.fail.levels >= top_level)
        error("image.fail_levels", std::to_string(a.image_tolerance.fail.levels) + " allows every difference on the " +
                                       "reference's " + std::to_string(bits) + "-bit display (at most " +
                                       std::to_string(top_level) + " levels): every render would pass; at most " +
                                       std::to_string(top_level - 1));
    if (a.image_points > 0 && a.image_tolerance.fail.percent >= 100)
        error("image.fail_percent", "100 lets every render pass; less than 100");
    if (scene && a.image_objects_only && scene->objects.empty())
        error("image.region", "\"objects\" with a reference scene without objects: no pixel would be compared");
    const nlohmann::json document = scene ? scene_to_json(*scene, PathWriting::absolute()) : nlohmann::json();
    for (std::size_t i = 0; i < a.rules.size(); ++i) {
        const Rule& rule = a.rules[i];
        const std::string field = "rules[" + std::to_string(i) + "]";
        if (rule.kind == RuleKind::model) {
            bool known = false;
            for (const std::string& name : models) known = known || name == rule.text;
            if (!known)
                error(field + ".is", "unknown model " + text::quote(rule.text) + " (" +
                                         text::cut_end(joined(models), 200) + ")");
        }
        if (!scene) continue;  // an image reference: nothing to resolve the rest in
        const bool has_object = rule.kind == RuleKind::model || rule.kind == RuleKind::eq14;
        if (has_object && rule.object >= int(scene->objects.size()))
            error(field + ".object", "no objects[" + std::to_string(rule.object) + "] in the reference scene (it has " +
                                         objects_text(scene->objects.size()) + ")");
        if (rule.kind == RuleKind::temperature && !has_light(*scene, rule.text))
            error(field + ".light", "no light named " + text::quote(rule.text) + " in the reference scene (its lights: " +
                                        joined(light_names(*scene)) + ")");
        if (rule.kind == RuleKind::warmer) {
            if (!has_light(*scene, rule.text))
                error(field + ".light", "no light named " + text::quote(rule.text) + " in the reference scene (its lights: " +
                                            joined(light_names(*scene)) + ")");
            if (!has_light(*scene, rule.other))
                error(field + ".than", "no light named " + text::quote(rule.other) + " in the reference scene (its lights: " +
                                           joined(light_names(*scene)) + ")");
        }
        if (rule.kind == RuleKind::key_to_fill && (!has_light(*scene, "key") || !has_light(*scene, "fill")))
            error(field, "key_to_fill compares the lights named \"key\" and \"fill\"; the reference scene's lights are " +
                             joined(light_names(*scene)));
        if (rule.kind == RuleKind::range) {
            const nlohmann::json* value = find_scene_value(document, rule.text);
            if (!value)
                error(field + ".path", text::quote(rule.text, text::kMaxPathBytes) + " is not in the reference scene");
            else if (!value->is_number())
                error(field + ".path", text::quote(rule.text, text::kMaxPathBytes) + " is not a number in the reference scene");
        }
    }
    // The reference graded against the rules: the teacher's own answer.
    out.reference_score = a.image_points;
    if (scene)
        for (const Rule& rule : a.rules) {
            const Check check = check_rule(rule, *scene, document);
            out.reference_score += check.earned;
            if (!check.ok && rule.points > 0)
                out.reference_fails.push_back(source + ": " + rule.label + ": the reference fails it: " + check.reason);
        }
    out.reference_score = std::round(out.reference_score * 100.0) / 100.0;
    return out;
}

}  // namespace m3055::grading
