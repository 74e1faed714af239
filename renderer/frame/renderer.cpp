#include "frame/renderer.h"

#include "frame/frame_sequence.h"
#include "geometry/mesh.h"
#include "gl/program.h"
#include "passes/camera_frame.h"
#include "passes/draw_chunks.h"
#include "passes/frame_targets.h"
#include "passes/light_uniforms.h"
#include "passes/mesh_pass.h"
#include "passes/shader_plan.h"
#include "passes/sphere_bounds.h"
#include "passes/sphere_pass.h"
#include "passes/translucent_blend.h"
#include "models/material.h"
#include "io/message_text.h"
#include "scene/load.h"
#include "scene/presets.h"

#include <algorithm>
#include <iterator>
#include <set>
#include <utility>
#include <stdexcept>

namespace m3055 {
namespace {
// Every pass of the general programs: opaque and translucent, spheres and
// meshes, directional, point and spot lights.
Scene general_warm_up_scene() {
    Scene scene = default_scene();
    scene.display.width = 32;
    scene.display.height = 20;
    Object translucent = scene.objects[0];
    translucent.material = Material::of("translucent");
    translucent.center = {0.5, 0.0, 1.0};
    scene.objects.push_back(translucent);
    Object cube = scene.objects[0];
    cube.shape = Shape::cube;
    cube.size = 0.6;
    cube.center = {-1.2, 0.0, 0.0};
    scene.objects.push_back(cube);
    cube.material = Material::of("translucent");
    cube.center = {1.2, 0.0, 0.0};
    scene.objects.push_back(cube);
    Light point = scene.lights[0];
    point.type = LightType::point;
    point.position = {2.0, 2.0, 3.0};
    scene.lights.push_back(point);
    point.type = LightType::spot;
    point.spot_direction = {-2.0, -2.0, -3.0};
    scene.lights.push_back(point);
    return scene;
}
}  // namespace

struct Renderer::Impl {
    const GlApi& gl;
    std::unique_ptr<ProgramCache> own_programs;  // when no cache is shared
    ProgramCache& programs;
    FrameTargets targets;  // scene and display targets, materials, clear, quantize, read-backs
    std::unique_ptr<FrameTargets> reduced;  // render_reduced's smaller frame, made at its first use
    FrameTargets* drawing = &targets;       // the frame this render draws into
    std::optional<DisplayRegion> region;  // render_region: the only pixels drawn
    MeshPass meshes;       // planes, cubes, cylinders, tori (passes/mesh_pass.h)
    SpherePass spheres;    // passes/sphere_pass.h
    ShaderMode shader_mode = ShaderMode::specialized;
    TranslucentBlend blend;       // set_translucent_blend; default_translucent_blend at first
    TranslucentBlender blender;   // the two-pass draws
    AreaSampling sampling = kRenderSampling;  // set_area_sampling
    bool defer_compiles = false;         // set_defer_compiles
    std::set<ProgramKey> deferred;       // specialized programs not built yet (render_specialized)
    ChunkedDraws::Deadline deadline;  // set_deadline
    std::optional<ChunkedDraws> chunks;  // this render's (passes/draw_chunks.h)

    Impl(const GlApi& api, std::unique_ptr<ProgramCache> own, ProgramCache* shared)
        : gl(api), own_programs(std::move(own)), programs(shared ? *shared : *own_programs), targets(api, programs),
          meshes(api), spheres(api), blend(default_translucent_blend(api)), blender(api) {}

