#include "frame/frame_sequence.h"

#include "passes/camera_uniforms.h"

namespace m3055 {

FrameSequence::FrameSequence(const GlApi& gl, FrameTargets& targets, const Scene& scene, AreaSampling sampling)
    : gl_(gl), targets_(targets), scene_(scene),
      camera_(make_camera_frame(scene.camera, scene.display, scene.objects)),
      lights_(pack_lights(scene.lights, scene.ambient, sampling)) {}

void FrameSequence::begin() { targets_.begin(scene_); }

void FrameSequence::use_program(unsigned program) const {
    gl_.UseProgram(program);
    targets_.set_material_uniforms(program);
    set_camera_uniforms(gl_, program, camera_);
    upload_lights(gl_, program, lights_);
    if (lights_.any_shadow) targets_.set_occluder_uniforms(program);
}

void FrameSequence::finish() { targets_.quantize(scene_.display); }  // docs/spec.md#2-display

}  // namespace m3055
