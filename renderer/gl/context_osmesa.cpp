#include "gl/context_osmesa.h"

#include "gl/dynamic_library.h"

#include <GL/osmesa.h>

#include <vector>

namespace m3055 {
namespace {

using CreateContextAttribsFn = OSMesaContext (*)(const int*, OSMesaContext);
using DestroyContextFn = void (*)(OSMesaContext);
using MakeCurrentFn = GLboolean (*)(OSMesaContext, void*, GLenum, GLsizei, GLsizei);
using GetProcAddressFn = OSMESAproc (*)(const char*);

class OsMesaContext final : public HeadlessContext {
public:
    explicit OsMesaContext(std::unique_ptr<DynamicLibrary> library) : library_(std::move(library)) {}
    ~OsMesaContext() override {
        if (context_) destroy_(context_);
    }

    bool open(std::string* why) {
        auto create = library_->symbol<CreateContextAttribsFn>("OSMesaCreateContextAttribs");
        destroy_ = library_->symbol<DestroyContextFn>("OSMesaDestroyContext");
        auto make_current = library_->symbol<MakeCurrentFn>("OSMesaMakeCurrent");
        get_proc_ = library_->symbol<GetProcAddressFn>("OSMesaGetProcAddress");
        if (!create || !destroy_ || !make_current || !get_proc_) {
            *why = "OSMesa: library lacks OSMesaCreateContextAttribs";
            return false;
        }
        const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                               OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
        context_ = create(attribs, nullptr);
        if (!context_) {
            *why = "OSMesa: no OpenGL 3.3 core context";
            return false;
        }
        // OSMesa needs a colour buffer to be current; all rendering goes to FBOs,
        // so a single pixel is enough.
        if (!make_current(context_, pixel_, GL_UNSIGNED_BYTE, 1, 1)) {
            *why = "OSMesa: cannot make the context current";
            return false;
        }
        std::string missing;
        if (!load_gl_api(gl_, &OsMesaContext::load, this, &missing)) {
            *why = "OSMesa: " + missing + " is missing";
            return false;
        }
        backend_name_ = "osmesa";
        return true;
    }

private:
    static void* load(const char* name, void* self) {
        return reinterpret_cast<void*>(static_cast<OsMesaContext*>(self)->get_proc_(name));
    }

    std::unique_ptr<DynamicLibrary> library_;
    OSMesaContext context_ = nullptr;
    DestroyContextFn destroy_ = nullptr;
    GetProcAddressFn get_proc_ = nullptr;
    unsigned char pixel_[4] = {0, 0, 0, 0};
};

}  // namespace

std::unique_ptr<HeadlessContext> create_osmesa_context(std::string* why) {
    auto library = std::make_unique<DynamicLibrary>(osmesa_library_name());
    if (!library->ok()) {
        *why = "OSMesa: " + library->error();
        return nullptr;
    }
    auto context = std::make_unique<OsMesaContext>(std::move(library));
    if (!context->open(why)) return nullptr;
    return context;
}

}  // namespace m3055
