// `m3055 models`: the model table as a scene's author reads it: each built-in
// model's name, family, citation and summary, then its parameters with kind,
// range, default and meaning. `--names` prints only the names, one a line (the
// fuzz dictionary and scripts/check-identical take them from here, so a model
// added to the table is covered without editing them).
#include "commands.h"

#include "io/message_text.h"
#include "models/model_spec.h"
#include "models/model_table.h"

#include <iostream>
#include <sstream>

namespace m3055 {

namespace {

std::string default_text(const ParamSpec& param) {
    std::ostringstream out;
    switch (param.kind) {
        case ParamKind::choice: return param.choices.at(std::size_t(param.fallback.at(0)));
        case ParamKind::flag: return param.fallback.at(0) != 0.0 ? "true" : "false";
        case ParamKind::lobes: {
            for (const Lobe& lobe : param.forms.front().fallback)
                out << (out.tellp() > 0 ? " " : "") << "{w " << text::format_number(lobe.w) << ", "
                    << param.forms.front().key << " " << text::format_number(lobe.m) << "}";
            return out.str();
        }
        default:
            for (std::size_t i = 0; i < param.fallback.size(); ++i)
                out << (i ? ", " : "") << text::format_number(param.fallback[i]);
            return param.fallback.size() > 1 ? "[" + out.str() + "]" : out.str();
    }
}

std::string range_text(const ParamSpec& param) {
    switch (param.kind) {
        case ParamKind::number: return param.range.text();
        case ParamKind::colour: return "each in [0, 1]";
        case ParamKind::direction: return "non-zero, made unit";
        case ParamKind::choice: {
            std::string all;
            for (const std::string& choice : param.choices) all += (all.empty() ? "" : " | ") + choice;
            return all;
        }
        case ParamKind::flag: return "true | false";
        case ParamKind::lobes: return "1 to " + std::to_string(kMaxLobes) + " lobes";
    }
    return "";
}

void print_model(const ModelSpec& model) {
    std::cout << model.name << "  (" << to_string(model.family) << "; " << model.citation << ")\n  "
              << model.summary << "\n";
    for (const ParamSpec& param : model.params)
        std::cout << "    " << param.name << (param.required ? " (required)" : "") << ": " << to_string(param.kind)
                  << ", " << range_text(param) << ", default " << (param.default_from.empty()
                                                                    ? default_text(param)
                                                                    : "its " + param.default_from)
                  << " - " << param.help << " [" << param.cite << "]\n";
}

}  // namespace

void add_models_command(CLI::App& app) {
    auto names_only = std::make_shared<bool>(false);
    CLI::App* command = app.add_subcommand("models", "List the built-in reflection models and their parameters");
    command->add_flag("--names", *names_only, "Only the model names, one a line");
    command->callback([names_only]() {
        const ModelTable& table = model_table();
        for (int id = 0; id < table.builtin_count(); ++id) {
            if (*names_only) {
                std::cout << table.at(id).name << "\n";
            } else {
                if (id) std::cout << "\n";
                print_model(table.at(id));
            }
        }
    });
}

}  // namespace m3055
