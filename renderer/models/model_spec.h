// One reflection model, described once: its scene name, UI label, citation,
// parameters (kind, range, default, help, slider) and its GLSL shading
// function, whose C++ namesake in reference/ is its double twin
// (reference/hooks.h binds them by that name). Everything else is derived from these
// descriptions: the scene loader's validation and defaults, scene_to_json,
// the GPU material record and its GLSL unpacking, the shader specialization
// defines, the explorer's material panel and the presets' defaults.
//
// The built-in entries are in models/builtin_models.cpp; docs/adding-a-model.md
// walks through adding one. A ModelSpec is plain data, so a model can also be
// added at run time (models/model_table.h: ModelTable::add).
#pragma once

#include "models/material.h"
#include "models/range.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace m3055 {

// What a parameter holds; decides how it is read, stored, packed and edited.
enum class ParamKind {
    number,     // one double in `range`
    colour,     // RGB, each in [0, 1]
    direction,  // non-zero 3-vector, stored unit
    choice,     // one of `choices`, stored as its index
    flag,       // true / false
    lobes,      // 1 to kMaxLobes lobes {"w", key}: a LobeForm says key and ranges
};

// The shape of a lobe list: its value key ("m" roughness, "n" exponent), the
// ranges, the default lobes, and who owns it in error messages
// ("model metal_blinn", "distribution blinn_phong").
struct LobeForm {
    std::string key;
    Range weight;
    Range value;
    std::vector<Lobe> fallback;
    std::string owner;
    std::string value_help;  // what the value means, for the UI's tooltip
};

struct ParamSpec {
    std::string name;   // scene-file key; also the GLSL field mat.NAME
    ParamKind kind = ParamKind::number;
    std::string label;  // UI label ("d (background)")
    std::string help;   // one line: meaning (the UI adds range and citation)
    std::string cite;   // the equation or seed it comes from ("eq. 4")
    Range range = closed(0.0, 1.0);  // number
    std::vector<double> fallback;    // default: 1 value (number, choice, flag) or 3 (colour, direction)
    bool required = false;           // absent is an error ("is required")
    bool log_slider = false;         // the UI slider is logarithmic (values spanning decades)
    std::string format = "%.3f";     // the UI's printf format
    std::vector<std::string> choices;  // choice
    std::vector<std::string> choice_labels;  // choice: the UI's words for each, when not the choice itself
    std::vector<LobeForm> forms;       // lobes: one form, or one per choice of `form_from`
    std::string form_from;             // lobes: the choice parameter that picks the form
    std::string default_from;          // absent: copy this (earlier) parameter ("ka" <- "kd")
    std::vector<std::string> carry_from;  // model switch in the explorer: also take these names
    bool carry = true;                 // model switch keeps a same-named value
    // Given in a scene, this parameter stands in for the (earlier) parameter of
    // this name: "conductor" for "color" (docs/spec.md#72-measured-metals). Giving
    // both is an error; the other is then not required. Only for a choice whose
    // first choice ("none") means "not given".
    std::string replaces;
    // A colour that a scene may give as a reflectance spectrum under this key
    // instead ("color_spectrum": docs/spec.md#73-spectral-colours); "" for none.
    std::string spectrum_key;
    // False: a scene is written without it while it holds its default, so
    // scenes saved before it existed are written as before.
    bool written_at_default = true;

    // Layout, set by ModelTable::add: doubles [offset, offset + size) of Material::values.
    int offset = 0;
    int size = 0;

    // The lobe form in effect for `material` (lobes only).
    const LobeForm& form_for(const Material& material) const;
};

// How a model is composed with the lights; decides the signature of its hook.
enum class Family {
    opaque,       // hook: the whole colour at a point            (the paper's highlight)
    translucent,  // hook: premultiplied colour + transmittance   (the paper's translucent)
    metal,        // hook: sum_j w_j lobe_j for one light          (the paper's metals, eq. 12-16)
    classic,      // hooks: the diffuse factor and the specular     (the seeds' models, the lecture's equation)
    brdf,         // hook: f(L, V, N, X, Y) of a BRDF Explorer file (run time only: brdf_file/brdf_model.h)
};

