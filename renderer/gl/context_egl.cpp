#include "gl/context_egl.h"

#include "gl/dynamic_library.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <vector>

namespace m3055 {
namespace {

// The EGL entry points we use, resolved from the dlopen'ed libEGL.
struct EglApi {
    PFNEGLGETPROCADDRESSPROC GetProcAddress = nullptr;
    PFNEGLQUERYSTRINGPROC QueryString = nullptr;
    PFNEGLINITIALIZEPROC Initialize = nullptr;
    PFNEGLTERMINATEPROC Terminate = nullptr;
    PFNEGLBINDAPIPROC BindAPI = nullptr;
    PFNEGLCHOOSECONFIGPROC ChooseConfig = nullptr;
    PFNEGLCREATECONTEXTPROC CreateContext = nullptr;
    PFNEGLDESTROYCONTEXTPROC DestroyContext = nullptr;
    PFNEGLMAKECURRENTPROC MakeCurrent = nullptr;
    PFNEGLGETERRORPROC GetError = nullptr;
    PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplayEXT = nullptr;
    PFNEGLQUERYDEVICESEXTPROC QueryDevicesEXT = nullptr;
};

class EglContext final : public HeadlessContext {
public:
    // The context keeps libEGL open for its whole life.
    EglContext(std::shared_ptr<DynamicLibrary> library, EglApi egl)
        : library_(std::move(library)), egl_(egl) {}
    ~EglContext() override {
        if (context_ != EGL_NO_CONTEXT) {
            egl_.MakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            egl_.DestroyContext(display_, context_);
        }
        if (display_ != EGL_NO_DISPLAY) egl_.Terminate(display_);
    }

    // Initializes `display`, creates a 3.3 core context and makes it current.
    bool open(EGLDisplay display, const std::string& name, std::string* why) {
        EGLint major = 0, minor = 0;
        if (display == EGL_NO_DISPLAY || !egl_.Initialize(display, &major, &minor)) {
            *why = name + ": cannot initialize the display";
            return false;
        }
        display_ = display;
        if (!egl_.BindAPI(EGL_OPENGL_API)) {
            *why = name + ": no desktop OpenGL API";
            return false;
        }
        // A pbuffer-capable config if there is one; with EGL_KHR_no_config_context
        // no config is needed at all (we render only to framebuffer objects).
        const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                         EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint count = 0;
        if (!egl_.ChooseConfig(display, config_attribs, &config, 1, &count) || count < 1) config = nullptr;
        const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                          EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                          EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        context_ = egl_.CreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
        if (context_ == EGL_NO_CONTEXT) {
            *why = name + ": no OpenGL 3.3 core context";
            return false;
        }
        if (!egl_.MakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
            *why = name + ": cannot make the context current without a surface";
            return false;
        }
        std::string missing;
        if (!load_gl_api(gl_, &EglContext::load, this, &missing)) {
            *why = name + ": " + missing + " is missing";
            return false;
        }
        backend_name_ = name;
        return true;
    }

private:
    static void* load(const char* name, void* self) {
        return reinterpret_cast<void*>(static_cast<EglContext*>(self)->egl_.GetProcAddress(name));
    }

    std::shared_ptr<DynamicLibrary> library_;
    EglApi egl_;
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

bool has_extension(const char* list, const char* name) {
    if (!list) return false;
    const std::string all = std::string(" ") + list + " ";
    return all.find(std::string(" ") + name + " ") != std::string::npos;
}

}  // namespace

std::unique_ptr<HeadlessContext> create_egl_context(std::string* why) {
    auto library = std::make_shared<DynamicLibrary>(egl_library_name());
    if (!library->ok()) {
        *why = "EGL: " + library->error();
        return nullptr;
    }
    EglApi egl;
    egl.GetProcAddress = library->symbol<PFNEGLGETPROCADDRESSPROC>("eglGetProcAddress");
    if (!egl.GetProcAddress) {
        *why = "EGL: eglGetProcAddress missing";
        return nullptr;
    }
#define M3055_EGL_LOAD(name) egl.name = reinterpret_cast<decltype(egl.name)>(egl.GetProcAddress("egl" #name))
    M3055_EGL_LOAD(QueryString);
    M3055_EGL_LOAD(Initialize);
    M3055_EGL_LOAD(Terminate);
    M3055_EGL_LOAD(BindAPI);
    M3055_EGL_LOAD(ChooseConfig);
    M3055_EGL_LOAD(CreateContext);
    M3055_EGL_LOAD(DestroyContext);
    M3055_EGL_LOAD(MakeCurrent);
    M3055_EGL_LOAD(GetError);
    M3055_EGL_LOAD(GetPlatformDisplayEXT);
    M3055_EGL_LOAD(QueryDevicesEXT);
#undef M3055_EGL_LOAD
    if (!egl.QueryString || !egl.Initialize || !egl.CreateContext || !egl.MakeCurrent ||
        !egl.GetPlatformDisplayEXT) {
        *why = "EGL: no platform-display support";
        return nullptr;
    }
    const char* client_extensions = egl.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    std::string reasons;

    // 1. Mesa's surfaceless platform: no window system, no device needed.
    if (has_extension(client_extensions, "EGL_MESA_platform_surfaceless")) {
        auto context = std::make_unique<EglContext>(library, egl);
        std::string reason;
        EGLDisplay display = egl.GetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (context->open(display, "egl-surfaceless", &reason)) return context;
        reasons += reason;
    }
    // 2. An EGL device (EGL_EXT_platform_device), e.g. a GPU without a display.
    if (egl.QueryDevicesEXT && has_extension(client_extensions, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (egl.QueryDevicesEXT(8, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                auto context = std::make_unique<EglContext>(library, egl);
                std::string reason;
                EGLDisplay display = egl.GetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (context->open(display, "egl-device", &reason)) return context;
                reasons += (reasons.empty() ? "" : "; ") + reason;
            }
        }
    }
    *why = "EGL: " + (reasons.empty() ? std::string("no surfaceless platform and no device") : reasons);
    return nullptr;
}

}  // namespace m3055
