// `m3055 compare A B`: two images (PNG, PFM, or a scene rendered first) at the
// display's own precision. Exit 0: pass; 1: warn or fail (the
// result line or "result" in --json says which); 2: error (unreadable input,
// sizes differ, bad option). `m3055 compare A_DIR B_DIR`: the PNGs of two
// folders by name, one summary line; exit 0 when every pair passes and no name
// is in one folder only, 1 otherwise, 2 when a pair could not be compared.
// The comparison is grading/.
#include "commands.h"
#include "headless_context.h"
#include "progress.h"
#include "slow_note.h"

#include "capture/capture.h"
#include "gl/program.h"
#include "grading/comparison_json.h"
#include "grading/diff_image.h"
#include "grading/folder_compare.h"
#include "grading/image_input.h"
#include "grading/level_compare.h"
#include "io/message_text.h"
#include "io/run_files.h"
#include "scene/load.h"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace m3055 {

namespace {

struct CompareOptions {
    std::string a, b, diff, backend = "auto";
    bool json = false;
    int bits = 5;
    int fail_levels = 0, warn_levels = -1;
    double fail_percent = 0, warn_percent = -1;
};

// Loads both inputs; a scene is rendered, and a PNG or PFM is read at the
// scene's bits when the other input is a scene, else at --bits. The sizes are
// checked before a scene is rendered (a shadowed sky takes minutes).
std::pair<grading::LevelImage, grading::LevelImage> load_inputs(const CompareOptions& options) {
    std::optional<Scene> scenes[2];
    const std::string paths[2] = {options.a, options.b};
    int bits = options.bits;
    for (int i = 0; i < 2; ++i)
        if (grading::input_kind(paths[i]) == grading::InputKind::scene) {
            scenes[i] = load_scene_file(paths[i], LoadContext::trusted());
            bits = scenes[i]->display.bits;
        }
    grading::LevelImage images[2];
    for (int i = 0; i < 2; ++i)
        if (!scenes[i]) images[i] = grading::read_level_image(paths[i], bits);
    const auto size = [&](int i) {
        return scenes[i] ? std::pair{scenes[i]->display.width, scenes[i]->display.height}
                         : std::pair{images[i].width, images[i].height};
    };
    grading::check_same_size(size(0).first, size(0).second, size(1).first, size(1).second);
    std::unique_ptr<Capture> capture;
    for (int i = 0; i < 2; ++i) {
        if (!scenes[i]) continue;
        if (!capture) capture = std::make_unique<Capture>(make_headless_context(parse_backend(options.backend)));
        SlowNote note = drawing_note("drawing " + text::quote_name(paths[i]));
        images[i] = grading::render_levels(capture->renderer(), *scenes[i]);
        note.finished();
    }
    return {std::move(images[0]), std::move(images[1])};
}

void print_text(const grading::Comparison& c) {
    const auto percent = [&](std::uint64_t count) { return 100.0 * double(count) / double(c.pixels ? c.pixels : 1); };
    std::printf("size: %d x %d, %d bits a channel, %llu pixels\n", c.width, c.height, c.bits,
                (unsigned long long)c.pixels);
    std::printf("same level: %llu pixels (%.4f %%)\n", (unsigned long long)c.same_pixels, 100.0 * c.same_share());
    const char* names[3] = {"r", "g", "b"};
    for (int ch = 0; ch < 3; ++ch) {
        std::printf("levels off, %s:", names[ch]);
        for (std::size_t k = 0; k < c.histogram[ch].size(); ++k)
            if (c.histogram[ch][k]) std::printf(" %zu:%llu", k, (unsigned long long)c.histogram[ch][k]);
        std::printf("\n");
    }
    std::printf("largest: %d level%s\n", c.max_levels, c.max_levels == 1 ? "" : "s");
    std::printf("over --fail-levels %d: %llu pixels (%.4f %%, allowed %s %%)\n", c.thresholds.fail.levels,
                (unsigned long long)c.over_fail, percent(c.over_fail),
                text::format_number(c.thresholds.fail.percent).c_str());
    if (c.thresholds.warn)
        std::printf("over --warn-levels %d: %llu pixels (%.4f %%, allowed %s %%)\n", c.thresholds.warn->levels,
                    (unsigned long long)c.over_warn, percent(c.over_warn),
                    text::format_number(c.thresholds.warn->percent).c_str());
    if (c.linear)
        std::printf("linear: max %.6g, mean %.6g, RMS %.6g, PSNR %.2f dB\n", c.linear->max_abs, c.linear->mean_abs,
                    c.linear->rms, c.linear->psnr_db);
    std::printf("%s\n", grading::summary_line(c).c_str());
}

grading::Thresholds thresholds_of(const CompareOptions& options) {
    grading::Thresholds thresholds;
    thresholds.fail = {options.fail_levels, options.fail_percent};
    // Either warn option alone turns warnings on; the other defaults to 0.
    if (options.warn_levels >= 0 || options.warn_percent >= 0)
        thresholds.warn = grading::Threshold{std::max(0, options.warn_levels), std::max(0.0, options.warn_percent)};
    return thresholds;
}

int run_compare(const CompareOptions& options) {
    if (!options.diff.empty()) {
        io::RunFiles files;
        files.add_input(0, "A", options.a);
        files.add_input(0, "B", options.b);
        files.add_output(0, "--diff", options.diff);
        if (const auto problems = files.check(); !problems.empty()) throw std::runtime_error(problems.begin()->second);
    }
    const auto [a, b] = load_inputs(options);
    const grading::Comparison comparison = grading::compare_levels(a, b, thresholds_of(options));
    if (!options.diff.empty()) write_png(options.diff, grading::difference_image(a, b));
    if (options.json) {
        nlohmann::json out = grading::to_json(comparison);
        out["a"] = options.a;
        out["b"] = options.b;
        std::cout << out.dump() << "\n";
    } else {
        print_text(comparison);
    }
    return comparison.verdict == grading::Verdict::pass ? kExitOk : kExitFailure;
}

// `compare A_DIR B_DIR`: a line for each pair that does not pass and each
// name in one folder only, then the summary line (or one JSON object).
int run_compare_folders(const CompareOptions& options) {
    const grading::FolderComparison c =
        grading::compare_folders(options.a, options.b, options.bits, thresholds_of(options));
    const std::size_t passed = c.count(grading::Verdict::pass), warned = c.count(grading::Verdict::warn),
                      failed = c.count(grading::Verdict::fail), problems = c.problems();
    if (options.json) {
        nlohmann::json pairs = nlohmann::json::array();
        for (const grading::PngPair& pair : c.pairs) {
            nlohmann::json entry = pair.comparison ? grading::to_json(*pair.comparison)
                                                   : nlohmann::json{{"result", "error"}, {"problem", pair.problem}};
            entry["name"] = pair.name;
            pairs.push_back(std::move(entry));
        }
        const nlohmann::json out = {
            {"a", options.a}, {"b", options.b}, {"pairs", pairs}, {"only_a", c.only_a}, {"only_b", c.only_b},
            {"summary", {{"pass", passed}, {"warn", warned}, {"fail", failed}, {"error", problems}}}};
        std::cout << out.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    } else {
        for (const grading::PngPair& pair : c.pairs) {
            if (!pair.comparison)
                std::printf("error: %s: %s\n", pair.name.c_str(), pair.problem.c_str());
            else if (pair.comparison->verdict != grading::Verdict::pass)
                std::printf("%s: %s\n", pair.name.c_str(), grading::summary_line(*pair.comparison).c_str());
        }
        for (const std::string& name : c.only_a) std::printf("only in A: %s\n", name.c_str());
        for (const std::string& name : c.only_b) std::printf("only in B: %s\n", name.c_str());
        const std::size_t both = c.pairs.size();
        std::printf("%zu PNG%s in both folders: %zu pass, %zu warn, %zu fail, %zu could not be compared; %zu only in A, "
                    "%zu only in B\n",
                    both, both == 1 ? "" : "s", passed, warned, failed, problems, c.only_a.size(), c.only_b.size());
    }
    if (problems) return kExitUsage;
    return warned || failed || !c.only_a.empty() || !c.only_b.empty() ? kExitFailure : kExitOk;
}

}  // namespace

