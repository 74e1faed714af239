#version 330 core
// Triangle meshes of the non-sphere shapes (renderer/geometry/): positions
// and normals in world space; the fragment shader shades per pixel.
#include "common/camera.glsl"
#include "common/projection.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in int a_material;  // material record index

out vec3 v_position;
out vec3 v_normal;
flat out int v_material;

void main() {
    gl_Position = clip_position(a_position);
    v_position = a_position;
    v_normal = a_normal;
    v_material = a_material;
}
