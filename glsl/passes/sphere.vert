#version 330 core
// One screen-space quad per sphere instance, covering its projected silhouette
// (computed on the CPU, renderer/passes/sphere_bounds.cpp); the fragment shader
// ray-casts the exact sphere inside it.

layout(location = 0) in vec4 a_sphere;    // centre xyz, radius
layout(location = 1) in vec4 a_rect;      // NDC x0, y0, x1, y1
layout(location = 2) in int a_material;   // material record index

flat out vec4 v_sphere;
flat out int v_material;

void main() {
    // Triangle strip corners 0..3: (0,0) (1,0) (0,1) (1,1).
    vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
    gl_Position = vec4(mix(a_rect.xy, a_rect.zw, corner), 0.0, 1.0);
    v_sphere = a_sphere;
    v_material = a_material;
}
