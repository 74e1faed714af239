#include "models/material.h"

#include "models/model_table.h"
#include "models/model_spec.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace m3055 {

namespace {

// Kinds a typed accessor accepts, as a bit mask of ParamKind.
constexpr int bit(ParamKind kind) { return 1 << static_cast<int>(kind); }
constexpr int kNumber = bit(ParamKind::number);
constexpr int kVec3 = bit(ParamKind::colour) | bit(ParamKind::direction);
constexpr int kChoice = bit(ParamKind::choice);
constexpr int kFlag = bit(ParamKind::flag);
constexpr int kLobes = bit(ParamKind::lobes);

}  // namespace

LobeList::LobeList(const std::vector<Lobe>& lobes) {
    count = static_cast<int>(std::min<std::size_t>(lobes.size(), kMaxLobes));
    std::copy_n(lobes.begin(), count, lobe);
}

Material::Material() : Material(model_table().get("highlight")) {}

Material::Material(const ModelSpec& model) : model_(&model), values_(model.value_count, 0.0) {
    for (const ParamSpec& param : model.params) {
        if (param.kind == ParamKind::lobes) {
            set_lobes(param.name, param.form_for(*this).fallback);
        } else {
            std::copy(param.fallback.begin(), param.fallback.end(), values_.begin() + param.offset);
        }
    }
    // Colours that default to another parameter ("ka" <- "kd") start equal to it.
    for (const ParamSpec& param : model.params)
        if (!param.default_from.empty()) set_vec3(param.name, vec3(param.default_from));
}

Material Material::of(std::string_view name) {
    const ModelSpec* model = model_table().find(name);
    if (!model) throw std::invalid_argument("no model named \"" + std::string(name) + "\"");
    return Material(*model);
}

const std::string& Material::model_name() const { return model_->name; }

std::string Material::shown_name() const { return model_->family == Family::brdf ? model_->label : model_->name; }

bool Material::has(std::string_view name) const { return model_->find(name) != nullptr; }

const double* Material::slot(std::string_view name, int kinds) const {
    const ParamSpec& param = model_->param(name);  // logic_error naming model and parameter
    if (!(bit(param.kind) & kinds))
        throw std::logic_error("parameter \"" + param.name + "\" of model " + model_->name + " is a " +
                               to_string(param.kind));
    return values_.data() + param.offset;
}

double* Material::slot(std::string_view name, int kinds) {
    return const_cast<double*>(static_cast<const Material*>(this)->slot(name, kinds));
}

double Material::number(std::string_view name) const { return *slot(name, kNumber); }

dvec3 Material::vec3(std::string_view name) const {
    const double* v = slot(name, kVec3);
    return dvec3(v[0], v[1], v[2]);
}

int Material::choice(std::string_view name) const { return static_cast<int>(*slot(name, kChoice)); }

const std::string& Material::choice_name(std::string_view name) const {
    return model_->param(name).choices.at(static_cast<std::size_t>(choice(name)));
}

bool Material::flag(std::string_view name) const { return *slot(name, kFlag) != 0.0; }

LobeList Material::lobes(std::string_view name) const {
    const double* v = slot(name, kLobes);
    LobeList list;
    list.count = static_cast<int>(v[0]);
    for (int j = 0; j < list.count; ++j) list.lobe[j] = {v[1 + 2 * j], v[2 + 2 * j]};
    return list;
}

void Material::set_number(std::string_view name, double value) { *slot(name, kNumber) = value; }

void Material::set_vec3(std::string_view name, const dvec3& value) {
    double* v = slot(name, kVec3);
    v[0] = value.x, v[1] = value.y, v[2] = value.z;
}

void Material::set_choice(std::string_view name, int index) { *slot(name, kChoice) = index; }

void Material::set_choice(std::string_view name, std::string_view choice) {
    const std::vector<std::string>& choices = model_->param(name).choices;
    const auto found = std::find(choices.begin(), choices.end(), choice);
    if (found == choices.end())
        throw std::logic_error("\"" + std::string(choice) + "\" is not a choice of parameter \"" +
                               std::string(name) + "\" of model " + model_->name);
    set_choice(name, static_cast<int>(found - choices.begin()));
}

void Material::set_flag(std::string_view name, bool value) { *slot(name, kFlag) = value ? 1.0 : 0.0; }

void Material::set_lobes(std::string_view name, const std::vector<Lobe>& lobes) {
    double* v = slot(name, kLobes);
    const int count = static_cast<int>(std::min<std::size_t>(lobes.size(), kMaxLobes));
    std::fill(v, v + 1 + 2 * kMaxLobes, 0.0);
    v[0] = count;
    for (int j = 0; j < count; ++j) v[1 + 2 * j] = lobes[j].w, v[2 + 2 * j] = lobes[j].m;
}

namespace {

// The parameter of `from` that `param` (of the new model) takes its value from, or nullptr.
const ParamSpec* carry_source(const Material& from, const ParamSpec& param, bool same_family) {
    if (!param.carry && !same_family) return nullptr;
    if (param.kind == ParamKind::lobes && !same_family) return nullptr;
    std::vector<std::string> names = {param.name};
    names.insert(names.end(), param.carry_from.begin(), param.carry_from.end());
    for (const std::string& name : names) {
        const ParamSpec* source = from.model().find(name);
        if (!source || source->kind != param.kind) continue;
        if (param.kind == ParamKind::choice && source->choices != param.choices) continue;
        return source;
    }
    return nullptr;
}

}  // namespace

double ReflectanceSpectrum::at(double wavelength_nm) const {
    if (wavelength_nm <= nm.front()) return values.front();
    if (wavelength_nm >= nm.back()) return values.back();
    const std::size_t i = std::size_t(std::upper_bound(nm.begin(), nm.end(), wavelength_nm) - nm.begin()) - 1;
    const double f = (wavelength_nm - nm[i]) / (nm[i + 1] - nm[i]);
    return values[i] + f * (values[i + 1] - values[i]);
}

void Material::set_colour_spectrum(const ReflectanceSpectrum* spectrum) {
    colour_spectrum_ = spectrum ? std::make_shared<const ReflectanceSpectrum>(*spectrum) : nullptr;
}

Material with_model(const Material& from, const ModelSpec& model) {
    Material to(model);
    // The spectrum goes along where the new model takes one (the paper's models' "color").
    for (const ParamSpec& param : model.params)
        if (!param.spectrum_key.empty() && from.colour_spectrum()) to.set_colour_spectrum(from.colour_spectrum());
    const bool same_family = from.model().family == model.family;
    for (const ParamSpec& param : model.params) {
        const ParamSpec* source = carry_source(from, param, same_family);
        if (!source) continue;
        if (param.kind == ParamKind::lobes) {
            // Only lobes that mean the same: the same key in the form each material is in.
            if (source->form_for(from).key != param.form_for(to).key) continue;
            to.set_lobes(param.name, from.lobes(source->name).to_vector());
            continue;
        }
        std::copy_n(from.values().begin() + source->offset, param.size, to.values().begin() + param.offset);
    }
    return to;
}

}  // namespace m3055
