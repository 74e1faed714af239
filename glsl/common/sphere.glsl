// Exact ray-sphere intersection. C++ twin: ref::intersect_sphere.

// Nearest front-face hit with t > 0 of the ray origin + t dir (dir unit) with a
// sphere, given oc = origin - centre. Uses the perpendicular-distance form
// (Haines et al., "Precision Improvements for Ray/Sphere Intersection", Ray
// Tracing Gems ch. 7): b^2 - c cancels catastrophically for small spheres far away.
bool intersect_sphere(vec3 oc, vec3 dir, float radius, out float t) {
    float b = dot(oc, dir);
    vec3 q = oc - b * dir;
    float h2 = radius * radius - dot(q, q);
    t = 0.0;
    if (h2 < 0.0) return false;
    t = -b - sqrt(h2);
    return t > 0.0;
}
