// Headless capture shared by `render`, `figures` (and later `batch`): one
// context and renderer, reused for many scenes.
#pragma once

#include "gl/context.h"
#include "renderer.h"
#include "scene/scene.h"

#include <memory>
#include <string>

namespace m3055 {

// Writes the PNG and, when raw_path is not empty, the PFM: both or neither.
void write_capture_files(const std::string& png_path, const Rgb8Image& display, const std::string& raw_path,
                         const RgbFloatImage& raw);

class Capture {
public:
    explicit Capture(Backend backend);
    // Renders `scene` and writes the PNG (and the PFM when raw_path is not
    // empty), each atomically. Throws on any failure; writes nothing then.
    void render_to_files(const Scene& scene, const std::string& png_path, const std::string& raw_path);
    const HeadlessContext& context() const { return *context_; }
    Renderer& renderer() { return *renderer_; }

private:
    std::unique_ptr<HeadlessContext> context_;
    std::unique_ptr<Renderer> renderer_;
};

}  // namespace m3055
