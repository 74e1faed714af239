#include "capture/capture.h"

#include "image/image.h"
#include "io/message_text.h"

#include <utility>

namespace m3055 {

Capture::Capture(std::unique_ptr<HeadlessContext> context)
    : context_(std::move(context)), renderer_(std::make_unique<Renderer>(context_->gl())) {}

void Capture::render_to_files(const Scene& scene, const std::string& png_path, const std::string& raw_path,
                              const std::function<void()>& committed, NonFinite* nonfinite) {
    renderer_->render(scene);
    // Read both images before writing either, so a GL failure leaves no file.
    const Rgb8Image display = renderer_->read_display();
    RgbFloatImage raw;
    if (!raw_path.empty() || nonfinite) raw = renderer_->read_raw();
    if (nonfinite) *nonfinite = count_nonfinite(raw);
    write_capture_files(png_path, display, raw_path, raw, committed);
}

std::optional<std::chrono::steady_clock::time_point> scene_deadline(std::chrono::steady_clock::time_point start,
                                                                    double seconds) {
    if (!(seconds > 0)) return std::nullopt;
    return start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
}

std::string nonfinite_warning(const std::string& scene_path, const NonFinite& nonfinite) {
    return text::one_line("m3055: warning: " + text::quote_name(scene_path) + ": " + nonfinite_text(nonfinite) +
                          " in the render (a material gives values that are not numbers; the display shows them as "
                          "some level)");
}

std::string over_budget_message(const std::string& scene_path, double seconds) {
    const std::string shown = text::format_number(seconds);
    return text::quote_name(scene_path) + ": over its time budget: not drawn within " + shown +
           " s (--scene-timeout " + shown + ")";
}

void write_capture_files(const std::string& png_path, const Rgb8Image& display, const std::string& raw_path,
                         const RgbFloatImage& raw, const std::function<void()>& committed) {
    // Both files or neither: a PFM that cannot be written must not leave a new
    // PNG behind, nor the other way round.
    std::vector<FileContents> files = {{png_path, encode_png(display)}};
    if (!raw_path.empty()) files.push_back(pfm_file(raw_path, raw));  // borrows raw's pixels, no 768 MiB copy
    write_files_atomic(files, committed);
}

}  // namespace m3055
