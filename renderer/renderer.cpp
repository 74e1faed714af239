#include "renderer.h"

#include "gl/program.h"
#include "passes/camera_frame.h"
#include "passes/camera_uniforms.h"
#include "passes/light_uniforms.h"
#include "passes/material_buffer.h"
#include "passes/mesh_pass.h"
#include "passes/shader_plan.h"
#include "passes/sphere_bounds.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <stdexcept>

namespace m3055 {
namespace {

// Per-instance data of the sphere quads (glsl/passes/sphere.vert).
struct SphereInstance {
    float sphere[4];  // centre, radius
    float rect[4];    // NDC rectangle
    int material;     // material record index = object index
};

// Back-to-front key of a sphere: the power of the eye with respect to it,
// |eye - c|^2 - r^2. For disjoint spheres the radical plane separates them, and
// the eye is on the side of the sphere with the smaller power, so this order is
// exact per pixel (sorting centres by distance is not, for unequal radii).
// Orthographic: the eye is at infinity along -f, where the order is by the
// centres' depth along f, then by the power.
double far_to_near_key(const CameraFrame& frame, const Object& object) {
    const dvec3 d = object.center - frame.position;
    if (frame.projection == Projection::orthographic) return glm::dot(d, frame.forward);
    return glm::dot(d, d) - object.radius * object.radius;
}

}  // namespace

struct Renderer::Impl {
    const GlApi& gl;
    ProgramCache programs;
    MeshPass meshes;  // planes, cubes, cylinders, tori (passes/mesh_pass.h)
    unsigned scene_fbo = 0, colour_texture = 0, depth_texture = 0;
    unsigned display_fbo = 0, display_tex = 0;
    unsigned material_buffer = 0, material_texture = 0;
    unsigned instance_buffer = 0, sphere_vao = 0, empty_vao = 0;
    int width = 0, height = 0;
    ShaderMode shader_mode = ShaderMode::specialized;

