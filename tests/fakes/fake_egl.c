/* A fake libEGL for tests/context_fallback_test.cpp: it has every entry point
 * m3055 uses and advertises Mesa's surfaceless platform and one EGL device,
 * initializes its displays, but refuses every OpenGL context, as an EGL whose
 * driver has no OpenGL 3.3 core profile does. m3055 must then fall back to
 * OSMesa (docs/spec.md#8-command-line). Loaded through $M3055_EGL_LIBRARY; never installed. */
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string.h>

/* How often m3055 asked for a context, and for which version: read by the test
 * (dlopen of this same file returns the same, already loaded, copy). */
int m3055_fake_egl_context_requests = 0;
int m3055_fake_egl_last_major = 0, m3055_fake_egl_last_minor = 0, m3055_fake_egl_last_profile = 0;

static int fake_display_object, fake_device_object;

static const char* EGLAPIENTRY fake_query_string(EGLDisplay display, EGLint name) {
    if (display == EGL_NO_DISPLAY && name == EGL_EXTENSIONS)
        return "EGL_EXT_platform_base EGL_EXT_device_base EGL_EXT_device_enumeration "
               "EGL_EXT_platform_device EGL_MESA_platform_surfaceless";
    if (name == EGL_VENDOR) return "m3055 fake EGL (tests)";
    return "";
}
static EGLDisplay EGLAPIENTRY fake_get_platform_display(EGLenum platform, void* native, const EGLint* attribs) {
    (void)platform, (void)native, (void)attribs;
    return (EGLDisplay)&fake_display_object;
}
static EGLBoolean EGLAPIENTRY fake_initialize(EGLDisplay display, EGLint* major, EGLint* minor) {
    (void)display;
    if (major) *major = 1;
    if (minor) *minor = 5;
    return EGL_TRUE;
}
static EGLBoolean EGLAPIENTRY fake_terminate(EGLDisplay display) { return (void)display, EGL_TRUE; }
static EGLBoolean EGLAPIENTRY fake_bind_api(EGLenum api) { return api == EGL_OPENGL_API || api == EGL_OPENGL_ES_API; }
static EGLBoolean EGLAPIENTRY fake_choose_config(EGLDisplay display, const EGLint* attribs, EGLConfig* configs,
                                                 EGLint size, EGLint* count) {
    (void)display, (void)attribs, (void)configs, (void)size;
    *count = 0;
    return EGL_TRUE;
}
static EGLContext EGLAPIENTRY fake_create_context(EGLDisplay display, EGLConfig config, EGLContext share,
                                                  const EGLint* attribs) {
    (void)display, (void)config, (void)share;
    ++m3055_fake_egl_context_requests;
    for (const EGLint* a = attribs; a && a[0] != EGL_NONE; a += 2) {
        if (a[0] == EGL_CONTEXT_MAJOR_VERSION) m3055_fake_egl_last_major = a[1];
        if (a[0] == EGL_CONTEXT_MINOR_VERSION) m3055_fake_egl_last_minor = a[1];
        if (a[0] == EGL_CONTEXT_OPENGL_PROFILE_MASK) m3055_fake_egl_last_profile = a[1];
    }
    return EGL_NO_CONTEXT; /* only OpenGL 2.1 here: no 3.3 core context */
}
static EGLBoolean EGLAPIENTRY fake_destroy_context(EGLDisplay display, EGLContext context) {
    return (void)display, (void)context, EGL_FALSE;
}
static EGLBoolean EGLAPIENTRY fake_make_current(EGLDisplay display, EGLSurface draw, EGLSurface read,
                                                EGLContext context) {
    (void)display, (void)draw, (void)read;
    return context == EGL_NO_CONTEXT;
}
static EGLint EGLAPIENTRY fake_get_error(void) { return EGL_BAD_MATCH; }
static EGLBoolean EGLAPIENTRY fake_query_devices(EGLint max, EGLDeviceEXT* devices, EGLint* count) {
    if (max > 0 && devices) devices[0] = (EGLDeviceEXT)&fake_device_object;
    *count = max > 0 ? 1 : 0;
    return EGL_TRUE;
}

static const struct {
    const char* name;
    __eglMustCastToProperFunctionPointerType function;
} fake_functions[] = {
    {"eglQueryString", (__eglMustCastToProperFunctionPointerType)fake_query_string},
    {"eglGetPlatformDisplayEXT", (__eglMustCastToProperFunctionPointerType)fake_get_platform_display},
    {"eglGetPlatformDisplay", (__eglMustCastToProperFunctionPointerType)fake_get_platform_display},
    {"eglInitialize", (__eglMustCastToProperFunctionPointerType)fake_initialize},
    {"eglTerminate", (__eglMustCastToProperFunctionPointerType)fake_terminate},
    {"eglBindAPI", (__eglMustCastToProperFunctionPointerType)fake_bind_api},
    {"eglChooseConfig", (__eglMustCastToProperFunctionPointerType)fake_choose_config},
    {"eglCreateContext", (__eglMustCastToProperFunctionPointerType)fake_create_context},
    {"eglDestroyContext", (__eglMustCastToProperFunctionPointerType)fake_destroy_context},
    {"eglMakeCurrent", (__eglMustCastToProperFunctionPointerType)fake_make_current},
    {"eglGetError", (__eglMustCastToProperFunctionPointerType)fake_get_error},
    {"eglQueryDevicesEXT", (__eglMustCastToProperFunctionPointerType)fake_query_devices},
};

__eglMustCastToProperFunctionPointerType EGLAPIENTRY eglGetProcAddress(const char* name) {
    for (size_t i = 0; i < sizeof fake_functions / sizeof fake_functions[0]; ++i)
        if (strcmp(fake_functions[i].name, name) == 0) return fake_functions[i].function;
    return NULL; /* no GL functions either */
}
