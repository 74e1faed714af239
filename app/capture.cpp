#include "capture.h"

#include "image/image.h"

namespace m3055 {

Capture::Capture(Backend backend)
    : context_(HeadlessContext::create(backend)), renderer_(std::make_unique<Renderer>(context_->gl())) {}

void Capture::render_to_files(const Scene& scene, const std::string& png_path, const std::string& raw_path) {
    renderer_->render(scene);
    // Read both images before writing either, so a GL failure leaves no file.
    const Rgb8Image display = renderer_->read_display();
    RgbFloatImage raw;
    if (!raw_path.empty()) raw = renderer_->read_raw();
    write_capture_files(png_path, display, raw_path, raw);
}

void write_capture_files(const std::string& png_path, const Rgb8Image& display, const std::string& raw_path,
                         const RgbFloatImage& raw) {
    // Both files or neither: a PFM that cannot be written must not leave a new
    // PNG behind, nor the other way round.
    std::vector<FileContents> files = {{png_path, encode_png(display)}};
    if (!raw_path.empty()) files.push_back({raw_path, encode_pfm(raw)});
    write_files_atomic(files);
}

}  // namespace m3055
