#include "models/model_table.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace m3055 {

namespace {

// The parameters each family's composer reads itself (glsl/models/*.glsl):
// every model of the family must have them.
std::vector<std::string> family_params(Family family) {
    switch (family) {
        case Family::metal: return {"color", "d", "lobes"};  // (d + sum_l ...) C0; lobes by the hook
        case Family::classic: return {"ka", "emission"};     // L_glob K_amb + L_emi, a_k ambient_k K_amb
        case Family::brdf: return {"axis"};                   // X, Y: the tangent frame of axis
        case Family::opaque:
        case Family::translucent: return {};
    }
    return {};
}

bool is_identifier(const std::string& name) {
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) ||
               c == '_';
    });
}

class SpecCheck {
public:
    explicit SpecCheck(const ModelSpec& spec) : spec_(spec) {}
    [[noreturn]] void fail(const std::string& problem) const {
        throw std::invalid_argument("model \"" + spec_.name + "\": " + problem);
    }
    void require(bool ok, const std::string& problem) const {
        if (!ok) fail(problem);
    }

    void lobes(const ParamSpec& param, std::size_t index) const {
        require(!param.forms.empty(), param.name + ": a lobe list needs a form");
        if (!param.form_from.empty()) {
            const ParamSpec* from = earlier(param.form_from, index);
            require(from && from->kind == ParamKind::choice,
                    param.name + ": form_from \"" + param.form_from + "\" must be an earlier choice parameter");
            require(param.forms.size() == from->choices.size(), param.name + ": one form per choice of " + from->name);
        } else {
            require(param.forms.size() == 1, param.name + ": several forms need form_from");
        }
        for (const LobeForm& form : param.forms) {
            require(form.key == "m" || form.key == "n", param.name + ": lobe key must be \"m\" or \"n\"");
            require(!form.fallback.empty() && form.fallback.size() <= std::size_t(kMaxLobes),
                    param.name + ": 1 to 4 default lobes");
            for (const Lobe& lobe : form.fallback)
                require(form.weight.contains(lobe.w) && form.value.contains(lobe.m),
                        param.name + ": a default lobe is out of range");
        }
    }

    void value(const ParamSpec& param, std::size_t index) const {
        const std::size_t wanted = param.kind == ParamKind::colour || param.kind == ParamKind::direction ? 3
                                   : param.kind == ParamKind::lobes                                     ? 0
                                                                                                        : 1;
        require(param.fallback.size() == wanted, param.name + ": the default needs " + std::to_string(wanted) +
                                                     " number(s) for a " + to_string(param.kind));
        switch (param.kind) {
            case ParamKind::number:
                require(param.range.contains(param.fallback[0]), param.name + ": the default is out of range");
                break;
            case ParamKind::colour:
                for (double c : param.fallback) require(c >= 0.0 && c <= 1.0, param.name + ": colour outside [0, 1]");
                break;
            case ParamKind::direction:
                require(std::any_of(param.fallback.begin(), param.fallback.end(), [](double c) { return c != 0.0; }),
                        param.name + ": a zero default direction");
                break;
            case ParamKind::choice:
                require(!param.choices.empty() && param.fallback[0] >= 0 &&
                            param.fallback[0] < double(param.choices.size()),
                        param.name + ": the default is not one of the choices");
                break;
            case ParamKind::flag:
                require(param.fallback[0] == 0.0 || param.fallback[0] == 1.0, param.name + ": a flag is 0 or 1");
                break;
            case ParamKind::lobes: lobes(param, index); break;
        }
        if (!param.replaces.empty()) {
            const ParamSpec* other = earlier(param.replaces, index);
            require(other && param.kind == ParamKind::choice && param.fallback[0] == 0.0,
                    param.name + ": replaces \"" + param.replaces +
                        "\" must name an earlier parameter, from a choice whose default (first) is none");
        }
        if (!param.default_from.empty()) {
            const ParamSpec* from = earlier(param.default_from, index);
            require(from && from->kind == param.kind,
                    param.name + ": default_from \"" + param.default_from + "\" must be an earlier " +
                        to_string(param.kind));
        }
    }

