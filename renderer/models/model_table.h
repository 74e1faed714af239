// The model table: every reflection model the renderer knows, as data
// (models/model_spec.h). The built-in models are registered on first use
// (models/builtin_models.cpp); more can be added at run time with add().
//
// The table is mutated only from the thread that renders (the explorer's and
// the CLI's main thread), before the scenes that use the new model are
// rendered; entries are never removed or moved, so a `const ModelSpec&` stays
// valid for the life of the process.
#pragma once

#include "models/model_spec.h"

#include <cstdint>
#include <deque>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace m3055 {

class ModelTable {
public:
    // Validates `spec` (names, kinds, ranges, defaults, hooks for its family;
    // std::invalid_argument naming the model and the problem), lays out its
    // values and GPU record, and appends it. A name already in the table is an
    // error.
    const ModelSpec& add(ModelSpec spec);

    const ModelSpec* find(std::string_view name) const;  // nullptr if unknown
    const ModelSpec& get(std::string_view name) const;   // std::invalid_argument if unknown
    const ModelSpec& at(int id) const { return models_.at(static_cast<std::size_t>(id)); }
    const std::deque<ModelSpec>& models() const { return models_; }
    std::vector<std::string> names() const;  // in id order (the scene loader's list)

    // True for a key some built-in model reads: on another model it is
    // "not a parameter of model X" rather than an unknown key.
    bool is_builtin_param(std::string_view key) const;

    // GPU record size: the largest model's, in RGBA32F texels.
    int record_texels() const { return record_texels_; }
    // Grows by one with every add(): programs built from an older table are stale.
    std::uint64_t revision() const { return revision_; }
    // How many of the models are built in (the first builtin_count() ids).
    int builtin_count() const { return builtin_count_; }
    // A model whose GLSL does not compile (a .brdf file saved with an error)
    // stays in the table (references stay valid) but is left out of the
    // general programs (every_model_define), which would otherwise never
    // compile again and leave the explorer showing nothing new.
    void retire(const ModelSpec& spec) { retired_.insert(spec.id); }
    bool retired(const ModelSpec& spec) const { return retired_.count(spec.id) > 0; }

private:
    friend const ModelTable& model_table();
    friend ModelTable& mutable_model_table();
    ModelTable();

    std::deque<ModelSpec> models_;
    int record_texels_ = 1;
    std::uint64_t revision_ = 0;
    int builtin_count_ = 0;
    std::set<int> retired_;
};

// The process's table, with the built-in models registered.
const ModelTable& model_table();
// The same, for adding models at run time.
ModelTable& mutable_model_table();

// The built-in entries (models/builtin_models.cpp), in table order.
std::vector<ModelSpec> builtin_models();

}  // namespace m3055