void add_compare_command(CLI::App& app) {
    auto options = std::make_shared<CompareOptions>();
    CLI::App* command = app.add_subcommand(
        "compare", "Compare two images (PNG, PFM, or a scene rendered first) level by level, or the PNGs of two "
                   "folders by name; exit 0 pass, 1 warn or fail (or a name in one folder only), 2 error");
    command->add_option("A", options->a, "First image: .png, .pfm, or a scene .json; or a folder of PNGs")->required();
    command->add_option("B", options->b, "Second image: .png, .pfm, or a scene .json; or a folder of PNGs")->required();
    command->add_option("--bits", options->bits, "Bits a channel of PNG/PFM inputs when neither is a scene")
        ->capture_default_str()
        ->check(CLI::Range(1, 8));
    command->add_option("--fail-levels", options->fail_levels, "A pixel is off when a channel differs by more levels")
        ->capture_default_str()
        ->check(CLI::Range(0, 255));
    command->add_option("--fail-percent", options->fail_percent, "Fail when more than this % of pixels are off")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 100.0));
    command->add_option("--warn-levels", options->warn_levels, "Warning threshold in levels (default: no warnings)")
        ->check(CLI::Range(0, 255));
    command->add_option("--warn-percent", options->warn_percent, "Warn when more than this % of pixels are over it")
        ->check(CLI::Range(0.0, 100.0));
    command->add_option("--diff", options->diff, "Write a false-colour image of the levels off, with a legend");
    command->add_flag("--json", options->json, "Print the result as one JSON object");
    command->add_option("--backend", options->backend, "GL context for scene inputs: auto, egl or osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    command->callback([options]() {
        int status = kExitUsage;
        std::error_code error;
        const bool folder_a = std::filesystem::is_directory(options->a, error),
                   folder_b = std::filesystem::is_directory(options->b, error);
        if (folder_a != folder_b || ((folder_a || folder_b) && !options->diff.empty())) {
            std::cerr << error_line(std::string("compare: ") +
                                    (folder_a != folder_b ? "give two folders or two images: " +
                                                                text::quote_name(folder_a ? options->a : options->b) +
                                                                " is a folder, " +
                                                                text::quote_name(folder_a ? options->b : options->a) +
                                                                " is not"
                                                          : std::string("--diff names one image: not taken with two folders")))
                      << "\n";
            throw CLI::RuntimeError(kExitUsage);
        }
        try {
            status = folder_a ? run_compare_folders(*options) : run_compare(*options);
        } catch (const std::exception& error) {
            std::cerr << error_text(error) << "\n";
            throw CLI::RuntimeError(kExitUsage);
        }
        if (status != kExitOk) throw CLI::RuntimeError(status);
    });
}

}  // namespace m3055
