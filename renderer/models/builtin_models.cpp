// The model table's built-in entries: the paper's five models (docs/spec.md,
// eq. 3-18) and the seeds' classic models (docs/models.md). Each entry is the
// one place that states a model's name, label, citation, parameters (kind,
// range, default, help, slider) and hooks (the GLSL function, whose C++ namesake
// in reference/ is its twin: reference/hooks.h); see
// models/model_spec.h for the fields and docs/adding-a-model.md for a walk
// through adding one.
#include "models/model_table.h"
#include "numeric/normalization.h"
#include "spectral/conductor.h"

#include <cmath>

namespace m3055 {

namespace {

// ---- Parameter builders ------------------------------------------------------------

ParamSpec number(std::string name, std::string label, Range range, double fallback, std::string help,
                 std::string cite, bool log_slider = false, std::string format = "%.3f") {
    ParamSpec p;
    p.name = std::move(name), p.label = std::move(label), p.help = std::move(help), p.cite = std::move(cite);
    p.kind = ParamKind::number;
    p.range = range;
    p.fallback = {fallback};
    p.log_slider = log_slider;
    p.format = std::move(format);
    return p;
}

ParamSpec colour(std::string name, std::string label, dvec3 fallback, std::string help, std::string cite) {
    ParamSpec p;
    p.name = std::move(name), p.label = std::move(label), p.help = std::move(help), p.cite = std::move(cite);
    p.kind = ParamKind::colour;
    p.fallback = {fallback.x, fallback.y, fallback.z};
    return p;
}

ParamSpec required(ParamSpec p) {
    p.required = true;
    return p;
}

ParamSpec lobe_list(std::string label, std::vector<LobeForm> forms, std::string help, std::string cite) {
    ParamSpec p;
    p.name = "lobes", p.label = std::move(label), p.help = std::move(help), p.cite = std::move(cite);
    p.kind = ParamKind::lobes;
    p.forms = std::move(forms);
    return p;
}

const Range kExponent = closed(0.0, 10000.0);    // m, n_j, shininess
const Range kBeckmannM = closed(0.001, 2.0);     // m_j, microfacet roughness
const Range kPaperWeight = closed(0.0, 100.0);   // the paper's lobe weights
const Range kUnitWeight = closed(0.0, 1.0);      // microfacet lobe weights

// ---- The paper's models (docs/spec.md section 4) ------------------------------------

// Where the material's spectral table starts in the material texture (texels),
// -1 for none: written by the frame, which knows the lights
// (passes/spectral_tables.h); the record itself carries -1.
void no_spectral_table(const Material&, float* out) { out[0] = -1.0f; }


ParamSpec paper_colour() {
    ParamSpec p = required(colour("color", "colour C0", {0.8, 0.2, 0.2}, "the object's colour C0", "eq. 3"));
    p.carry_from = {"kd", "base_color"};
    p.spectrum_key = "color_spectrum";
    return p;
}

ParamSpec paper_d(double fallback, std::string label, std::string help) {
    return number("d", std::move(label), closed(0.0, 1.0), fallback, std::move(help), "eq. 3, 12");
}

// highlight and translucent share d, w, m (eq. 3-4).
std::vector<ParamSpec> highlight_params() {
    return {paper_colour(),
            paper_d(0.5, "d (environment)", "share of the diffuse light that comes from the environment"),
            number("w", "w (highlight)", closed(0.0, 1.0), 1.0,
                   "highlight brightness: 1 drives the highlight centre to display white", "eq. 4"),
            number("m", "m (size)", kExponent, 10.0, "highlight exponent on R.V: larger is smaller and sharper",
                   "eq. 4", true, "%.2f")};
}

ModelSpec highlight() {
    ModelSpec s;
    s.name = "highlight", s.label = "highlight (eq. 4)", s.citation = "Yokoi et al., eq. 3-4";
    s.summary = "coloured object whose highlight is driven to display white";
    s.family = Family::opaque;
    s.params = highlight_params();
    s.derived = {{"spectral_table", 1, no_spectral_table}};
    s.glsl_file = "models/highlight.glsl", s.glsl_hook = "shade_highlight";
    s.glsl_lobe = "mat.m";
    s.glsl_lobe_exact = true;
    return s;
}

ModelSpec translucent() {
    ModelSpec s;
    s.name = "translucent", s.label = "translucent (eq. 8)", s.citation = "Yokoi et al., eq. 5-8 (Newell, Kay)";
    s.summary = "translucent object: Newell's blend with Kay's opacity, plus the highlight";
    s.family = Family::translucent;
    s.params = highlight_params();
    s.params.push_back(number("t_n", "t_n (opacity)", closed(0.0, 1.0), 0.8,
                              "opacity: 1 opaque, 0 clear (Newell's constant when t_p = 0)", "eq. 6"));
    s.params.push_back(number("t_p", "t_p (falloff)", closed(0.0, 10.0), 1.0,
                              "Kay's falloff power: larger makes faces towards the viewer clearer", "eq. 6"));
    s.derived = {{"spectral_table", 1, no_spectral_table}};
    s.glsl_file = "models/translucent.glsl", s.glsl_hook = "shade_translucent";
    s.glsl_lobe = "mat.m";
    s.glsl_lobe_exact = true;
    return s;
}

// A measured metal in place of C0 (docs/spec.md#72-measured-metals): "none", or
// one of data/conductors/*.nk by name.
ParamSpec conductor_choice(std::string replaces) {
    ParamSpec p;
    p.name = "conductor", p.label = "conductor", p.kind = ParamKind::choice;
    p.choices = {"none"};
    for (const std::string& name : spectral::conductor_names()) p.choices.push_back(name);
    p.fallback = {0.0};
    p.help = "a measured metal: C0 from its complex index n + i k under each light, in place of the colour";
    p.cite = "eq. 2, assumption 3";
    p.replaces = std::move(replaces);
    p.written_at_default = false;
    return p;
}

// How a conductor's F depends on the angle: "normal" F(lambda, 0) (assumption 3),
// "full" eq. 19 with the complex index, at V.H.
ParamSpec conductor_fresnel() {
    ParamSpec p;
    p.name = "fresnel", p.label = "F", p.kind = ParamKind::choice, p.choices = {"normal", "full"};
    p.choice_labels = {"F(\u03bb, 0) (normal)", "full eq. 19 (full)"};  // as docs/spec.md#72-measured-metals names them
    p.fallback = {0.0};
    p.help = "a conductor's F: normal incidence (the paper's assumption 3), or eq. 19 at every angle";
    p.cite = "eq. 19";
    p.written_at_default = false;
    return p;
}

ModelSpec paper_metal(std::string name, std::string label, std::string citation, LobeForm form) {
    ModelSpec s;
    s.name = std::move(name), s.label = std::move(label), s.citation = std::move(citation);
    s.family = Family::metal;
    ParamSpec d = paper_d(0.05, "d (background)", "background light (d << 1); eq. 14 wants d + D(0) = 1");
    d.carry = false;  // from another family: the default, which meets eq. 14 with the default lobes
    const bool beckmann = form.key == "m";
    s.params = {paper_colour(), d,
                lobe_list(beckmann ? "Beckmann lobes (w_j, m_j)" : "lobes (w_j, n_j)", {std::move(form)},
                          "1 to 4 weighted lobes; a light may carry its own (Fig. 11)", "eq. 12-16"),
                conductor_choice("color"), conductor_fresnel()};
    s.derived = {{"spectral_table", 1, no_spectral_table}};
    s.light_lobes = beckmann ? LobeKind::beckmann : LobeKind::exponent;
    s.glsl_file = "models/metal.glsl";
    return s;
}

LobeForm paper_lobes(std::string key, Range value, std::vector<Lobe> fallback, std::string owner,
                     std::string value_help) {
    return {std::move(key), kPaperWeight, value, std::move(fallback), std::move(owner), std::move(value_help)};
}

ModelSpec metal() {
    ModelSpec s = paper_metal("metal", "metal, Cook-Torrance (eq. 12)", "Yokoi et al., eq. 12-14, 17-18",
                              paper_lobes("m", kBeckmannM, {{0.013, 0.2}, {0.1, 0.4}}, "model metal",
                                          "Beckmann roughness m_j (eq. 13)"));
    s.summary = "metal after Cook-Torrance, a mixture of Beckmann lobes; F = C0";
    s.glsl_hook = "beckmann_lobe_sum";
    s.glsl_lobe = "sharpest_lobe(mat, i, LIGHT_LOBES_BECKMANN)";
    s.glsl_control_lobe = "dominant_lobe(mat, i, LIGHT_LOBES_BECKMANN)";
    return s;
}

// The cheap metals' defaults are those of Figs. 12 and 13 (scenes/fig12, fig13.json):
// with d = 0.05 they meet eq. 14, d + sum_j w_j = 1.
ModelSpec metal_blinn() {
    ModelSpec s = paper_metal("metal_blinn", "metal_blinn (eq. 15)", "Yokoi et al., eq. 15",
                              paper_lobes("n", kExponent, {{0.95, 13.0}}, "model metal_blinn",
                                          "exponent n_j on N.H"));
    s.summary = "cheap metal: lobes ((N.H)+)^n_j";
    s.glsl_hook = "blinn_lobe_sum";
    s.glsl_lobe = "exponent_on_half_vector(sharpest_lobe(mat, i, LIGHT_LOBES_EXPONENT))";
    s.glsl_control_lobe = "exponent_on_half_vector(dominant_lobe(mat, i, LIGHT_LOBES_EXPONENT))";
    return s;
}

ModelSpec metal_phong() {
    ModelSpec s = paper_metal("metal_phong", "metal_phong (eq. 16)", "Yokoi et al., eq. 16",
                              paper_lobes("n", kExponent, {{0.19, 20.0}, {0.76, 3.0}}, "model metal_phong",
                                          "exponent n_j on R.V"));
    s.summary = "cheap metal: lobes ((R.V)+)^n_j, falls off twice as fast as eq. 15";
    s.glsl_hook = "phong_lobe_sum";
    s.glsl_lobe = "sharpest_lobe(mat, i, LIGHT_LOBES_EXPONENT)";
    s.glsl_control_lobe = "dominant_lobe(mat, i, LIGHT_LOBES_EXPONENT)";
    return s;
}

// ---- The seeds' classic models (docs/models.md) --------------------------------------

// kd, ka and emission: every classic model's; ks: those with a specular term,
// whose diffuse term is Lambert's (the hooks: diffuse_NAME, specular_NAME).
ModelSpec classic(std::string name, std::string label, std::string citation, std::string summary, bool specular) {
    ModelSpec s;
    s.name = std::move(name), s.label = std::move(label), s.citation = std::move(citation);
    s.summary = std::move(summary);
    s.family = Family::classic;
    ParamSpec kd = required(colour("kd", "K_diff", {0.8, 0.2, 0.2}, "diffuse colour", "seed 003"));
    kd.carry_from = {"color", "base_color"};
    // K_diff as a reflectance spectrum, one colour per light (docs/spec.md#73-spectral-colours).
    kd.spectrum_key = "kd_spectrum";
    ParamSpec ka = colour("ka", "K_amb", {0.8, 0.2, 0.2}, "ambient colour (the diffuse colour unless given)",
                          "seed 001, 003");
    ka.default_from = "kd";
    ka.carry_from = {"color", "base_color"};
    s.params = {kd, ka, colour("emission", "emission", {0, 0, 0}, "emitted light L_emi, added as is", "seed 003")};
    if (specular) s.params.push_back(colour("ks", "K_spec", {1, 1, 1}, "specular colour", "seed 003"));
    s.misplaced_hints = {{"color", "its diffuse colour is \"kd\""}};
    s.glsl_file = "models/classic.glsl";
    s.glsl_hook = specular ? "diffuse_lambert" : "diffuse_" + s.name;
    if (specular) s.glsl_specular = "specular_" + s.name;
    s.derived = {{"spectral_table", 1, no_spectral_table}};  // kd_spectrum's colours per light
    return s;
}

ParamSpec shininess(std::string help, std::string cite) {
    return number("shininess", "shininess", kExponent, 32.0, std::move(help), std::move(cite), true, "%.1f");
}

std::vector<ModelSpec> diffuse_models() {
    std::vector<ModelSpec> out;
    out.push_back(classic("lambert", "Lambert", "Lambert's cosine law (seed 003)", "(N.L)+ K_diff", false));
    out.push_back(classic("half_lambert", "Half-Lambert", "Valve, Mitchell 2008 (seed 004)",
                          "((N.L) 0.5 + 0.5)^2 K_diff: the back still gets light", false));
    out.push_back(classic("half_lambert_clamped", "Half-Lambert, N.L clamped", "seed 004's code",
                          "Half-Lambert of (N.L)+: the unlit side a flat 1/4", false));
    out.push_back(classic("half_lambert_normalized", "Half-Lambert, normalized", "seed 004",
                          "Half-Lambert x 3/(4 pi): integrates to 1 over the sphere", false));
    ModelSpec on = classic("oren_nayar", "Oren-Nayar", "Oren & Nayar 1994 (seed 003)",
                           "rough diffuse: brighter towards the light at grazing view", false);
    on.params.push_back(number("sigma", "sigma (rad)", closed(0.0, 10.0), 0.3,
                               "surface roughness: standard deviation of the facet angle, radians; 0 is Lambert",
                               "seed 003", true, "%.3f"));
    out.push_back(std::move(on));
    ModelSpec minnaert = classic("minnaert", "Minnaert", "Minnaert 1941 (BRDF Explorer's minnaert.brdf)",
                                 "(N.L)^k (N.V)^(k-1): limb brightening (k < 1) or darkening (k > 1)", false);
    minnaert.params.push_back(number("minnaert_k", "k (limb)", closed(0.5, 1.5), 0.75,
                                     "Minnaert's exponent: 1 is Lambert, below 1 the limb brightens (the Moon)",
                                     "Minnaert 1941"));
    out.push_back(std::move(minnaert));
    return out;
}

ModelSpec phong() {
    ModelSpec s = classic("phong", "Phong", "Phong 1975 (seed 001)", "Lambert + ((R.V)+)^n K_spec", true);
    s.params.push_back(shininess("exponent n on R.V: larger is a smaller, sharper highlight", "seed 001"));
    s.glsl_lobe = "mat.shininess";
    s.glsl_lobe_exact = true;
    return s;
}

ModelSpec blinn_phong() {
    ModelSpec s = classic("blinn_phong", "Blinn-Phong", "Blinn 1977 (seed 003)", "Lambert + ((N.H)+)^n K_spec", true);
    s.params.push_back(shininess("exponent n on N.H: larger is a smaller, sharper highlight", "seed 003"));
    s.glsl_lobe = "exponent_on_half_vector(mat.shininess)";
    return s;
}

// D's lobes hold an exponent n for blinn_phong, a roughness m for the others.
ParamSpec microfacet_lobes(const std::vector<std::string>& distributions) {
    std::vector<LobeForm> forms;
    for (const std::string& d : distributions) {
        const bool exponent = d == "blinn_phong";
        forms.push_back({exponent ? "n" : "m", kUnitWeight, exponent ? kExponent : kBeckmannM,
                         {exponent ? Lobe{1.0, 100.0} : Lobe{1.0, 0.3}}, "distribution " + d,
                         exponent ? "exponent n of the normalized Blinn-Phong D" : "roughness m of D"});
    }
    ParamSpec p = lobe_list("lobes (w_j, m_j or n_j)", std::move(forms),
                            "1 to 4 weighted lobes of one D, weights in [0, 1]", "seed 002");
    p.form_from = "distribution";
    return p;
}

// Gaussian D's normalization b(m) per lobe (1 for the other distributions).
void gaussian_norms(const Material& material, float* out) {
    const LobeList lobes = material.lobes();
    const bool gaussian = material.choice_name("distribution") == "gaussian";
    for (int j = 0; j < kMaxLobes; ++j)
        out[j] = gaussian && j < lobes.count ? float(numeric::gaussian_norm(lobes[j].m)) : 1.0f;
}

ModelSpec microfacet() {
    ModelSpec s = classic("microfacet", "microfacet (D G F)", "Cook & Torrance 1982 (seeds 002, 003)",
                          "Lambert + D G F / (4 N.L N.V), D a mixture of 1 to 4 lobes", true);
    const std::vector<std::string> distributions = {"blinn_phong", "gaussian", "beckmann", "ggx"};
    ParamSpec d;
    d.name = "distribution", d.label = "D", d.kind = ParamKind::choice, d.choices = distributions;
    d.fallback = {2.0};  // beckmann
    d.help = "normal distribution: normalized Blinn-Phong, Gaussian, Beckmann or GGX", d.cite = "seed 002, 003";
    ParamSpec f;
    f.name = "fresnel", f.label = "F", f.kind = ParamKind::choice, f.choices = {"none", "schlick", "dielectric"};
    f.fallback = {1.0};  // schlick
    f.help = "Fresnel term: none (F = 1), Schlick, or the full dielectric Fresnel", f.cite = "seed 003";
    s.params.push_back(d);
    s.params.push_back(f);
    s.params.push_back(number("ior", "IOR", closed(1.0, 5.0), 1.5,
                              "index of refraction; Schlick's F0 = ((n - 1)/(n + 1))^2", "seed 003"));
    s.params.push_back(microfacet_lobes(distributions));
    // A measured metal in place of K_spec: F (its "fresnel": none, schlick or the
    // full eq. 19) from the complex index per wavelength; "ior" is then unused.
    ParamSpec metal = conductor_choice("ks");
    metal.help = "a measured metal: K_spec F from its complex index n + i k under each light (ior unused)";
    s.params.push_back(metal);
    s.derived = {{"lobe_norm", kMaxLobes, gaussian_norms}, {"spectral_table", 1, no_spectral_table}};
    s.glsl_lobe = "microfacet_lobe(mat)";
    s.glsl_control_lobe = "microfacet_dominant_lobe(mat)";
    return s;
}

ParamSpec tangent_axis() {
    ParamSpec p;
    p.name = "axis", p.label = "tangent axis", p.kind = ParamKind::direction, p.fallback = {0.0, 1.0, 0.0};
    p.help = "grooves run around this axis: T = normalize(axis x N)", p.cite = "docs/models.md";
    return p;
}

ModelSpec ward() {
    ModelSpec s = classic("ward", "Ward (anisotropic)", "Ward 1992 (seed 002)",
                          "Lambert + anisotropic Gaussian highlight, alpha_x along T, alpha_y across", true);
    s.params.push_back(number("alpha_x", "alpha_x", closed(0.001, 1.0), 0.15, "roughness along the tangent T",
                              "seed 002", true));
    s.params.push_back(number("alpha_y", "alpha_y", closed(0.001, 1.0), 0.5,
                              "roughness along the bitangent N x T", "seed 002", true));
    s.params.push_back(tangent_axis());
    s.glsl_lobe = "exponent_of_roughness(sqrt(mat.alpha_x * mat.alpha_y))";
    return s;
}

ModelSpec heidrich_seidel() {
    ModelSpec s = classic("heidrich_seidel", "Heidrich-Seidel (fibres)", "Heidrich & Seidel 1998 (seed 002)",
                          "Lambert + a highlight of fibres along the tangent T", true);
    s.params.push_back(shininess("exponent n of the fibre highlight", "seed 002"));
    s.params.push_back(tangent_axis());
    return s;
}

// ---- Burley's principled BRDF (docs/models.md#principled-burleys-principled-brdf) ---------

// A number of disney.brdf's parameter block: range [0, 1], its default.
ParamSpec principled_number(std::string name, std::string label, double fallback, std::string help) {
    return number(std::move(name), std::move(label), closed(0.0, 1.0), fallback, std::move(help),
                  "Burley 2012; disney.brdf");
}

// K_diff of the classic family's composer (mat.kd in glsl/models/classic.glsl,
// reference/classic_models.cpp): the diffuse hook's factor multiplies the base
// colour, as Burley's diffuse lobe is baseColor / pi times its retro-reflection.
void principled_kd(const Material& material, float* out) {
    const dvec3 c = material.vec3("base_color");
    out[0] = float(c.r), out[1] = float(c.g), out[2] = float(c.b);
}

// Burley 2012, as BRDF Explorer's disney.brdf implements it. The classic family
// with ka and emission (ambient, emission, spot and attenuation as every classic
// model); the diffuse hook is the Disney diffuse (with subsurface) times
// (1 - metallic), the specular hook the sheen, the GTR2 specular and the GTR1
// clear coat. Ranges and defaults are disney.brdf's parameter block.
ModelSpec principled() {
    ModelSpec s;
    s.name = "principled", s.label = "principled (Disney)";
    s.citation = "Burley 2012, Physically-Based Shading at Disney (BRDF Explorer's disney.brdf)";
    s.summary = "Disney's principled BRDF: base colour, subsurface, metallic, specular, roughness, anisotropy, "
                "sheen, clear coat";
    s.family = Family::classic;
    // disney.brdf's default baseColor (.82, .67, .16) is a monitor value that its
    // mon2lin (x^2.2) linearizes; here colours are linear (the M3055 has no gamma,
    // docs/spec.md#2-display), so the default is that colour linearized.
    const dvec3 base_default = {std::pow(0.82, 2.2), std::pow(0.67, 2.2), std::pow(0.16, 2.2)};
    ParamSpec base = colour("base_color", "base colour", base_default,
                            "surface colour, linear (disney.brdf's baseColor after its mon2lin): the diffuse "
                            "colour, and the specular colour as metallic goes to 1",
                            "Burley 2012");
    base.carry_from = {"kd", "color"};
    ParamSpec ka = colour("ka", "K_amb", base_default, "ambient colour (the base colour unless given)",
                          "seed 001, 003");
    ka.default_from = "base_color";
    ka.carry_from = {"color"};
    s.params = {base, ka, colour("emission", "emission", {0, 0, 0}, "emitted light L_emi, added as is", "seed 003")};
    s.params.push_back(principled_number("subsurface", "subsurface", 0.0,
                                         "blends the diffuse towards Hanrahan-Krueger's subsurface approximation: "
                                         "flatter, darker at the rim"));
    s.params.push_back(principled_number("metallic", "metallic", 0.0,
                                         "0 dielectric, 1 metal: no diffuse or sheen, the specular takes the base "
                                         "colour"));
    s.params.push_back(principled_number("specular", "specular", 0.5,
                                         "dielectric reflectance at normal incidence, 0.08 x specular (0.5: 4 %, "
                                         "an index of 1.5)"));
    s.params.push_back(principled_number("specular_tint", "specular tint", 0.0,
                                         "tints the dielectric specular towards the base colour's hue"));
    s.params.push_back(principled_number("roughness", "roughness", 0.5,
                                         "perceptual roughness r: GGX alpha = r^2 (at least 0.001); also the "
                                         "diffuse retro-reflection"));
    s.params.push_back(principled_number("anisotropic", "anisotropic", 0.0,
                                         "aspect of the specular: alpha_x = r^2 / aspect along T, alpha_y = r^2 "
                                         "aspect, aspect = sqrt(1 - 0.9 anisotropic)"));
    s.params.push_back(principled_number("sheen", "sheen", 0.0, "a grazing Fresnel lobe for cloth"));
    s.params.push_back(
        principled_number("sheen_tint", "sheen tint", 0.5, "tints the sheen towards the base colour's hue"));
    s.params.push_back(principled_number("clearcoat", "clear coat", 0.0,
                                         "a second, white specular lobe (GTR1, F0 0.04) of weight 0.25 clearcoat"));
    s.params.push_back(principled_number("clearcoat_gloss", "clear coat gloss", 1.0,
                                         "the clear coat's GTR1 alpha from 0.1 (0: satin) to 0.001 (1: gloss)"));
    s.params.push_back(tangent_axis());
    s.misplaced_hints = {{"kd", "its base colour is \"base_color\""}, {"color", "its base colour is \"base_color\""}};
    s.glsl_file = "models/principled.glsl";
    s.glsl_hook = "diffuse_principled";
    s.glsl_specular = "specular_principled";
    s.glsl_lobe = "exponent_of_roughness(max(mat.roughness * mat.roughness, 0.001))";
    // kd: K_diff for the composer; spectral_table: read by the composer, -1 (no spectra here).
    s.derived = {{"kd", 3, principled_kd}, {"spectral_table", 1, no_spectral_table}};
    return s;
}

}  // namespace

std::vector<ModelSpec> builtin_models() {
    std::vector<ModelSpec> out = {highlight(), translucent(), metal(), metal_blinn(), metal_phong()};
    for (ModelSpec& s : diffuse_models()) out.push_back(std::move(s));
    for (ModelSpec s : {phong(), blinn_phong(), microfacet(), ward(), heidrich_seidel()}) out.push_back(std::move(s));
    out.push_back(principled());
    return out;
}

}  // namespace m3055
