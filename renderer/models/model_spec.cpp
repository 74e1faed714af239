#include "models/model_spec.h"

#include <cctype>
#include <stdexcept>

namespace m3055 {

const LobeForm& ParamSpec::form_for(const Material& material) const {
    if (form_from.empty()) return forms.at(0);
    return forms.at(static_cast<std::size_t>(material.choice(form_from)));
}

const ParamSpec* ModelSpec::find(std::string_view name) const {
    for (const ParamSpec& p : params)
        if (p.name == name) return &p;
    return nullptr;
}

const ParamSpec& ModelSpec::param(std::string_view name) const {
    if (const ParamSpec* p = find(name)) return *p;
    throw std::logic_error("model " + this->name + " has no parameter \"" + std::string(name) + "\"");
}

std::vector<std::string> ModelSpec::param_names() const {
    std::vector<std::string> out;
    for (const ParamSpec& p : params) out.push_back(p.name);
    return out;
}

std::string ModelSpec::macro_name() const {
    std::string out = name;
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

int gpu_floats_of(ParamKind kind) {
    switch (kind) {
        case ParamKind::number:
        case ParamKind::choice:
        case ParamKind::flag: return 1;
        case ParamKind::colour:
        case ParamKind::direction: return 3;
        case ParamKind::lobes: return 1 + 2 * kMaxLobes;  // count, then (w, m) pairs
    }
    return 0;
}

const char* to_string(Family family) {
    switch (family) {
        case Family::opaque: return "opaque";
        case Family::translucent: return "translucent";
        case Family::metal: return "metal";
        case Family::classic: return "classic";
        case Family::brdf: return "brdf";
    }
    return "?";
}

const char* to_string(ParamKind kind) {
    switch (kind) {
        case ParamKind::number: return "number";
        case ParamKind::colour: return "colour";
        case ParamKind::direction: return "direction";
        case ParamKind::choice: return "choice";
        case ParamKind::flag: return "flag";
        case ParamKind::lobes: return "lobe list";
    }
    return "?";
}

}  // namespace m3055
