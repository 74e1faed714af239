// The GL function table. Every GL call in the project goes through a GlApi
// filled from the *current context's own* getProcAddress (EGL, OSMesa or
// GLFW), never through symbols linked from libGL/libOpenGL: with several GL
// libraries in one process (glvnd's libOpenGL, Mesa's libOSMesa), a linked
// glClear may land in a library that has no current context.
#pragma once

#include <GL/glcorearb.h>

#include <string>

namespace m3055 {

// X(type, name): one line per GL entry point the project uses.
#define M3055_GL_FUNCTIONS(X)                                              \
    X(PFNGLGETSTRINGPROC, GetString)                                       \
    X(PFNGLGETERRORPROC, GetError)                                         \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                                   \
    X(PFNGLENABLEPROC, Enable)                                             \
    X(PFNGLDISABLEPROC, Disable)                                           \
    X(PFNGLVIEWPORTPROC, Viewport)                                         \
    X(PFNGLSCISSORPROC, Scissor)                                           \
    X(PFNGLCLEARCOLORPROC, ClearColor)                                     \
    X(PFNGLCLEARPROC, Clear)                                               \
    X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                               \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                                       \
    X(PFNGLDEPTHMASKPROC, DepthMask)                                       \
    X(PFNGLBLENDFUNCPROC, BlendFunc)                                       \
    X(PFNGLBLENDEQUATIONPROC, BlendEquation)                               \
    X(PFNGLCOLORMASKPROC, ColorMask)                                       \
    X(PFNGLSTENCILFUNCPROC, StencilFunc)                                   \
    X(PFNGLSTENCILOPPROC, StencilOp)                                       \
    X(PFNGLSTENCILMASKPROC, StencilMask)                                   \
    X(PFNGLCLEARBUFFERIVPROC, ClearBufferiv)                               \
    X(PFNGLGENQUERIESPROC, GenQueries)                                     \
    X(PFNGLDELETEQUERIESPROC, DeleteQueries)                               \
    X(PFNGLBEGINQUERYPROC, BeginQuery)                                     \
    X(PFNGLENDQUERYPROC, EndQuery)                                         \
    X(PFNGLGETQUERYOBJECTUIVPROC, GetQueryObjectuiv)                       \
    X(PFNGLFINISHPROC, Finish)                                             \
    X(PFNGLFLUSHPROC, Flush)                                               \
    X(PFNGLREADPIXELSPROC, ReadPixels)                                     \
    X(PFNGLREADBUFFERPROC, ReadBuffer)                                     \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                                   \
    X(PFNGLCREATESHADERPROC, CreateShader)                                 \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                                 \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                               \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                                   \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                         \
    X(PFNGLDELETESHADERPROC, DeleteShader)                                 \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                               \
    X(PFNGLATTACHSHADERPROC, AttachShader)                                 \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                                   \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                 \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                       \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                               \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                                     \
    X(PFNGLBINDATTRIBLOCATIONPROC, BindAttribLocation)                     \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                     \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                                       \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                                       \
    X(PFNGLUNIFORM2FPROC, Uniform2f)                                       \
    X(PFNGLUNIFORM3FPROC, Uniform3f)                                       \
    X(PFNGLUNIFORM4FPROC, Uniform4f)                                       \
    X(PFNGLUNIFORM1IVPROC, Uniform1iv)                                     \
    X(PFNGLUNIFORM1FVPROC, Uniform1fv)                                     \
    X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                     \
    X(PFNGLUNIFORM4FVPROC, Uniform4fv)                                     \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                         \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                           \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                           \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                     \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                                     \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                                     \
    X(PFNGLBUFFERDATAPROC, BufferData)                                     \
    X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                               \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                               \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                   \
    X(PFNGLVERTEXATTRIBIPOINTERPROC, VertexAttribIPointer)                 \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)           \
    X(PFNGLVERTEXATTRIBDIVISORPROC, VertexAttribDivisor)                   \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                                     \
    X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced)                   \
    X(PFNGLDRAWELEMENTSPROC, DrawElements)                                 \
    X(PFNGLGENTEXTURESPROC, GenTextures)                                   \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                                   \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                               \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                     \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri)                               \
    X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D)                               \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                             \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                           \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                           \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                 \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)             \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                     \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                   \
    X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)

struct GlApi {
#define M3055_GL_DECLARE(type, name) type name = nullptr;
    M3055_GL_FUNCTIONS(M3055_GL_DECLARE)
#undef M3055_GL_DECLARE
};

using GlProcLoader = void* (*)(const char* name, void* user);

// Fills `gl` through `loader` ("gl" is prefixed to each name). Returns false and
// names the first missing function in `missing` when one cannot be resolved.
bool load_gl_api(GlApi& gl, GlProcLoader loader, void* user, std::string* missing);

}  // namespace m3055
