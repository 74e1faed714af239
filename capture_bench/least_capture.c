/* m3055_least_capture: the least any OpenGL capture of a 512 × 320 image does,
 * and nothing more: the bare context (bare_context.c), then one framebuffer of
 * the display's size (RGBA8), one program of two tiny shaders (a full-screen
 * triangle whose colour is a function of the pixel, so llvmpipe builds a real
 * fragment function), one draw, and the pixels read back; no scene, no PNG.
 * scripts/bench-capture measures it beside the bare context: what it costs
 * beyond the context is what llvmpipe charges any program that draws, the
 * floor under `m3055 render` on this platform (docs/bench/capture.md).
 * Exit status 0 when the pixels came back as drawn, 1 otherwise (the reason on
 * stderr). */
#include "surfaceless_context.h"

#include <GL/glcorearb.h>
#include <stdio.h>

enum { kWidth = 512, kHeight = 320 };

static int fail(const char* why) {
    fprintf(stderr, "m3055_least_capture: %s\n", why);
    return 1;
}

static const char* const kVertex =
    "#version 330 core\n"
    "void main() {\n"
    "    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));\n"
    "    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n";

/* A Lambert sphere's worth of arithmetic: enough for a real fragment function. */
static const char* const kFragment =
    "#version 330 core\n"
    "out vec4 colour;\n"
    "void main() {\n"
    "    vec2 p = gl_FragCoord.xy / vec2(512.0, 320.0) * 2.0 - 1.0;\n"
    "    float r2 = dot(p, p);\n"
    "    vec3 n = vec3(p, sqrt(max(1.0 - r2, 0.0)));\n"
    "    float lambert = max(dot(n, normalize(vec3(1.0, 1.0, 1.0))), 0.0);\n"
    "    colour = vec4(r2 < 1.0 ? vec3(0.8, 0.5, 0.2) * lambert : vec3(0.0), 1.0);\n"
    "}\n";

int main(void) {
    PFNEGLGETPROCADDRESSPROC get_proc = make_surfaceless_context("m3055_least_capture");
    if (!get_proc) return 1;

    /* The GL entry points, resolved for this context. */
#define GL_ENTRY(type, name)                    \
    type name = (type)get_proc(#name);          \
    if (!name) return fail(#name " missing");
    GL_ENTRY(PFNGLGENTEXTURESPROC, glGenTextures)
    GL_ENTRY(PFNGLBINDTEXTUREPROC, glBindTexture)
    GL_ENTRY(PFNGLTEXIMAGE2DPROC, glTexImage2D)
    GL_ENTRY(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)
    GL_ENTRY(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)
    GL_ENTRY(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)
    GL_ENTRY(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)
    GL_ENTRY(PFNGLCREATESHADERPROC, glCreateShader)
    GL_ENTRY(PFNGLSHADERSOURCEPROC, glShaderSource)
    GL_ENTRY(PFNGLCOMPILESHADERPROC, glCompileShader)
    GL_ENTRY(PFNGLCREATEPROGRAMPROC, glCreateProgram)
    GL_ENTRY(PFNGLATTACHSHADERPROC, glAttachShader)
    GL_ENTRY(PFNGLLINKPROGRAMPROC, glLinkProgram)
    GL_ENTRY(PFNGLGETPROGRAMIVPROC, glGetProgramiv)
    GL_ENTRY(PFNGLUSEPROGRAMPROC, glUseProgram)
    GL_ENTRY(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)
    GL_ENTRY(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)
    GL_ENTRY(PFNGLVIEWPORTPROC, glViewport)
    GL_ENTRY(PFNGLDRAWARRAYSPROC, glDrawArrays)
    GL_ENTRY(PFNGLREADPIXELSPROC, glReadPixels)
#undef GL_ENTRY

    GLuint texture, framebuffer, vertex_array;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kWidth, kHeight, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) return fail("framebuffer incomplete");

    GLuint program = glCreateProgram();
    const char* const sources[2] = {kVertex, kFragment};
    const GLenum stages[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
    for (int i = 0; i < 2; ++i) {
        GLuint shader = glCreateShader(stages[i]);
        glShaderSource(shader, 1, &sources[i], NULL);
        glCompileShader(shader);
        glAttachShader(program, shader);
    }
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) return fail("the program did not link");
    glUseProgram(program);
    glGenVertexArrays(1, &vertex_array);
    glBindVertexArray(vertex_array);
    glViewport(0, 0, kWidth, kHeight);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    static unsigned char pixels[kWidth * kHeight * 4];  /* static: nothing to free before exit */
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    /* The centre is lit, a corner black: the draw happened. */
    const unsigned char* centre = pixels + ((size_t)(kHeight / 2) * kWidth + kWidth / 2) * 4;
    if (centre[0] == 0 || pixels[0] != 0) return fail("the pixels read back are not the ones drawn");
    return 0;
}
