// The properties the scene-loader fuzzer checks on every input, shared by the
// libFuzzer target (scene_loader_fuzz.cpp, clang only) and the regression test
// (tests/fuzz_regressions_test.cpp, every build), so an input that once broke
// the loader is re-checked by ctest with the same rules.
//
// Input format: a scene file's text, optionally followed by `--set` texts,
// each introduced by the line "#set ":
//     { ...scene JSON... }
//     #set objects[0].material.m=40
//     #set lights[1]={"type": "point", "position": [0, 0, 1]}
// Header-only on purpose: tests/CMakeLists.txt builds each *_test.cpp on its own.
#pragma once

#include "io/message_text.h"
#include "models/model_spec.h"
#include "scene/json_parse.h"
#include "scene/load.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

namespace m3055::fuzz {

inline constexpr const char* kSource = "fuzz.json";
inline constexpr const char* kSetMarker = "\n#set ";

struct FuzzInput {
    std::string scene;              // the scene file's text
    std::vector<std::string> sets;  // each a `--set` argument, "path=value"
};

inline FuzzInput split_input(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::string marker = kSetMarker;
    FuzzInput input;
    std::size_t at = text.find(marker);
    input.scene = text.substr(0, at);
    while (at != std::string::npos) {
        const std::size_t begin = at + marker.size();
        at = text.find(marker, begin);
        input.sets.push_back(text.substr(begin, at == std::string::npos ? std::string::npos : at - begin));
    }
    return input;
}

// "" when every number in `value` is finite, else the JSON path of the first
// one that is not. Walks with an explicit stack: the scene is already
// validated, but this check must not be the thing that overflows.
inline std::string first_non_finite(const nlohmann::json& value) {
    std::vector<std::pair<const nlohmann::json*, std::string>> todo{{&value, "(root)"}};
    while (!todo.empty()) {
        const auto [node, path] = todo.back();
        todo.pop_back();
        if (node->is_number_float() && !std::isfinite(node->get<double>())) return path;
        if (node->is_object())
            for (const auto& item : node->items()) todo.push_back({&item.value(), path + "." + item.key()});
        if (node->is_array())
            for (std::size_t i = 0; i < node->size(); ++i)
                todo.push_back({&(*node)[i], path + "[" + std::to_string(i) + "]"});
    }
    return "";
}

// "" when every double the renderers read is finite and every count and size
// within the documented limits, else what is wrong. The scene's fields are
// listed by hand and each material's parameters come from its model's table
// entry (they are what the GL and reference renderers read); on top of that,
// everything scene_to_json writes is walked, which covers fields added to
// Scene later.
inline std::string check_loaded_scene(const Scene& scene) {
    std::string problem;
    auto finite = [&](double x, const std::string& where) {
        if (problem.empty() && !std::isfinite(x)) problem = where + " is not finite";
    };
    auto finite3 = [&](const dvec3& v, const std::string& where) {
        for (int i = 0; i < 3; ++i) finite(v[i], where + "[" + std::to_string(i) + "]");
    };
    const Display& display = scene.display;
    if (display.width < 1 || display.width > kMaxDisplaySize || display.height < 1 ||
        display.height > kMaxDisplaySize || display.bits < 1 || display.bits > 8)
        return "display out of range";
    finite3(scene.background, "background");
    const Camera& camera = scene.camera;
    finite3(camera.position, "camera.position");
    finite3(camera.target, "camera.target");
    finite3(camera.up, "camera.up");
    finite(camera.fov_y_deg, "camera.fov_y_deg");
    finite(camera.height, "camera.height");
    if (scene.lights.size() > std::size_t(kMaxLights)) return "too many lights";
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        const std::string at = "lights[" + std::to_string(i) + "]";
        finite3(light.direction, at + ".direction");
        finite3(light.position, at + ".position");
        finite3(light.color, at + ".color");
        finite3(light.spot_direction, at + ".spot_direction");
        finite(light.intensity, at + ".intensity");
        finite(light.att_constant, at + ".att_constant");
        finite(light.att_linear, at + ".att_linear");
        finite(light.att_quadratic, at + ".att_quadratic");
        finite(light.spot_exponent, at + ".spot_exponent");
        finite3(light.normal, at + ".normal");
        finite3(light.up, at + ".up");
        // An area light's radiance is a c / area: its area must stay positive and finite.
        if (!(light.size[0] > 0.0 && light.size[1] > 0.0 && light.radius > 0.0) ||
            !std::isfinite(light.size[0] * light.size[1] + light.radius * light.radius))
            return at + ": emitter size out of range";
        if (light.lobes.size() > std::size_t(kMaxLobes)) return at + ": too many lobes";
        for (const Lobe& lobe : light.lobes) {
            finite(lobe.w, at + ".lobes.w");
            finite(lobe.m, at + ".lobes.m");
        }
    }
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& object = scene.objects[i];
        const std::string at = "objects[" + std::to_string(i) + "]";
        finite3(object.center, at + ".center");
        finite(object.radius, at + ".radius");
        if (!(object.radius > 0.0)) return at + ".radius is not positive";
        // Every parameter of the object's model, by its table entry.
        const Material& material = object.material;
        for (const ParamSpec& param : material.model().params) {
            const std::string where = at + ".material." + param.name;
            switch (param.kind) {
                case ParamKind::number: finite(material.number(param.name), where); break;
                case ParamKind::colour:
                case ParamKind::direction: finite3(material.vec3(param.name), where); break;
                case ParamKind::lobes: {
                    const double count = material.values()[std::size_t(param.offset)];  // the stored lobe count
                    if (!(count >= 0.0 && count <= kMaxLobes)) return at + ": too many lobes";
                    for (const Lobe& lobe : material.lobes(param.name)) {
                        finite(lobe.w, where + ".w");
                        finite(lobe.m, where + ".m");
                    }
                    break;
                }
                case ParamKind::choice:
                    if (material.choice(param.name) < 0 || material.choice(param.name) >= int(param.choices.size()))
                        return where + ": choice out of range";
                    break;
                case ParamKind::flag: break;
            }
        }
    }
    if (!problem.empty()) return problem;
    const std::string walked = first_non_finite(scene_to_json(scene, PathWriting::absolute()));
    if (!walked.empty()) return "scene_to_json: " + walked + " is not finite";
    return "";
}