    // Draws the opaque meshes, or the index range of one translucent mesh
    // (`only`), in chunks, deadline or not: llvmpipe keeps every triangle's
    // set-up data of one draw call until it is rasterized, and 4 million
    // triangles in one call took 2.3 GB more at 8192 x 8192 than in chunks
    // (docs/limits.md). The pixels are the same.
    // `two_pass_program`: the translucent mesh's program in use when the blend
    // is two_pass (passes/translucent_blend.h), 0 otherwise.
    void draw_meshes(const CameraFrame& frame, std::size_t lights, const MeshPass::Translucent* only,
                     unsigned two_pass_program = 0) {
        std::vector<DrawSpan> spans;
        std::vector<MeshPass::Range> ranges = meshes.opaque_ranges();
        if (only) ranges = {{only->first, only->count, only->object}};
        for (const MeshPass::Range& range : ranges) {
            const auto rect = sphere_ndc_rect(frame, range.object->center, geometry::bounding_radius(*range.object));
            if (rect) spans.push_back(chunks->span_of(range.first, range.count, range.count / 3, rect->data(), lights));
            else spans.push_back(DrawSpan{range.first, range.count, kPrimitiveWork * double(range.count / 3), 0, 0});
        }
        chunks->run(plan_chunks(spans, kChunkWork, 3), [&](std::size_t first, std::size_t count) {
            if (!two_pass_program) return meshes.draw(first, count, only != nullptr);
            // Back faces culled, a convex shape covers each pixel at most once.
            const bool convex = only->object->shape != Shape::torus && only->object->shape != Shape::mesh;
            blender.draw_two_pass(two_pass_program, [&] { meshes.draw(first, count, true); }, convex);
        });
    }

    // The defines of a pass over `objects` (passes/shader_plan.h), and the lobe's
    // closed form where the sampling asks for it and the scene has an area light
    // (the render's and the explorer's preview: kRenderSampling, kFastSampling).
    std::vector<std::string> defines_of(const std::vector<const Object*>& objects, const std::vector<Light>& lights) const {
        std::vector<std::string> defines = specialization_defines(shader_mode, objects, lights);
        if (sampling.lobe_closed_form &&
            std::find(defines.begin(), defines.end(), "HAS_AREA_LIGHTS") != defines.end())
            defines.push_back(kLobeClosedFormDefine);
        return defines;
    }

    // The program for `key`; with deferral, a specialized one not built yet is
    // noted and the general program of the same pass stands in (same pixels).
    // Where the stand-in is not built either (the general programs warmed up
    // at start have no area lights or shadows), the specialized program is
    // built at once: it costs no more than the stand-in would, and the
    // refine needs it anyway (a scene opened with area lights: one compile,
    // not two; docs/lights.md).
    unsigned program(const ProgramKey& key, bool translucent_pass) {
        if (!defer_compiles || shader_mode != ShaderMode::specialized || programs.contains(key))
            return programs.get(key);
        std::vector<std::string> general = specialization_defines(ShaderMode::general, {}, {});
        for (const char* feature : {"HAS_AREA_LIGHTS", "HAS_SHADOWS", kLobeClosedFormDefine})  // as the key has them
            if (std::find(key.defines.begin(), key.defines.end(), feature) != key.defines.end())
                general.push_back(feature);
        if (translucent_pass) general.push_back("TRANSLUCENT_PASS");
        if (translucent_pass && blend == TranslucentBlend::two_pass) general.push_back(kTwoPassBlendDefine);
        const ProgramKey stand_in{key.vertex, key.fragment, general};
        if (!programs.contains(stand_in)) return programs.get(key);
        deferred.insert(key);
        return programs.get(stand_in);
    }

    // A run of spheres with `program`; `two_pass`: a translucent run drawn with the two-pass blend.
    void draw_spheres(unsigned program, const std::vector<SphereInstance>& instances, const FrameSequence& sequence,
                      bool two_pass = false) {
        if (instances.empty()) return;
        sequence.use_program(program);
        spheres.draw(instances, deadline ? &*chunks : nullptr, sequence.lights().work,
                     two_pass ? &blender : nullptr, program, drawing->width(), drawing->height());
    }

    // Pass 1: opaque spheres and meshes, with depth.
    void draw_opaque(const Scene& scene, const SphereSets& sets, const FrameSequence& sequence) {
        if (!sets.opaque.empty()) {
            const auto defines = defines_of(sets.opaque_objects, scene.lights);
            draw_spheres(program({"passes/sphere.vert", "passes/sphere.frag", defines}, false), sets.opaque,
                         sequence);
        }
        if (!meshes.opaque_objects().empty()) {
            const auto defines = defines_of(meshes.opaque_objects(), scene.lights);
            sequence.use_program(program({"passes/mesh.vert", "passes/mesh.frag", defines}, false));
            draw_meshes(sequence.camera(), sequence.lights().work, nullptr);
        }
    }

