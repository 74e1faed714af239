// Headless capture shared by `render`, `figures`, `batch`, `compare` and
// `grade`: one context and renderer, reused for many scenes.
#pragma once

#include "gl/context.h"
#include "frame/renderer.h"
#include "analysis/nonfinite.h"
#include "scene/scene.h"

#include <chrono>
#include <functional>
#include <optional>
#include <memory>
#include <string>

namespace m3055 {

// Writes the PNG and, when raw_path is not empty, the PFM: both or neither.
// `committed` runs once both are in place, under the file-commit lock
// (image/temporary_files.h), so an interrupt's count of what was written is exact.
void write_capture_files(const std::string& png_path, const Rgb8Image& display, const std::string& raw_path,
                         const RgbFloatImage& raw, const std::function<void()>& committed = {});

// A scene's time budget (`--scene-timeout SECONDS`): from
// when it starts loading to its last draw; encoding and writing the files are
// not counted (bounded by the display's size). 0: no limit.
std::optional<std::chrono::steady_clock::time_point> scene_deadline(std::chrono::steady_clock::time_point start,
                                                                    double seconds);
// "SCENE: over its time budget: not drawn within 30 s (--scene-timeout 30)".
std::string over_budget_message(const std::string& scene_path, double seconds);

// "m3055: warning: SCENE: 12 pixels are NaN in the render (...)": what
// `render` and `batch` print for a render with non-finite pixels.
std::string nonfinite_warning(const std::string& scene_path, const NonFinite& nonfinite);

class Capture {
public:
    // `context`: made by the caller, who decides what the process does
    // before its first context (app/headless_context.h).
    explicit Capture(std::unique_ptr<HeadlessContext> context);
    // Renders `scene` and writes the PNG (and the PFM when raw_path is not
    // empty), each atomically. Throws on any failure; writes nothing then.
    // `nonfinite`, when given: the render's NaN and infinite pixels, counted.
    void render_to_files(const Scene& scene, const std::string& png_path, const std::string& raw_path,
                         const std::function<void()>& committed = {}, NonFinite* nonfinite = nullptr);
    const HeadlessContext& context() const { return *context_; }
    Renderer& renderer() { return *renderer_; }

private:
    std::unique_ptr<HeadlessContext> context_;
    std::unique_ptr<Renderer> renderer_;
};

}  // namespace m3055
