#include "analysis/brdf_target.h"

#include "brdf_file/brdf_model.h"
#include "models/model_table.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace m3055 {

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The table parameter a user's NAME means (a .brdf file's name, or the model's own).
const ParamSpec& param_named(const Material& m, const std::string& name) {
    const ModelSpec& spec = m.model();
    std::string field = name;
    if (const BrdfModel* file = find_brdf_model(spec)) field = file->field(name).empty() ? name : file->field(name);
    const ParamSpec* p = spec.find(field);
    if (!p || p->kind == ParamKind::lobes)
        throw std::runtime_error("--set " + name + ": not a parameter of " + spec.label);
    return *p;
}

void apply_setting(Material& m, const std::string& setting, std::set<std::string>& pinned) {
    const auto eq = setting.find('=');
    if (eq == std::string::npos || eq == 0) throw std::runtime_error("--set " + setting + ": expected NAME=VALUE");
    const std::string name = setting.substr(0, eq), text = setting.substr(eq + 1);
    const ParamSpec& p = param_named(m, name);
    const nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
    const std::string where = "--set " + name + ": ";
    switch (p.kind) {
        case ParamKind::number:
            if (!value.is_number() || !p.range.contains(value.get<double>()))
                throw std::runtime_error(where + "must be a number " + p.range.text() + ", got " + text);
            m.set_number(p.name, value.get<double>());
            break;
        case ParamKind::colour:
        case ParamKind::direction: {
            if (!value.is_array() || value.size() != 3 || !value[0].is_number() || !value[1].is_number() ||
                !value[2].is_number())
                throw std::runtime_error(where + "must be [x, y, z], got " + text);
            m.set_vec3(p.name, {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()});
            break;
        }
        case ParamKind::flag:
            if (!value.is_boolean()) throw std::runtime_error(where + "must be true or false, got " + text);
            m.set_flag(p.name, value.get<bool>());
            break;
        case ParamKind::choice: {
            const auto it = std::find(p.choices.begin(), p.choices.end(), text);
            if (it == p.choices.end()) throw std::runtime_error(where + "not one of its choices: " + text);
            m.set_choice(p.name, int(it - p.choices.begin()));
            break;
        }
        case ParamKind::lobes: break;
    }
    pinned.insert(p.name);
}

}  // namespace

BrdfTarget brdf_target(const std::string& target, const std::vector<std::string>& settings) {
    const ModelSpec* spec = nullptr;
    std::string name = target;
    if (ends_with(target, ".brdf")) {
        try {
            spec = load_brdf_model(target).spec;
        } catch (const BrdfError& e) {
            throw std::runtime_error(e.what());
        }
    } else {
        spec = model_table().find(target);
        if (!spec || spec->family == Family::brdf) throw std::runtime_error("no model named \"" + target + "\" (nor a .brdf file)");
    }
    if (spec->family == Family::translucent) throw std::runtime_error(target + ": a translucent model is not a BRDF");
    BrdfTarget out{Material(*spec), name, {}};
    for (const std::string& setting : settings) apply_setting(out.material, setting, out.pinned);
    return out;
}

std::vector<Material> parameter_corners(const BrdfTarget& target) {
    std::vector<const ParamSpec*> free;
    for (const ParamSpec& p : target.material.model().params)
        if ((p.kind == ParamKind::number || p.kind == ParamKind::flag) && !target.pinned.count(p.name)) free.push_back(&p);
    const auto set_end = [](Material& m, const ParamSpec& p, bool high) {
        if (p.kind == ParamKind::flag) m.set_flag(p.name, high);
        else {
            // An open end: the nearest value inside; an unbounded one: left at its value.
            double x = high ? p.range.hi : p.range.lo;
            if (high ? p.range.hi_open : p.range.lo_open) x = std::nextafter(x, high ? p.range.lo : p.range.hi);
            if (std::isfinite(x) && p.range.contains(x)) m.set_number(p.name, x);
        }
    };
    std::vector<Material> out{target.material};
    if (free.size() <= 5) {
        for (unsigned bits = 0; bits < (1u << free.size()); ++bits) {
            Material m = target.material;
            for (std::size_t k = 0; k < free.size(); ++k) set_end(m, *free[k], (bits >> k) & 1u);
            out.push_back(m);
        }
    } else {
        for (const ParamSpec* p : free)
            for (bool high : {false, true}) {
                Material m = target.material;
                set_end(m, *p, high);
                out.push_back(m);
            }
    }
    return out;
}

}  // namespace m3055
