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
    // Encode both before writing: a PFM that cannot be written must not leave
    // a new PNG behind either (the PNG is written last, after the PFM).
    if (!raw_path.empty()) write_pfm(raw_path, raw);
    write_png(png_path, display);
}

}  // namespace m3055
