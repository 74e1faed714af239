#include "explore_ui/readout_requests.h"

#include "image/image.h"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace m3055::explore {

namespace {

// "profile row Y bits B<TAB>R l l l ...<TAB>G ...<TAB>B ..." ("profile_b ..." for B's, dashed)
void print_profile(const RowProfile& profile, const char* name = "profile") {
    std::string line = std::string(name) + " row " + std::to_string(profile.row) + " bits " + std::to_string(profile.bits);
    const char* names[3] = {"R", "G", "B"};
    for (std::size_t c = 0; c < 3; ++c) {
        line += std::string("\t") + names[c];
        for (int level : profile.levels[c]) line += " " + std::to_string(level);
    }
    std::printf("%s\n", line.c_str());
}

void answer(const std::string& request, ExplorerState& state, Readouts& readouts, Renderer& a, CompareView& compare,
            Renderer& b) {
    if (request == "profile") {
        const RowProfile* profile = readouts.profile(state, a);
        if (!profile) throw std::runtime_error("print_profile: no row hovered yet");
        print_profile(*profile);
        if (state.compare) {  // B's row, as the plot draws it dashed
            compare.update(state, readouts.display_image(a), b);
            print_profile(row_profile(compare.b_display(), state.scene.display.bits, profile->row), "profile_b");
        }
        return;
    }
    if (!state.compare) throw std::runtime_error(request + ": the A/B split is off");
    compare.update(state, readouts.display_image(a), b);
    if (request == "compare") {
        const grading::LevelDifference& d = compare.difference();
        std::printf("compare differing=%llu pixels=%llu scale=%d\n", static_cast<unsigned long long>(d.differing),
                    static_cast<unsigned long long>(d.pixels), compare.scale_used());
    } else {  // "save_difference PATH"
        if (!state.compare_diff) throw std::runtime_error("save_difference: the difference pane is off");
        write_png(request.substr(request.find(' ') + 1), compare.difference_image());
    }
}

}  // namespace

void answer_readout_requests(ExplorerState& state, Readouts& readouts, Renderer& a, CompareView& compare,
                             Renderer& b) {
    for (const std::string& request : state.readout_requests) {
        try {
            answer(request, state, readouts, a, compare, b);
        } catch (const std::exception& e) {
            state.error = e.what();
            std::fprintf(stderr, "%s\n", e.what());
        }
    }
    if (!state.readout_requests.empty()) std::fflush(stdout);
    state.readout_requests.clear();
}

}  // namespace m3055::explore
