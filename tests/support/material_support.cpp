#include "material_support.h"

#include "models/model_table.h"

#include "models/model_spec.h"

#include <cstdio>

namespace m3055::test {

namespace {

std::string number_text(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

// A parameter's values as text: "0.5", "(1,0.5,0)", "(w,m)(w,m)", a choice's name.
std::string value_text(const Material& material, const ParamSpec& param) {
    switch (param.kind) {
        case ParamKind::number: return number_text(material.number(param.name));
        case ParamKind::colour:
        case ParamKind::direction: {
            const dvec3 v = material.vec3(param.name);
            return "(" + number_text(v.x) + "," + number_text(v.y) + "," + number_text(v.z) + ")";
        }
        case ParamKind::choice: return material.choice_name(param.name);
        case ParamKind::flag: return material.flag(param.name) ? "true" : "false";
        case ParamKind::lobes: {
            std::string text;
            for (const Lobe& lobe : material.lobes(param.name))
                text += "(" + number_text(lobe.w) + "," + number_text(lobe.m) + ")";
            return text.empty() ? "none" : text;
        }
    }
    return "?";
}

// The parameter's slice of Material::values (what is compared bit for bit).
std::vector<double> slice(const Material& material, const ParamSpec& param) {
    const auto begin = material.values().begin() + param.offset;
    return {begin, begin + param.size};
}

}  // namespace

::testing::AssertionResult same_material(const Material& a, const Material& b) {
    if (&a.model() != &b.model())
        return ::testing::AssertionFailure() << "model " << a.model_name() << " vs " << b.model_name();
    for (const ParamSpec& param : a.model().params)
        if (slice(a, param) != slice(b, param))
            return ::testing::AssertionFailure() << a.model_name() << "." << param.name << ": "
                                                 << value_text(a, param) << " vs " << value_text(b, param);
    return ::testing::AssertionSuccess();
}

std::string describe(const Material& material) {
    std::string text = material.model_name();
    for (const ParamSpec& param : material.model().params) text += " " + param.name + "=" + value_text(material, param);
    return text;
}

std::vector<std::string> builtin_models_of(Family family) {
    std::vector<std::string> names;
    const ModelTable& table = model_table();
    for (int id = 0; id < table.builtin_count(); ++id)
        if (table.at(id).family == family) names.push_back(table.at(id).name);
    return names;
}

}  // namespace m3055::test
