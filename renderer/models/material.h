// A material: which reflection model an object wears and that model's
// parameter values. The parameters are not fields of this struct: each model
// states its own in the model table (models/model_table.h), and a Material
// holds their values in the layout the model's ModelSpec gives. So a model
// added to the table, or loaded at run time, needs no change here.
//
//   Material m = Material::of("phong");
//   m.set_vec3("kd", {0.7, 0.3, 0.2});
//   m.set_number("shininess", 40);
//   double n = m.number("shininess");
//
// Asking for a parameter the model does not have is a programming error
// (std::logic_error naming the model and the parameter).
#pragma once

#include <glm/vec3.hpp>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace m3055 {

using glm::dvec3;

struct ModelSpec;

inline constexpr int kMaxLobes = 4;

// One lobe of a lobe-list parameter: a weight w and a value m, which is a
// roughness m_j or an exponent n_j as the parameter's LobeForm says.
struct Lobe {
    double w = 0.0;
    double m = 0.0;
};

// Which models a light's own lobes are for: Beckmann lobes {"w", "m"} override
// the lobes of `metal`; exponent lobes {"w", "n"} those of `metal_blinn`/`metal_phong`.
// (A lobe concept, here beside Lobe: the model table's entries name it.)
enum class LobeKind { beckmann, exponent };

// 0 to kMaxLobes lobes without a heap allocation (what a lobe-list parameter
// holds; read per light per pixel by the CPU reference).
struct LobeList {
    int count = 0;
    Lobe lobe[kMaxLobes];

    LobeList() = default;
    LobeList(const std::vector<Lobe>& lobes);  // NOLINT: lobes convert freely (first kMaxLobes)
    const Lobe* begin() const { return lobe; }
    const Lobe* end() const { return lobe + count; }
    std::size_t size() const { return static_cast<std::size_t>(count); }
    bool empty() const { return count == 0; }
    const Lobe& operator[](std::size_t j) const { return lobe[j]; }
    std::vector<Lobe> to_vector() const { return {begin(), end()}; }
};

// A reflectance spectrum given in a scene ("color_spectrum", docs/spec.md#73-spectral-colours):
// values in [0, 1] at increasing wavelengths in [380, 780] nm, any sampling;
// linearly interpolated, held at the end values outside.
struct ReflectanceSpectrum {
    std::vector<double> nm, values;
    double at(double wavelength_nm) const;
    bool operator==(const ReflectanceSpectrum& other) const { return nm == other.nm && values == other.values; }
};

class Material {
public:
    Material();                               // the default model ("highlight") with its defaults
    explicit Material(const ModelSpec& model);  // `model` with the table's defaults
    // The table's model `name` with its defaults; std::invalid_argument if unknown.
    static Material of(std::string_view name);

    const ModelSpec& model() const { return *model_; }
    const std::string& model_name() const;
    // For people (messages, panels): the scene name, or for a model from a
    // .brdf file (internally "brdf_16") its label, the file's name + " (.brdf)".
    std::string shown_name() const;

    // Typed access by parameter name (the scene file's key).
    bool has(std::string_view name) const;
    double number(std::string_view name) const;   // number parameter
    dvec3 vec3(std::string_view name) const;      // colour or direction
    int choice(std::string_view name) const;      // index into ParamSpec::choices
    const std::string& choice_name(std::string_view name) const;
    bool flag(std::string_view name) const;
    LobeList lobes(std::string_view name = "lobes") const;

    void set_number(std::string_view name, double value);
    void set_vec3(std::string_view name, const dvec3& value);
    void set_choice(std::string_view name, int index);
    void set_choice(std::string_view name, std::string_view choice);  // logic_error if unknown
    void set_flag(std::string_view name, bool value);
    void set_lobes(std::string_view name, const std::vector<Lobe>& lobes);
    void set_lobes(const std::vector<Lobe>& lobes) { set_lobes("lobes", lobes); }

    // The colour as a spectrum, in place of the colour parameter whose
    // ParamSpec::spectrum_key names it (nullptr: none). That parameter then
    // holds the spectrum's colour under D65, for display and model switches.
    const ReflectanceSpectrum* colour_spectrum() const { return colour_spectrum_.get(); }
    void set_colour_spectrum(const ReflectanceSpectrum* spectrum);

    // The raw values, in the model's layout (ParamSpec::offset / size).
    const std::vector<double>& values() const { return values_; }
    std::vector<double>& values() { return values_; }

    bool operator==(const Material& other) const {
        return model_ == other.model_ && values_ == other.values_ &&
               (colour_spectrum_ == other.colour_spectrum_ ||
                (colour_spectrum_ && other.colour_spectrum_ && *colour_spectrum_ == *other.colour_spectrum_));
    }
    bool operator!=(const Material& other) const { return !(*this == other); }

private:
    const double* slot(std::string_view name, int kind) const;
    double* slot(std::string_view name, int kind);

    const ModelSpec* model_;
    std::vector<double> values_;
    std::shared_ptr<const ReflectanceSpectrum> colour_spectrum_;  // shared: copied per pixel by the reference
};

// `from` switched to `model` (the explorer's model selector): the new model's
// defaults, then every value `from` has under the same name (or a name of
// ParamSpec::carry_from) and kind. Parameters marked carry = false, and lobe
// lists, are kept only within one family; lobe lists also need the same key,
// and choices the same list of choices.
Material with_model(const Material& from, const ModelSpec& model);

}  // namespace m3055