    explicit Impl(const GlApi& api) : gl(api), programs(api), meshes(api) {
        gl.GenVertexArrays(1, &sphere_vao);
        gl.GenVertexArrays(1, &empty_vao);
        gl.GenBuffers(1, &instance_buffer);
        gl.GenBuffers(1, &material_buffer);
        gl.GenTextures(1, &material_texture);

        gl.BindVertexArray(sphere_vao);
        gl.BindBuffer(GL_ARRAY_BUFFER, instance_buffer);
        const GLsizei stride = sizeof(SphereInstance);
        gl.EnableVertexAttribArray(0);
        gl.VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, stride, (void*)offsetof(SphereInstance, sphere));
        gl.VertexAttribDivisor(0, 1);
        gl.EnableVertexAttribArray(1);
        gl.VertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, (void*)offsetof(SphereInstance, rect));
        gl.VertexAttribDivisor(1, 1);
        gl.EnableVertexAttribArray(2);
        gl.VertexAttribIPointer(2, 1, GL_INT, stride, (void*)offsetof(SphereInstance, material));
        gl.VertexAttribDivisor(2, 1);
        gl.BindVertexArray(0);
    }

    ~Impl() {
        release_targets();
        gl.DeleteVertexArrays(1, &sphere_vao);
        gl.DeleteVertexArrays(1, &empty_vao);
        gl.DeleteBuffers(1, &instance_buffer);
        gl.DeleteBuffers(1, &material_buffer);
        gl.DeleteTextures(1, &material_texture);
    }

    void release_targets() {
        if (!scene_fbo) return;
        gl.DeleteFramebuffers(1, &scene_fbo);
        gl.DeleteFramebuffers(1, &display_fbo);
        unsigned textures[] = {colour_texture, depth_texture, display_tex};
        gl.DeleteTextures(3, textures);
        scene_fbo = display_fbo = 0;
    }

    unsigned make_texture(GLint internal_format, GLenum format, GLenum type, int w, int h) {
        unsigned texture = 0;
        gl.GenTextures(1, &texture);
        gl.BindTexture(GL_TEXTURE_2D, texture);
        gl.TexImage2D(GL_TEXTURE_2D, 0, internal_format, w, h, 0, format, type, nullptr);
        // Nearest: the explorer shows the display's dots as they are.
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        return texture;
    }

    void ensure_targets(int w, int h) {
        if (scene_fbo && w == width && h == height) return;
        release_targets();
        width = w, height = h;
        // Float colour: the raw output is unquantized and unclamped (metals exceed 1).
        colour_texture = make_texture(GL_RGBA32F, GL_RGBA, GL_FLOAT, w, h);
        depth_texture = make_texture(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, w, h);
        display_tex = make_texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, w, h);
        gl.GenFramebuffers(1, &scene_fbo);
        gl.BindFramebuffer(GL_FRAMEBUFFER, scene_fbo);
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_texture, 0);
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_texture, 0);
        check_framebuffer("scene");
        gl.GenFramebuffers(1, &display_fbo);
        gl.BindFramebuffer(GL_FRAMEBUFFER, display_fbo);
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, display_tex, 0);
        check_framebuffer("display");
    }

    void check_framebuffer(const char* name) {
        const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error(std::string("the ") + name + " framebuffer is incomplete (status " +
                                     std::to_string(status) + ") at " + std::to_string(width) + "x" +
                                     std::to_string(height));
    }

    void upload_materials(const Scene& scene) {
        std::vector<float> records;
        records.reserve(scene.objects.size() * kMaterialTexels * 4);
        for (const auto& object : scene.objects) pack_material(object.material, records);
        if (records.empty()) records.resize(kMaterialTexels * 4, 0.0f);
        gl.BindBuffer(GL_TEXTURE_BUFFER, material_buffer);
        gl.BufferData(GL_TEXTURE_BUFFER, GLsizeiptr(records.size() * sizeof(float)), records.data(), GL_STREAM_DRAW);
        gl.ActiveTexture(GL_TEXTURE0);
        gl.BindTexture(GL_TEXTURE_BUFFER, material_texture);
        gl.TexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, material_buffer);
    }

    void use_program(unsigned program, const CameraFrame& frame, const LightUniforms& lights) {
        gl.UseProgram(program);
        set_camera_uniforms(gl, program, frame);
        upload_lights(gl, program, lights);
    }

    void draw_spheres(unsigned program, const std::vector<SphereInstance>& instances,
                      const CameraFrame& frame, const LightUniforms& lights) {
        if (instances.empty()) return;
        use_program(program, frame, lights);
        gl.BindVertexArray(sphere_vao);
        gl.BindBuffer(GL_ARRAY_BUFFER, instance_buffer);
        gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(instances.size() * sizeof(SphereInstance)), instances.data(),
                      GL_STREAM_DRAW);
        // Instances are drawn, and blended, in buffer order: back to front.
        gl.DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(instances.size()));
    }

    void render(const Scene& scene) {
        const Display& display = scene.display;
        ensure_targets(display.width, display.height);
        const CameraFrame frame = make_camera_frame(scene.camera, display, scene.objects);
        const LightUniforms lights = pack_lights(scene.lights, scene.ambient);
        upload_materials(scene);

        // Split by pass; translucent spheres sorted far to near.
        std::vector<SphereInstance> opaque, translucent;
        std::vector<const Object*> opaque_objects, translucent_objects;
        std::vector<std::pair<double, SphereInstance>> sorted;
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            const Object& object = scene.objects[i];
            if (object.shape != Shape::sphere) continue;  // a mesh: MeshPass
            auto rect = sphere_ndc_rect(frame, object.center, object.radius);
            if (!rect) continue;
            SphereInstance instance{{float(object.center.x), float(object.center.y), float(object.center.z),
                                     float(object.radius)},
                                    {(*rect)[0], (*rect)[1], (*rect)[2], (*rect)[3]},
                                    int(i)};
            if (is_translucent(object.material.model)) {
                sorted.emplace_back(far_to_near_key(frame, object), instance);
                translucent_objects.push_back(&object);
            } else {
                opaque.push_back(instance);
                opaque_objects.push_back(&object);
            }
        }
        std::stable_sort(sorted.begin(), sorted.end(),
                         [](const auto& a, const auto& b) { return a.first > b.first; });
        for (const auto& entry : sorted) translucent.push_back(entry.second);
        meshes.prepare(scene, frame);

        // Pass 1: background and opaque spheres, with depth.
        gl.BindFramebuffer(GL_FRAMEBUFFER, scene_fbo);
        gl.Viewport(0, 0, width, height);
        const float background[4] = {float(scene.background.r), float(scene.background.g),
                                     float(scene.background.b), 1.0f};
        gl.ClearBufferfv(GL_COLOR, 0, background);
        const float far_depth = 1.0f;
        gl.ClearBufferfv(GL_DEPTH, 0, &far_depth);
        gl.Enable(GL_DEPTH_TEST);
        gl.DepthFunc(GL_LESS);
        gl.DepthMask(GL_TRUE);
        gl.Disable(GL_BLEND);
        if (!opaque.empty()) {
            const auto defines = specialization_defines(shader_mode, opaque_objects, scene.lights);
            draw_spheres(programs.get({"passes/sphere.vert", "passes/sphere.frag", defines}), opaque, frame, lights);
        }
        if (!meshes.opaque_objects().empty()) {
            const auto defines = specialization_defines(shader_mode, meshes.opaque_objects(), scene.lights);
            use_program(programs.get({"passes/mesh.vert", "passes/mesh.frag", defines}), frame, lights);
            meshes.draw_opaque();
        }

        // Pass 2: translucent spheres over what is behind them (SPEC 4.2), as a
        // premultiplied "over" with a per-channel transmittance: dual-source
        // blending, dst = src0 + src1 * dst. Skipped when there are none.
        if (!translucent.empty() || !meshes.translucent().empty()) {
            gl.DepthMask(GL_FALSE);
            gl.Enable(GL_BLEND);
            gl.BlendEquation(GL_FUNC_ADD);
            gl.BlendFunc(GL_ONE, GL_SRC1_COLOR);
            auto defines = specialization_defines(shader_mode, translucent_objects, scene.lights);
            defines.push_back("TRANSLUCENT_PASS");
            auto mesh_defines = specialization_defines(shader_mode, meshes.translucent_objects(), scene.lights);
            mesh_defines.push_back("TRANSLUCENT_PASS");
            // Spheres and meshes merged far to near: runs of spheres between meshes.
            std::vector<MeshPass::Translucent> mesh_order = meshes.translucent();
            std::stable_sort(mesh_order.begin(), mesh_order.end(),
                             [](const auto& a, const auto& b) { return a.key > b.key; });
            std::size_t next_sphere = 0;
            for (std::size_t m = 0; m <= mesh_order.size(); ++m) {
                std::vector<SphereInstance> run;
                while (next_sphere < sorted.size() &&
                       (m == mesh_order.size() || sorted[next_sphere].first >= mesh_order[m].key))
                    run.push_back(sorted[next_sphere++].second);
                if (!run.empty())
                    draw_spheres(programs.get({"passes/sphere.vert", "passes/sphere.frag", defines}), run, frame,
                                 lights);
                if (m == mesh_order.size()) break;
                use_program(programs.get({"passes/mesh.vert", "passes/mesh.frag", mesh_defines}), frame, lights);
                meshes.draw_translucent(mesh_order[m]);
            }
            gl.Disable(GL_BLEND);
            gl.DepthMask(GL_TRUE);
        }
        gl.Disable(GL_DEPTH_TEST);

        // Pass 3: quantize to the display's levels (SPEC 2).
        const unsigned quantize = programs.get({"passes/fullscreen.vert", "passes/quantize.frag", {}});
        gl.BindFramebuffer(GL_FRAMEBUFFER, display_fbo);
        gl.Viewport(0, 0, width, height);
        gl.UseProgram(quantize);
        gl.ActiveTexture(GL_TEXTURE0);
        gl.BindTexture(GL_TEXTURE_2D, colour_texture);
        gl.Uniform1i(gl.GetUniformLocation(quantize, "u_colour"), 0);
        gl.Uniform1i(gl.GetUniformLocation(quantize, "u_bits"), display.bits);
        gl.Uniform1i(gl.GetUniformLocation(quantize, "u_dither"), display.dither ? 1 : 0);
        gl.BindVertexArray(empty_vao);
        gl.DrawArrays(GL_TRIANGLES, 0, 3);
        gl.BindVertexArray(0);
        gl.UseProgram(0);
        gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    Rgb8Image read_display() const {
        std::vector<unsigned char> rgba(std::size_t(width) * height * 4);
        gl.BindFramebuffer(GL_FRAMEBUFFER, display_fbo);
        gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
        gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
        Rgb8Image image;
        image.width = width, image.height = height;
        image.pixels.resize(std::size_t(width) * height * 3);
        for (int y = 0; y < height; ++y) {  // GL rows run bottom to top, PNG rows top to bottom
            const unsigned char* src = &rgba[std::size_t(height - 1 - y) * width * 4];
            unsigned char* dst = &image.pixels[std::size_t(y) * width * 3];
            for (int x = 0; x < width; ++x)
                for (int c = 0; c < 3; ++c) dst[x * 3 + c] = src[x * 4 + c];
        }
        return image;
    }

    RgbFloatImage read_raw() const {
        RgbFloatImage image;
        image.width = width, image.height = height;
        image.pixels.resize(std::size_t(width) * height * 3);
        gl.BindFramebuffer(GL_FRAMEBUFFER, scene_fbo);
        gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
        gl.ReadPixels(0, 0, width, height, GL_RGB, GL_FLOAT, image.pixels.data());
        gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
        return image;
    }
};

Renderer::Renderer(const GlApi& gl) : impl_(std::make_unique<Impl>(gl)) {}
Renderer::~Renderer() = default;
void Renderer::render(const Scene& scene) { impl_->render(scene); }
void Renderer::set_shader_mode(ShaderMode mode) { impl_->shader_mode = mode; }
std::size_t Renderer::compiled_programs() const { return impl_->programs.size(); }
unsigned Renderer::display_texture() const { return impl_->display_tex; }
int Renderer::width() const { return impl_->width; }
int Renderer::height() const { return impl_->height; }
Rgb8Image Renderer::read_display() const { return impl_->read_display(); }
RgbFloatImage Renderer::read_raw() const { return impl_->read_raw(); }

}  // namespace m3055
