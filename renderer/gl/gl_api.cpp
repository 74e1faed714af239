#include "gl/gl_api.h"

namespace m3055 {

bool load_gl_api(GlApi& gl, GlProcLoader loader, void* user, std::string* missing) {
#define M3055_GL_LOAD(type, name)                                              \
    gl.name = reinterpret_cast<type>(loader("gl" #name, user));                \
    if (!gl.name) {                                                            \
        if (missing) *missing = "gl" #name;                                    \
        return false;                                                          \
    }
    M3055_GL_FUNCTIONS(M3055_GL_LOAD)
#undef M3055_GL_LOAD
    return true;
}

}  // namespace m3055