    void whole() const {
        require(is_identifier(spec_.name), "the name must be lower-case letters, digits and _");
        require(!spec_.label.empty() && !spec_.glsl_file.empty() && !spec_.glsl_hook.empty(),
                "label, glsl_file and glsl_hook are required");
        for (std::size_t i = 0; i < spec_.params.size(); ++i) {
            const ParamSpec& param = spec_.params[i];
            require(is_identifier(param.name) && param.name != "model", "bad parameter name \"" + param.name + "\"");
            require(!earlier(param.name, i), "parameter \"" + param.name + "\" twice");
            value(param, i);
        }
        for (const std::string& name : family_params(spec_.family))
            require(spec_.find(name) != nullptr, std::string("a ") + to_string(spec_.family) +
                                                     " model needs parameter \"" + name + "\"");
        for (const DerivedValue& d : spec_.derived)
            require(is_identifier(d.name) && d.floats >= 1 && d.floats <= 4 && d.fill, "bad derived value");
    }

private:
    const ParamSpec* earlier(const std::string& name, std::size_t before) const {
        for (std::size_t i = 0; i < before; ++i)
            if (spec_.params[i].name == name) return &spec_.params[i];
        return nullptr;
    }
    const ModelSpec& spec_;
};

}  // namespace

ModelTable::ModelTable() {
    for (ModelSpec& spec : builtin_models()) {
        add(std::move(spec));
    }
    builtin_count_ = static_cast<int>(models_.size());
}

const ModelSpec& ModelTable::add(ModelSpec spec) {
    SpecCheck(spec).whole();
    if (find(spec.name)) throw std::invalid_argument("model \"" + spec.name + "\": already in the table");
    // A parameter name is one GLSL field of struct Material: one kind everywhere.
    for (const ParamSpec& param : spec.params)
        for (const ModelSpec& other : models_)
            if (const ParamSpec* same = other.find(param.name); same && same->kind != param.kind)
                throw std::invalid_argument("model \"" + spec.name + "\": parameter \"" + param.name + "\" is a " +
                                            to_string(param.kind) + " here but a " + to_string(same->kind) +
                                            " in model " + other.name);
    int offset = 0;
    for (ParamSpec& param : spec.params) {
        param.offset = offset;
        param.size = value_count_of(param.kind);
        offset += param.size;
    }
    spec.value_count = offset;
    spec.gpu_floats = 2 + offset;  // model id, family, parameters
    for (const DerivedValue& d : spec.derived) spec.gpu_floats += d.floats;
    spec.id = static_cast<int>(models_.size());
    record_texels_ = std::max(record_texels_, (spec.gpu_floats + 3) / 4);
    ++revision_;
    models_.push_back(std::move(spec));
    return models_.back();
}

const ModelSpec* ModelTable::find(std::string_view name) const {
    for (const ModelSpec& spec : models_)
        if (spec.name == name) return &spec;
    return nullptr;
}

const ModelSpec& ModelTable::get(std::string_view name) const {
    if (const ModelSpec* spec = find(name)) return *spec;
    throw std::invalid_argument("no model named \"" + std::string(name) + "\"");
}

std::vector<std::string> ModelTable::names() const {
    std::vector<std::string> out;
    for (const ModelSpec& spec : models_) out.push_back(spec.name);
    return out;
}

bool ModelTable::is_builtin_param(std::string_view key) const {
    for (int i = 0; i < builtin_count_; ++i)
        if (models_[std::size_t(i)].find(key)) return true;
    return false;
}

ModelTable& mutable_model_table() {
    static ModelTable table;
    return table;
}

const ModelTable& model_table() { return mutable_model_table(); }

}  // namespace m3055