// An error message must be one line of valid UTF-8 without control
// characters (docs/spec.md#7-scene-files); a loader error must start with the file name.
inline std::string check_error_message(const std::string& message, bool names_source) {
    if (!text::is_valid_utf8(message)) return "error message is not valid UTF-8: " + text::escape(message);
    for (const unsigned char c : message)
        if (c < 0x20 || c == 0x7F) return "error message spans lines or holds a control character: " + text::escape(message);
    if (names_source && message.rfind(std::string(kSource) + ": ", 0) != 0)
        return "error message does not name the file: " + message;
    return "";
}

// Runs one input through parse_override, parse_document, apply_overrides and
// scene_from_json (load_scene_file minus the file read), then round-trips the
// scene through scene_to_json. Returns "" when the loader behaved: a finite,
// in-range scene or a SceneError with a one-line message. Anything else (an
// exception of another type, a NaN, a scene that does not reload) is returned
// as a description; crashes, hangs and sanitizer reports are the caller's
// (libFuzzer's, or the test's) to notice.
inline std::string check_scene_input(const std::uint8_t* data, std::size_t size) {
    const FuzzInput input = split_input(data, size);
    std::vector<Override> overrides;
    try {
        for (const std::string& text : input.sets) overrides.push_back(parse_override(text));
    } catch (const SceneError& error) {
        return check_error_message(error.what(), false);
    } catch (const std::exception& error) {
        return std::string("parse_override threw a non-SceneError: ") + error.what();
    }
    Scene scene;
    try {
        nlohmann::json doc = scene_json::parse_document(input.scene, kSource);
        apply_overrides(doc, overrides, kSource);
        scene = scene_from_json(doc, kSource, LoadContext::trusted());
    } catch (const SceneError& error) {
        return check_error_message(error.what(), true);
    } catch (const std::exception& error) {
        return std::string("loader threw a non-SceneError: ") + error.what();
    }
    if (std::string problem = check_loaded_scene(scene); !problem.empty()) return problem;
    // What the explorer saves must load again, to the same scene.
    try {
        const nlohmann::json saved = scene_to_json(scene, PathWriting::absolute());
        const Scene reloaded = scene_from_json(saved, kSource, LoadContext::trusted());
        if (scene_to_json(reloaded, PathWriting::absolute()) != saved)
            return "scene_to_json does not round-trip: " + saved.dump();
    } catch (const std::exception& error) {
        return std::string("a saved scene does not reload: ") + error.what();
    }
    return "";
}

}  // namespace m3055::fuzz
