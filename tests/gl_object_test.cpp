// gl/gl_object.h: one delete per object, none for an empty or moved-from
// handle, through the GlApi the handle was made with. A GlApi of counting
// functions stands in for a context: no GL needed.
#include "gl/gl_object.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace m3055 {
namespace {

std::vector<unsigned> deleted_textures;
std::vector<unsigned> deleted_programs;
unsigned next_name = 0;

void APIENTRY gen_textures(GLsizei n, GLuint* names) {
    for (GLsizei i = 0; i < n; ++i) names[i] = ++next_name;
}
void APIENTRY delete_textures(GLsizei n, const GLuint* names) {
    deleted_textures.insert(deleted_textures.end(), names, names + n);
}
void APIENTRY delete_program(GLuint name) { deleted_programs.push_back(name); }

GlApi counting_api() {
    GlApi gl;
    gl.GenTextures = gen_textures;
    gl.DeleteTextures = delete_textures;
    gl.DeleteProgram = delete_program;
    deleted_textures.clear();
    deleted_programs.clear();
    return gl;
}

TEST(GlObject, DeletesItsObjectOnceWhenItGoes) {
    const GlApi gl = counting_api();
    unsigned name = 0;
    {
        GlTexture texture(gl);
        name = texture.id();
        EXPECT_NE(name, 0u);
        EXPECT_TRUE(deleted_textures.empty());
    }
    EXPECT_EQ(deleted_textures, std::vector<unsigned>{name});
}

TEST(GlObject, AMoveHandsTheObjectOverAndTheSourceDeletesNothing) {
    const GlApi gl = counting_api();
    GlTexture first(gl);
    const unsigned name = first.id();
    GlTexture second(std::move(first));
    EXPECT_FALSE(first);
    EXPECT_EQ(second.id(), name);
    first = GlTexture(gl);  // a moved-from handle takes a new object
    const unsigned other = first.id();
    second = std::move(first);  // the old object of `second` goes now
    EXPECT_EQ(deleted_textures, std::vector<unsigned>{name});
    second.reset();
    EXPECT_EQ(deleted_textures, (std::vector<unsigned>{name, other}));
    EXPECT_FALSE(second);
}

TEST(GlObject, AnAdoptedProgramIsDeletedAsAProgram) {
    const GlApi gl = counting_api();
    { GlProgram program(gl, 42u); }
    { GlProgram empty; }
    EXPECT_EQ(deleted_programs, std::vector<unsigned>{42u});
    EXPECT_TRUE(deleted_textures.empty());
}

}  // namespace
}  // namespace m3055
