// The steps every render of a scene takes around its own draws, in this
// order: the scene's camera frame and lights worked out; begin() (materials
// uploaded, the scene target cleared to the background, depth state set);
// each draw's program made ready by use_program() (material, camera and light
// uniforms); finish() (the quantize pass into the display). The Renderer
// draws its spheres and meshes between begin() and finish(); the benchmark's
// UV-sphere renderer (app/bench/mesh_renderer.cpp) draws its meshes there, so
// the two frames differ only in their draws.
#pragma once

#include "gl/gl_api.h"
#include "passes/camera_frame.h"
#include "passes/frame_targets.h"
#include "passes/light_uniforms.h"
#include "scene/scene.h"

namespace m3055 {

class FrameSequence {
public:
    // `targets` and `scene` must outlive the sequence. `sampling`: the area
    // lights' (passes/light_uniforms.h).
    FrameSequence(const GlApi& gl, FrameTargets& targets, const Scene& scene,
                  AreaSampling sampling = kRenderSampling);

    const CameraFrame& camera() const { return camera_; }
    const LightUniforms& lights() const { return lights_; }

    void begin();
    void use_program(unsigned program) const;  // binds it, with its uniforms set
    void finish();

private:
    const GlApi& gl_;
    FrameTargets& targets_;
    const Scene& scene_;
    CameraFrame camera_;
    LightUniforms lights_;
};

}  // namespace m3055