// Floats computed on the CPU (in double) per material and packed after the
// parameters, e.g. the Gaussian distribution's normalization per lobe. The
// GLSL field mat.NAME is a float or vecN.
struct DerivedValue {
    std::string name;
    int floats = 1;  // 1 to 4
    void (*fill)(const Material& material, float* out) = nullptr;
};

struct ModelSpec {
    std::string name;      // scene file's "model"
    std::string label;     // UI selector
    std::string citation;  // the paper's equation or the seed ("eq. 12", "Ward 1992 (seed 002)")
    std::string summary;   // one line: what the model is
    Family family = Family::opaque;
    std::vector<ParamSpec> params;  // in reading order (a `default_from`/`form_from` comes first)
    // Extra words for a key of another model: {"color", "its diffuse colour is \"kd\""}.
    std::vector<std::pair<std::string, std::string>> misplaced_hints;
    std::optional<LobeKind> light_lobes;  // the per-light lobes it reads (Fig. 11), if any

    std::string glsl_file;  // glsl/ file defining the hook (included when the model is present)
    std::string glsl_hook;  // its GLSL function, with the family's signature (classic: the diffuse factor)
    std::string glsl_specular;  // classic: the specular hook ("" for a diffuse-only model)
    // The Phong exponent e of a lobe ((R_V . L)+)^e about V's mirror direction R_V
    // that the model's highlight resembles, as a GLSL expression of `mat` and the
    // light `i` (helpers: glsl/common/lobe_hints.glsl); area lights draw samples
    // from it as well as from the emitter. "": no highlight to draw from.
    std::string glsl_lobe;
    // The whole-numbered exponent of the lobe whose closed form is the samples'
    // control variate (glsl/common/lights.glsl: pair_factor), where it is not
    // glsl_lobe's: a mixture of lobes draws samples from its sharpest (its peaks)
    // and, under a rect or disk, is controlled by the one that carries most light. "": glsl_lobe's.
    std::string glsl_control_lobe;
    // Whether the highlight is exactly cosine terms and ((R_V . L)+)^glsl_lobe (the
    // paper's highlight, Phong): the pair of closed forms then integrates it wholly
    // from any two points, so the explorer's preview takes two of an area light (its
    // centre and where the highlight is) in place of the centre alone. A lobe that
    // only resembles that one (a microfacet's, a metal's) could be overshot by two
    // points standing for the whole emitter: the centre alone (docs/lights.md).
    bool glsl_lobe_exact = false;
    std::vector<DerivedValue> derived;
    // GLSL the entry brings itself, (path, text) as the composer includes it
    // (run-time models: a .brdf file's code and its wrapper); built-in models
    // have theirs in glsl/.
    std::vector<std::pair<std::string, std::string>> glsl_sources;
    // The same files for GLSL ES 3.00 (WebGL2), where they differ: a .brdf
    // file's code with desktop GLSL's implicit conversions made explicit
    // (brdf_file/brdf_glsl_es.h). Empty: glsl_sources serve both.
    std::vector<std::pair<std::string, std::string>> glsl_sources_es;

    // Set by ModelTable::add.
    int id = -1;           // MODEL_<NAME> in GLSL; index in the table
    int value_count = 0;   // doubles in Material::values
    int gpu_floats = 0;    // floats of its GPU record (model id, family, parameters, derived)

    const ParamSpec* find(std::string_view param) const;  // nullptr if absent
    const ParamSpec& param(std::string_view param) const;  // std::logic_error if absent
    std::vector<std::string> param_names() const;
    // "HIGHLIGHT": the model's name as a GLSL macro suffix (MODEL_X, HAS_X).
    std::string macro_name() const;
};

// Floats a parameter takes in the GPU record (lobes: count + kMaxLobes pairs).
int gpu_floats_of(ParamKind kind);
// Doubles it takes in Material::values (the same numbers).
inline int value_count_of(ParamKind kind) { return gpu_floats_of(kind); }

// True for a material drawn in the translucent pass (over what lies behind).
inline bool is_translucent(const Material& material) { return material.model().family == Family::translucent; }

const char* to_string(Family family);
const char* to_string(ParamKind kind);

}  // namespace m3055
