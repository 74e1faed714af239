/* m3055_bare_context: what a headless capture cannot do without, and nothing
 * more: opens libEGL at run time as m3055 does (renderer/gl/context_egl.cpp),
 * makes an OpenGL 3.3 core context current on Mesa's surfaceless platform and
 * exits. scripts/bench-capture measures `m3055 render` against it.
 * Exit status 0 when the context was made, 1 otherwise (the reason on stderr). */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>
#include <stdio.h>

static int fail(const char* why) {
    fprintf(stderr, "m3055_bare_context: %s\n", why);
    return 1;
}

int main(void) {
    void* library = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!library) return fail(dlerror());
    PFNEGLGETPROCADDRESSPROC get_proc = (PFNEGLGETPROCADDRESSPROC)dlsym(library, "eglGetProcAddress");
    if (!get_proc) return fail("eglGetProcAddress missing");
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)get_proc("eglGetPlatformDisplayEXT");
    PFNEGLINITIALIZEPROC initialize = (PFNEGLINITIALIZEPROC)get_proc("eglInitialize");
    PFNEGLBINDAPIPROC bind_api = (PFNEGLBINDAPIPROC)get_proc("eglBindAPI");
    PFNEGLCREATECONTEXTPROC create_context = (PFNEGLCREATECONTEXTPROC)get_proc("eglCreateContext");
    PFNEGLMAKECURRENTPROC make_current = (PFNEGLMAKECURRENTPROC)get_proc("eglMakeCurrent");
    if (!get_display || !initialize || !bind_api || !create_context || !make_current)
        return fail("an EGL entry point is missing");
    EGLDisplay display = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (display == EGL_NO_DISPLAY || !initialize(display, NULL, NULL)) return fail("no surfaceless EGL display");
    if (!bind_api(EGL_OPENGL_API)) return fail("no desktop OpenGL API");
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = create_context(display, NULL, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) return fail("no OpenGL 3.3 core context");
    if (!make_current(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
        return fail("cannot make the context current without a surface");
    return 0;
}