    // Pass 2: translucent spheres and meshes over what is behind them (docs/spec.md#42-translucent),
    // as a premultiplied "over" with a per-channel transmittance,
    // dst = src0 + src1 * dst: dual-source blending, or the same in two draws
    // per layer (passes/translucent_blend.h). Spheres and meshes merged far to
    // near: runs of spheres between meshes. Skipped when there are none.
    void draw_translucent(const Scene& scene, const SphereSets& sets, const FrameSequence& sequence) {
        if (sets.translucent.empty() && meshes.translucent().empty()) return;
        gl.DepthMask(GL_FALSE);
        blender.begin(blend);
        const bool two_pass = blend == TranslucentBlend::two_pass;
        auto defines = defines_of(sets.translucent_objects, scene.lights);
        defines.push_back("TRANSLUCENT_PASS");
        auto mesh_defines = defines_of(meshes.translucent_objects(), scene.lights);
        mesh_defines.push_back("TRANSLUCENT_PASS");
        if (two_pass) {
            defines.push_back(kTwoPassBlendDefine);
            mesh_defines.push_back(kTwoPassBlendDefine);
        }
        std::vector<MeshPass::Translucent> mesh_order = meshes.translucent();
        std::stable_sort(mesh_order.begin(), mesh_order.end(),
                         [](const auto& a, const auto& b) { return a.key > b.key; });
        const auto& sorted = sets.translucent;
        std::size_t next_sphere = 0;
        for (std::size_t m = 0; m <= mesh_order.size(); ++m) {
            std::vector<SphereInstance> run;
            while (next_sphere < sorted.size() &&
                   (m == mesh_order.size() || sorted[next_sphere].first >= mesh_order[m].key))
                run.push_back(sorted[next_sphere++].second);
            if (!run.empty())
                draw_spheres(program({"passes/sphere.vert", "passes/sphere.frag", defines}, true), run, sequence,
                             two_pass);
            if (m == mesh_order.size()) break;
            const unsigned mesh_program = program({"passes/mesh.vert", "passes/mesh.frag", mesh_defines}, true);
            sequence.use_program(mesh_program);
            draw_meshes(sequence.camera(), sequence.lights().work, &mesh_order[m],
                        two_pass ? mesh_program : 0);
        }
        gl.Disable(GL_BLEND);
        gl.DepthMask(GL_TRUE);
    }

    // A render that stops part way (RenderTimeout, a GL error) leaves the GL
    // state the next one assumes: a depth write mask left off would even stop
    // the next frame's depth clear.
    void render(const Scene& scene) {
        try {
            draw_scene(scene);
        } catch (...) {
            gl.DepthMask(GL_TRUE);
            gl.Disable(GL_BLEND);
            gl.Disable(GL_STENCIL_TEST);
            gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            gl.Disable(GL_SCISSOR_TEST);
            gl.Disable(GL_CULL_FACE);
            gl.Disable(GL_DEPTH_TEST);
            gl.BindVertexArray(0);
            gl.UseProgram(0);
            gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
            throw;
        }
    }

