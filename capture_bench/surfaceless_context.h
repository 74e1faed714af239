/* What both capture_bench programs do first, as m3055 does
 * (renderer/gl/context_egl.cpp): libEGL opened at run time, an OpenGL 3.3
 * core context made current on Mesa's surfaceless platform. Returns
 * eglGetProcAddress, or NULL with the reason on stderr after `program`. */
#pragma once

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>
#include <stdio.h>

static PFNEGLGETPROCADDRESSPROC context_failed(const char* program, const char* why) {
    fprintf(stderr, "%s: %s\n", program, why);
    return NULL;
}

static PFNEGLGETPROCADDRESSPROC make_surfaceless_context(const char* program) {
    void* library = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!library) return context_failed(program, dlerror());
    PFNEGLGETPROCADDRESSPROC get_proc = (PFNEGLGETPROCADDRESSPROC)dlsym(library, "eglGetProcAddress");
    if (!get_proc) return context_failed(program, "eglGetProcAddress missing");
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)get_proc("eglGetPlatformDisplayEXT");
    PFNEGLINITIALIZEPROC initialize = (PFNEGLINITIALIZEPROC)get_proc("eglInitialize");
    PFNEGLBINDAPIPROC bind_api = (PFNEGLBINDAPIPROC)get_proc("eglBindAPI");
    PFNEGLCREATECONTEXTPROC create_context = (PFNEGLCREATECONTEXTPROC)get_proc("eglCreateContext");
    PFNEGLMAKECURRENTPROC make_current = (PFNEGLMAKECURRENTPROC)get_proc("eglMakeCurrent");
    if (!get_display || !initialize || !bind_api || !create_context || !make_current)
        return context_failed(program, "an EGL entry point is missing");
    EGLDisplay display = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (display == EGL_NO_DISPLAY || !initialize(display, NULL, NULL))
        return context_failed(program, "no surfaceless EGL display");
    if (!bind_api(EGL_OPENGL_API)) return context_failed(program, "no desktop OpenGL API");
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = create_context(display, NULL, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) return context_failed(program, "no OpenGL 3.3 core context");
    if (!make_current(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
        return context_failed(program, "cannot make the context current without a surface");
    return get_proc;
}