    void draw_scene(const Scene& scene) {
        chunks.emplace(gl, deadline, scene.display.width, scene.display.height);
        if (region) {
            chunks->clip_to(*region);
            gl.Enable(GL_SCISSOR_TEST);  // the clear, the draws and the quantize pass: only these pixels
            gl.Scissor(region->x0, region->y0, region->x1 - region->x0, region->y1 - region->y0);
        }
        chunks->check_deadline();  // loading the scene may have taken it all
        FrameSequence sequence(gl, *drawing, scene, sampling);
        const SphereSets sets = sort_spheres(scene, sequence.camera());
        meshes.prepare(scene, sequence.camera());
        chunks->check_deadline();  // up to 4 million triangles tessellated
        drawing->set_stencil(blend == TranslucentBlend::two_pass);
        sequence.begin();  // background and depth cleared
        draw_opaque(scene, sets, sequence);
        draw_translucent(scene, sets, sequence);
        sequence.finish();  // Pass 3: the display's levels
        gl.Disable(GL_SCISSOR_TEST);
    }
};

Renderer::Renderer(const GlApi& gl, ProgramCache& programs)
    : impl_(std::make_unique<Impl>(gl, nullptr, &programs)) {}
Renderer::Renderer(const GlApi& gl) : impl_(std::make_unique<Impl>(gl, std::make_unique<ProgramCache>(gl), nullptr)) {}
Renderer::~Renderer() = default;
void Renderer::render(const Scene& scene) { impl_->render(scene); }
void Renderer::render_region(const Scene& scene, const DisplayRegion& box) {
    if (impl_->targets.width() != scene.display.width || impl_->targets.height() != scene.display.height)
        throw std::logic_error("render_region: the display was not drawn at this size");
    DisplayRegion region;
    region.x0 = std::clamp(box.x0, 0, scene.display.width);
    region.x1 = std::clamp(box.x1, region.x0, scene.display.width);
    region.y0 = std::clamp(box.y0, 0, scene.display.height);
    region.y1 = std::clamp(box.y1, region.y0, scene.display.height);
    if (region.x1 == region.x0 || region.y1 == region.y0) return;
    const bool defer = impl_->defer_compiles;
    impl_->defer_compiles = false;
    impl_->region = region;
    try {
        impl_->render(scene);
    } catch (...) {
        impl_->region.reset();
        impl_->defer_compiles = defer;
        throw;
    }
    impl_->region.reset();
    impl_->defer_compiles = defer;
    for (auto key = impl_->deferred.begin(); key != impl_->deferred.end();)
        key = impl_->programs.contains(*key) ? impl_->deferred.erase(key) : std::next(key);
}

void Renderer::render_reduced(const Scene& scene, int divisor) {
    if (divisor <= 1) return impl_->render(scene);
    Scene small = scene;
    small.display.width = std::max(1, (scene.display.width + divisor - 1) / divisor);
    small.display.height = std::max(1, (scene.display.height + divisor - 1) / divisor);
    if (!impl_->reduced) impl_->reduced = std::make_unique<FrameTargets>(impl_->gl, impl_->programs);
    impl_->drawing = impl_->reduced.get();
    try {
        impl_->render(small);
    } catch (...) {
        impl_->drawing = &impl_->targets;
        throw;
    }
    impl_->drawing = &impl_->targets;
    impl_->targets.show_scaled(*impl_->reduced, scene.display.width, scene.display.height);
}
void Renderer::set_shader_mode(ShaderMode mode) { impl_->shader_mode = mode; }
void Renderer::set_deadline(std::optional<std::chrono::steady_clock::time_point> deadline) {
    impl_->deadline = deadline;
}
void Renderer::set_translucent_blend(TranslucentBlend blend) { impl_->blend = blend; }
TranslucentBlend Renderer::translucent_blend() const { return impl_->blend; }
void Renderer::set_area_sampling(AreaSampling sampling) {
    impl_->sampling = {std::max(sampling.light, 1), std::max(sampling.shadow, 2), sampling.lobe_closed_form};
}
AreaSampling Renderer::area_sampling() const { return impl_->sampling; }
void Renderer::set_defer_compiles(bool on) { impl_->defer_compiles = on; }
bool Renderer::defers_compiles() const { return impl_->defer_compiles; }
void Renderer::render_specialized(const Scene& scene) {
    const bool defer = impl_->defer_compiles;
    impl_->defer_compiles = false;
    try {
        impl_->render(scene);
    } catch (...) {
        impl_->defer_compiles = defer;
        throw;
    }
    impl_->defer_compiles = defer;
    impl_->deferred.clear();
}

void Renderer::warm_up_general_programs() {
    const ShaderMode mode = impl_->shader_mode;
    impl_->shader_mode = ShaderMode::general;
    try {
        impl_->render(general_warm_up_scene());
    } catch (...) {
        impl_->shader_mode = mode;
        throw;
    }
    impl_->shader_mode = mode;
}
std::size_t Renderer::deferred_programs() const { return impl_->deferred.size(); }
std::size_t Renderer::compiled_programs() const { return impl_->programs.size(); }
unsigned Renderer::display_texture() const { return impl_->targets.display_texture(); }
int Renderer::width() const { return impl_->targets.width(); }
int Renderer::height() const { return impl_->targets.height(); }
Rgb8Image Renderer::read_display() const { return impl_->targets.read_display(); }
RgbFloatImage Renderer::read_raw() const { return impl_->targets.read_raw(); }

}  // namespace m3055
