// The sky's shadow as what the objects take away from it: the integral of
// L r(w) V(w) over the sky is the unshadowed integral (the sky's samples with
// their closed forms, as without a shadow) less the integral of L r(w) over
// the directions some object blocks. That second integral is drawn only where
// objects can be: from a cone about each object's bounding sphere (uniform in
// the cone's solid angle), or, for an object whose bounding sphere holds the
// point, uniformly from the hemisphere about N (not by the cosine: a highlight
// (R.V)^m has no N.L to cancel its 1 / cos near the horizon, where objects
// stand as a floor's point sees them), or, for a prism of few sides that P lies
// on, from the lune its face blocks; the techniques combined by the balance
// heuristic (Veach 1997), every sample its own shadow ray. Where the sky's
// samples traced rays over the whole hemisphere, a small or distant object was
// hit by a few of them, and its shadow was noise; drawn from its cone it is hit
// by all of a technique's samples that its silhouette covers (a sphere: every
// one). Unbiased as long as every blocked direction lies in some technique's
// domain: an object is left out only where it cannot block the sky above P
// (a plane through P, a box wholly below N's or the sky's horizon, a sphere or a
// box wholly below N's: the one P lies on).
// renderer/passes/occluders.h uploads the bounding spheres and boxes of at
// most MAX_SKY_OCCLUDERS objects; with more, u_sky_occluder_count is 0 and the
// sky's samples trace their own rays (common/lights.glsl). The reference
// integrates visibility adaptively (reference/area_quadrature.h): no twin.

#define MAX_SKY_OCCLUDERS 8  // renderer/passes/occluders.h: kMaxSkyOccluders

uniform int u_sky_occluder_count;                         // 0: not drawn this way
uniform vec4 u_sky_occluder_sphere[MAX_SKY_OCCLUDERS];    // bounding sphere: centre, radius
uniform vec4 u_sky_occluder_centre[MAX_SKY_OCCLUDERS];    // the box's centre; w: 1 for a plane
uniform vec4 u_sky_occluder_half[MAX_SKY_OCCLUDERS];      // the box's half extents
uniform vec4 u_sky_occluder_normal[MAX_SKY_OCCLUDERS];    // a plane's unit normal
// A sphere's or a box's exact shape, for the closed forms of what it blocks
// (u_sky_occluder_half[k].w: kOccluderSphere, kOccluderBox, else 0): a
// sphere's is its bounding sphere; a box's (a cube, a plane) is its three unit
// axes (w: its half size along each; a plane's normal: 0) and its centre.
uniform vec4 u_sky_occluder_frame[4 * MAX_SKY_OCCLUDERS];
const float kOccluderSphere = 1.0;  // renderer/passes/occluders.h: SkyOccluderShape
const float kOccluderBox = 2.0;
// A capped cylinder's prism (its mesh: geometry/shapes.cpp, make_cylinder): frame[0] its
// axis (w: half height), frame[1] and frame[2] the radial axes (w: radius; segments n),
// frame[3] its centre; corner k of a rim at angle 2 pi k / n from frame[1] towards frame[2].
const float kOccluderPrism = 3.0;

// Samples of each technique, for the sky's n x n: half as many (a power of two
// for n = 2, 4, 8, 16), so that four objects take as many rays as the n x n
// emitter and n x n lobe samples traced before.
int sky_occluder_samples(int n) {
    return max(n * n / 2, 1);
}

// How technique k draws from P: uniformly in a cone of half-angle cos^-1(z)
// about `axis` (N's hemisphere: z = 0 about N), uniformly in a lune (z =
// kOccluderLune: the prism P lies on), or nothing (z = kOccluderNone: object k
// cannot block the sky above P).
const float kOccluderNone = 2.0;
const float kOccluderLune = 3.0;

struct OccluderCone {
    vec3 axis;        // a lune: N
    float z;          // cos of the half-angle, kOccluderLune or kOccluderNone
    float one_minus;  // 1 - z, kept where z is near 1 (a small, distant object); a lune: its angle
    vec3 face;        // a lune: the normal of the face P lies on
};

// Whether object k's exact shape (a sphere, a box) lies wholly on or below the
// plane through o with normal N: the shape that P lies on, N its outward normal (a
// convex shape never blocks a direction above its own tangent plane), seen from the
// shadow ray's origin o = P + eps N, so that rounding on its surface stays below.
bool exact_shape_below(int k, vec3 o, vec3 N) {
    float shape = u_sky_occluder_half[k].w;
    if (shape == kOccluderSphere) {
        vec4 sphere = u_sky_occluder_sphere[k];
        return dot(N, sphere.xyz - o) + sphere.w <= 0.0;
    }
    if (shape != kOccluderBox) return false;
    float top = dot(N, u_sky_occluder_frame[4 * k + 3].xyz - o);
    for (int a = 0; a < 3; ++a) top += abs(dot(N, u_sky_occluder_frame[4 * k + a].xyz)) * u_sky_occluder_frame[4 * k + a].w;
    return top <= 0.0;
}

// The side face of prism k that o (the shadow ray's origin) lies on, as its outward
// normal, where N is a side's normal (the mesh's smooth normals, perpendicular to the
// axis, lean up to pi / n from their face's); false elsewhere. From a point on a face,
// a convex prism blocks exactly the lune of directions above N's horizon and below the
// face's plane: at 6 sides up to a 30 degree wedge of the sky, which the hemisphere's
// samples met rarely (noisy facets, a principled lobe's estimate below zero).
// Only up to kMaxLuneSides sides: beyond, the lune is a sliver (under 5.6 degrees),
// and its samples did more for the other objects' parts drawn from the hemisphere
// (the eight objects' 64-sided metal cylinder: mean |diff| 1.2e-3 with the
// hemisphere, 1.6e-3 with the lune; docs/lights.md, "tenth").
const int kMaxLuneSides = 32;

bool prism_own_face(int k, vec3 o, vec3 N, out vec3 face) {
    face = N;
    if (u_sky_occluder_half[k].w != kOccluderPrism) return false;
    vec4 a = u_sky_occluder_frame[4 * k], t = u_sky_occluder_frame[4 * k + 1], b = u_sky_occluder_frame[4 * k + 2];
    int n = int(b.w + 0.5);
    if (n > kMaxLuneSides) return false;
    vec3 rel = o - u_sky_occluder_frame[4 * k + 3].xyz;
    float tol = 4e-4 * max(1.0, max(abs(o.x), max(abs(o.y), abs(o.z))));
    if (abs(dot(N, a.xyz)) > 0.5 || abs(dot(a.xyz, rel)) > a.w + tol) return false;
    float angle_step = 2.0 * PI / float(n), phi = atan(dot(rel, b.xyz), dot(rel, t.xyz));
    float f = min(floor((phi < 0.0 ? phi + 2.0 * PI : phi) / angle_step), float(n - 1));
    float middle = angle_step * (f + 0.5);
    face = cos(middle) * t.xyz + sin(middle) * b.xyz;
    return abs(dot(face, rel) - t.w * cos(PI / float(n))) <= tol;
}

OccluderCone occluder_cone(int k, vec3 P, vec3 N, vec3 up) {
    OccluderCone cone;
    cone.axis = N;
    cone.z = kOccluderNone;
    cone.one_minus = 0.0;
    cone.face = N;
    vec4 box = u_sky_occluder_centre[k];
    vec3 half_size = u_sky_occluder_half[k].xyz;
    vec3 to_box = box.xyz - P;
    // Its box wholly below a horizon: its corner furthest up is not above it; or its
    // exact shape below N's (the object P lies on, a sphere or a box).
    if (dot(N, to_box) + dot(abs(N), half_size) <= 0.0 || dot(up, to_box) + dot(abs(up), half_size) <= 0.0)
        return cone;
    vec3 o = shadow_ray_origin(P, N);
    if (exact_shape_below(k, o, N)) return cone;
    // A plane through P blocks only directions along it.
    float eps = 1e-4 * max(1.0, max(abs(P.x), max(abs(P.y), abs(P.z))));
    if (box.w > 0.5 && abs(dot(u_sky_occluder_normal[k].xyz, to_box)) <= eps) return cone;
    vec3 face;
    if (prism_own_face(k, o, N, face)) {  // the lune below the face P lies on; none where N is its normal
        float c = dot(N, face);
        if (c < 1.0 - 1e-7) {
            cone.z = kOccluderLune;
            cone.one_minus = acos(clamp(c, -1.0, 1.0));
            cone.face = face;
        }
        return cone;
    }
    vec4 sphere = u_sky_occluder_sphere[k];
    vec3 to_sphere = sphere.xyz - P;
    float d2 = dot(to_sphere, to_sphere), r2 = sphere.w * sphere.w;
    if (d2 <= r2) {  // the hemisphere about N
        cone.z = 0.0;
        cone.one_minus = 1.0;
        return cone;
    }
    float d = sqrt(d2);
    cone.axis = to_sphere / d;
    float sin2 = r2 / d2;
    cone.z = sqrt(1.0 - sin2);
    cone.one_minus = sin2 / (1.0 + cone.z);
    // Narrower where the box's corners all lie closer to the axis (a flat torus, a cube:
    // their spheres are wide); a cone within 90 degrees holds the box when it holds its corners.
    if (box.w < 0.5 && any(greaterThan(abs(to_box), half_size))) {
        float z = 1.0;
        for (int corner = 0; corner < 8; ++corner) {
            vec3 side = vec3(float(corner & 1), float((corner >> 1) & 1), float((corner >> 2) & 1)) * 2.0 - 1.0;
            z = min(z, dot(cone.axis, normalize(to_box + side * half_size)));
        }
        if (z > cone.z) {
            cone.z = z;
            cone.one_minus = 1.0 - z;
        }
    }
    return cone;
}

// Technique `cone`'s density (per solid angle) where it draws: a cone's
// 2 pi (1 - z) of solid angle, a lune's 2 x its angle.
float occluder_density(OccluderCone cone) {
    return cone.z == kOccluderLune ? 0.5 / cone.one_minus : 1.0 / (2.0 * PI * cone.one_minus);
}

// Technique `cone`'s density at w (per solid angle).
float occluder_pdf(OccluderCone cone, vec3 w) {
    if (cone.z == kOccluderNone) return 0.0;
    bool in_it = cone.z == kOccluderLune ? dot(cone.axis, w) > 0.0 && dot(cone.face, w) < 0.0 : dot(cone.axis, w) >= cone.z;
    return in_it ? occluder_density(cone) : 0.0;
}

// Where the lune of `cone` (above N's horizon, below the face's plane) starts: the
// direction on N's horizon furthest below the face's plane; its ends are
// +-normalize(N x face), and it turns from here towards N by its angle.
vec3 lune_start(OccluderCone cone) {
    return -normalize(cone.face - dot(cone.face, cone.axis) * cone.axis);
}

// Technique `cone`'s direction for the point u of the unit square.
vec3 occluder_direction(OccluderCone cone, vec2 u) {
    if (cone.z == kOccluderLune) {
        // Uniform in solid angle: the angle about the lune's ends, and the height along them (Archimedes).
        float turn = u.x * cone.one_minus, height = 2.0 * u.y - 1.0;
        vec3 across = cos(turn) * lune_start(cone) + sin(turn) * cone.axis;
        return normalize(sqrt(max(1.0 - height * height, 0.0)) * across + height * normalize(cross(cone.axis, cone.face)));
    }
    float one_minus = u.x * cone.one_minus;  // 1 - cos, uniform in solid angle
    float c = 1.0 - one_minus, s = sqrt(max(one_minus * (2.0 - one_minus), 0.0));
    float phi = 2.0 * PI * u.y;
    vec3 T, B;
    complete_frame(cone.axis, T, B);
    return normalize(s * cos(phi) * T + s * sin(phi) * B + c * cone.axis);
}

// The objects that can block the sky above P, as bits.
int occluder_mask(vec3 P, vec3 N, vec3 up) {
    int mask = 0;
    for (int k = 0; k < MAX_SKY_OCCLUDERS; ++k)
        if (k < u_sky_occluder_count && occluder_cone(k, P, N, up).z != kOccluderNone) mask |= 1 << k;
    return mask;
}

int bit_count(int mask) {
    int count = 0;
    for (int k = 0; k < MAX_SKY_OCCLUDERS; ++k) count += (mask >> k) & 1;
    return count;
}

// The blocked part's techniques: one an object of `mask` and, where lobe.w > 0, the
// highlight's lobe ((lobe.xyz . w)+)^lobe.w (common/area_lights.glsl:
// lobe_technique_direction), which the cones, uniform in solid angle, meet only now and
// then where an object stands in V's mirror direction: a principled floor at the
// foot of four objects, its grazing Fresnel lobe drawn from their cones alone, was up
// to 0.076 off, above and below, and in places below zero.
int occluder_techniques(int mask, vec4 lobe) {
    return bit_count(mask) + (lobe.w > 0.0 ? 1 : 0);
}

// Sample j of the blocked part, `per` samples a technique (occluder_techniques):
// its direction, and the balance heuristic's weight 1 / sum_k per p_k(w).
vec3 occluder_sample(int j, int per, int mask, vec4 lobe, vec2 rotation, vec3 P, vec3 N, vec3 up,
                     out float weight) {
    int technique = j / per, seen = 0, k_of = -1;
    for (int k = 0; k < MAX_SKY_OCCLUDERS; ++k) {
        if (((mask >> k) & 1) == 0) continue;
        if (seen == technique) k_of = k;
        ++seen;
    }
    // Each technique's strata shifted on their own (the same pixel, another hash).
    vec2 shift = fract(rotation + vec2(0.618034, 0.754878) * float((k_of < 0 ? MAX_SKY_OCCLUDERS : k_of) + 1));
    vec2 u = net_point(j - technique * per, per, shift);
    vec3 w;
    float density = 0.0;
    if (k_of < 0) {
        w = lobe_technique_direction(u, lobe.xyz, lobe.w, LIGHT_SKY);
    } else {
        OccluderCone own = occluder_cone(k_of, P, N, up);
        w = occluder_direction(own, u);
        // The drawing technique's own density whatever its cone test says of w: a
        // direction drawn at a narrow cone's rim can fail the test by rounding (SwiftShader
        // did), and weighed by a wide technique's density alone it was a firefly.
        density = float(per) * occluder_density(own);
    }
    for (int k = 0; k < MAX_SKY_OCCLUDERS; ++k)
        if (k != k_of && ((mask >> k) & 1) != 0) density += float(per) * occluder_pdf(occluder_cone(k, P, N, up), w);
    // The lobe's samples count only inside some object's cone: every direction an
    // object of `mask` blocks lies in its cone, and one at a cone's rim that meets the
    // object by rounding would be weighed by the lobe's thin tail alone.
    bool in_a_cone = density > 0.0;
    if (lobe.w > 0.0) density += float(per) * lobe_technique_pdf(w, lobe.xyz, lobe.w, LIGHT_SKY);
    weight = in_a_cone ? 1.0 / density : 0.0;
    return w;
}

// ---- The exact part: spheres, boxes, prisms ---------------------------------------------
// The samples above estimate what the objects block; its largest part has a
// closed form where the object is a sphere, a box (a cube, a plane) or a
// capped cylinder's prism: the projected solid angle of its silhouette. The samples that meet such a shape
// are scaled so that their sum of N . L equals that exact part, as the
// emitters' samples are by E / E_s (common/lights.glsl): the Lambert term of
// what spheres and boxes take from the sky is then exact where their
// silhouettes do not overlap (where they do, the samples' noise remains); a
// model with a highlight takes the factor on each sample's share of the cosine
// (common/lights.glsl: light_walk_sample), and the samples blocked by other
// objects are as before. Both closed forms and every test below start at o,
// the shadow ray's own origin (P + eps N, common/shadows.glsl).

// Where the ray rel + t w (rel from a point on the unit axis a) is within `radius` of
// that axis: [t0, t1], empty (t0 > t1) where never.
vec2 cylinder_interval(vec3 rel, vec3 w, vec3 a, float radius) {
    vec3 rp = rel - dot(rel, a) * a, wp = w - dot(w, a) * a;
    float qa = dot(wp, wp), qb = dot(rp, wp), qc = dot(rp, rp) - radius * radius;
    if (qa < 1e-20) return qc <= 0.0 ? vec2(-3.4e38, 3.4e38) : vec2(1.0, 0.0);
    float disc = qb * qb - qa * qc;
    if (disc < 0.0) return vec2(1.0, 0.0);
    float root = sqrt(disc);
    return vec2((-qb - root) / qa, (-qb + root) / qa);
}

// Whether the ray o + t w, t > 0, meets prism k: inside both rims' planes, then the
// circumscribed cylinder (radius R) and the inscribed one (R cos(pi / n)) decide all
// but the rays between them, which take the prism's n faces one by one.
bool prism_meets(int k, vec3 o, vec3 w) {
    vec4 a = u_sky_occluder_frame[4 * k], t = u_sky_occluder_frame[4 * k + 1], b = u_sky_occluder_frame[4 * k + 2];
    vec3 rel = o - u_sky_occluder_frame[4 * k + 3].xyz;
    float s = dot(a.xyz, rel), v = dot(a.xyz, w), enter = 0.0, leave = 3.4e38;
    if (abs(v) < 1e-30) {
        if (abs(s) > a.w) return false;
    } else {
        float t0 = (-a.w - s) / v, t1 = (a.w - s) / v;
        enter = max(enter, min(t0, t1));
        leave = min(leave, max(t0, t1));
    }
    if (enter > leave) return false;
    vec2 outer = cylinder_interval(rel, w, a.xyz, t.w);
    if (max(enter, outer.x) > min(leave, outer.y)) return false;
    int n = int(b.w + 0.5);
    float inradius = t.w * cos(PI / float(n));
    vec2 inner = cylinder_interval(rel, w, a.xyz, inradius);
    if (max(enter, inner.x) <= min(leave, inner.y)) return true;
    for (int f = 0; f < n; ++f) {
        float phi = 2.0 * PI * (float(f) + 0.5) / float(n);
        vec3 normal = cos(phi) * t.xyz + sin(phi) * b.xyz;  // face f's, between corners f and f + 1
        float sf = dot(normal, rel) - inradius, vf = dot(normal, w);
        if (abs(vf) < 1e-30) {
            if (sf > 0.0) return false;
            continue;
        }
        if (vf > 0.0) leave = min(leave, -sf / vf);
        else enter = max(enter, -sf / vf);
        if (enter > leave) return false;
    }
    return true;
}

// Whether the ray o + t w, t > 0, meets object k's exact shape (a sphere, a box
// or a prism; false for any other object). A box's slab test and a prism's faces
// meet the same faces as their triangles do (common/shadows.glsl).
bool occluder_shape_meets(int k, vec3 o, vec3 w) {
    float shape = u_sky_occluder_half[k].w;
    if (shape == kOccluderSphere)
        return ray_meets_sphere(o, w, u_sky_occluder_sphere[k].xyz, u_sky_occluder_sphere[k].w, 3.4e38);
    if (shape == kOccluderPrism) return prism_meets(k, o, w);
    if (shape != kOccluderBox) return false;
    vec3 rel = o - u_sky_occluder_frame[4 * k + 3].xyz;
    float enter = 0.0, leave = 3.4e38;
    for (int a = 0; a < 3; ++a) {
        vec4 axis = u_sky_occluder_frame[4 * k + a];
        float s = dot(axis.xyz, rel), v = dot(axis.xyz, w);
        if (abs(v) < 1e-30) {
            if (abs(s) > axis.w) return false;
            continue;
        }
        float t0 = (-axis.w - s) / v, t1 = (axis.w - s) / v;
        enter = max(enter, min(t0, t1));
        leave = min(leave, max(t0, t1));
    }
    return enter <= leave;
}

// The corners of a convex polygon (`count` of them, in order, from the point)
// clipped to plane . x > 0 (Sutherland-Hodgman): at most one more than before.
int clip_corners(inout vec3 v[6], int count, vec3 plane) {
    vec3 kept[6] = v;
    int out_count = 0;
    for (int j = 0; j < count; ++j) {
        vec3 a = kept[j], b = kept[j + 1 < count ? j + 1 : 0];
        float ha = dot(plane, a), hb = dot(plane, b);
        if (ha > 0.0) v[out_count++] = a;
        if ((ha > 0.0) != (hb > 0.0)) v[out_count++] = a + (ha / (ha - hb)) * (b - a);
    }
    return out_count;
}

// Lambert's formula about N over a polygon's corners (in order, from the point).
float corners_projected_solid_angle(vec3 v[6], int count, vec3 N) {
    float sum = 0.0;
    for (int j = 0; j < count; ++j) sum += lambert_edge(v[j], v[j + 1 < count ? j + 1 : 0], N);
    return 0.5 * abs(sum);
}

// The projected solid angle about N of the rect with corners q0..q3 (from the
// point, in order) above up's and N's horizons: clipped against up . x > 0 (at
// most five corners), then against N . x > 0 (at most six), then Lambert's formula
// (as rect_projected_solid_angle, common/area_lights.glsl). Clipped as a polygon,
// not as arcs of great circles (lobe_integral_in_hemispheres): where an edge's
// plane nearly holds N's horizon, the arcs' ends are ill-conditioned.
float face_projected_solid_angle(vec3 q0, vec3 q1, vec3 q2, vec3 q3, vec3 up, vec3 N) {
    vec3 v[6] = vec3[6](q0, q1, q2, q3, q3, q3);
    int count = clip_corners(v, 4, up);
    count = clip_corners(v, count, N);
    return corners_projected_solid_angle(v, count, N);
}

// The projected solid angle about N of the lune of `cone` above up's horizon: the
// lune as the polygon of its two ends and the middles of its two sides (each 90
// degrees from the next), clipped against up . x > 0. (Unclipped: pi (1 - N . face) / 2.)
float lune_projected_solid_angle(OccluderCone cone, vec3 up) {
    vec3 end = normalize(cross(cone.axis, cone.face)), start = lune_start(cone);
    vec3 v[6] = vec3[6](end, start, -end, cos(cone.one_minus) * start + sin(cone.one_minus) * cone.axis, end, end);
    return corners_projected_solid_angle(v, clip_corners(v, 4, up), cone.axis);
}

// Whether a prism's side face f (between corners f and f + 1, `angle_step` apart) faces the
// point its centre is at `to_centre` from: the point outside the face's plane.
bool prism_face_toward(int f, float angle_step, vec3 t, vec3 b, vec3 to_centre, float inradius) {
    float phi = angle_step * (float(f) + 0.5);
    return -dot(cos(phi) * t + sin(phi) * b, to_centre) > inradius;
}

// Lambert's formula over a convex polygon clipped to the hemispheres above up's and
// N's horizons, its edges given one at a time in any order (each directed round the
// polygon the same way): Sutherland-Hodgman edge by edge, against up . x > 0, then
// against N . x > 0. Each edge's part above both adds its term; where the outline
// leaves a horizon and where it comes back are kept, and the chord between them along
// the horizon closes the clipped polygon (up's chord itself clipped against N's).
struct ClippedOutline {
    float sum;                 // the terms so far
    vec3 exit_up, entry_up;    // where the outline crosses up's horizon, going out and coming back
    vec3 exit_N, entry_N;      // ... N's, of the outline clipped to up's hemisphere
    int crossed;               // bits: 1 exit_up, 2 entry_up, 4 exit_N, 8 entry_N
};

ClippedOutline clipped_outline() {
    ClippedOutline c;
    c.sum = 0.0;
    c.exit_up = c.entry_up = c.exit_N = c.entry_N = vec3(0.0);
    c.crossed = 0;
    return c;
}

// Edge a -> b, already above up's horizon, clipped against N's.
void outline_edge_above_up(inout ClippedOutline c, vec3 a, vec3 b, vec3 N) {
    float ha = dot(N, a), hb = dot(N, b);
    if ((ha > 0.0) != (hb > 0.0)) {
        vec3 x = a + (ha / (ha - hb)) * (b - a);
        if (ha > 0.0) {
            c.exit_N = x;
            c.crossed |= 4;
            b = x;
        } else {
            c.entry_N = x;
            c.crossed |= 8;
            a = x;
        }
    } else if (!(ha > 0.0)) {
        return;
    }
    c.sum += lambert_edge(a, b, N);
}

void outline_edge(inout ClippedOutline c, vec3 a, vec3 b, vec3 N, vec3 up) {
    float ha = dot(up, a), hb = dot(up, b);
    if ((ha > 0.0) != (hb > 0.0)) {
        vec3 x = a + (ha / (ha - hb)) * (b - a);
        if (ha > 0.0) {
            c.exit_up = x;
            c.crossed |= 1;
            b = x;
        } else {
            c.entry_up = x;
            c.crossed |= 2;
            a = x;
        }
    } else if (!(ha > 0.0)) {
        return;
    }
    outline_edge_above_up(c, a, b, N);
}

float outline_projected_solid_angle(ClippedOutline c, vec3 N) {
    if ((c.crossed & 3) == 3) outline_edge_above_up(c, c.exit_up, c.entry_up, N);
    if ((c.crossed & 12) == 12) c.sum += lambert_edge(c.exit_N, c.entry_N, N);
    return 0.5 * abs(c.sum);
}

// The projected solid angle about N of prism k seen from o, above N's and up's horizons,
// -1 where o is within its radius of the axis (on it: the lune of the face it lies on, or
// its own samples, decide). Lambert's formula over the outline of the faces that face o (a
// convex prism's cover its silhouette once), clipped to both horizons: each side face's
// bottom and top edges (the near rims), its side edges where the next face turns away (the
// outline's two sides), and where a cap faces o, the cap's edges beside the side faces that
// turn away (the far rim), all taken round each face the same way.
float prism_projected(int k, vec3 o, vec3 N, vec3 up) {
    vec4 a = u_sky_occluder_frame[4 * k], t = u_sky_occluder_frame[4 * k + 1], b = u_sky_occluder_frame[4 * k + 2];
    vec3 to_centre = u_sky_occluder_frame[4 * k + 3].xyz - o;
    float h = -dot(to_centre, a.xyz);  // o's height along the axis
    if (length(-to_centre - h * a.xyz) <= 1.001 * t.w) return -1.0;
    int n = int(b.w + 0.5);
    float inradius = t.w * cos(PI / float(n)), angle_step = 2.0 * PI / float(n);
    bool top = h > a.w, bottom = h < -a.w;  // a cap faces o
    vec3 top_axis = to_centre + a.w * a.xyz, bottom_axis = to_centre - a.w * a.xyz;
    bool previous = prism_face_toward(n - 1, angle_step, t.xyz, b.xyz, to_centre, inradius);
    bool current = prism_face_toward(0, angle_step, t.xyz, b.xyz, to_centre, inradius);
    ClippedOutline outline = clipped_outline();
    vec3 r0 = t.w * t.xyz;  // corner 0's radius; each next corner's carried round
    for (int f = 0; f < n; ++f) {
        bool next = prism_face_toward(f + 1, angle_step, t.xyz, b.xyz, to_centre, inradius);
        vec3 r1 = t.w * (cos(angle_step * float(f + 1)) * t.xyz + sin(angle_step * float(f + 1)) * b.xyz);
        vec3 b0 = bottom_axis + r0, b1 = bottom_axis + r1, t0 = top_axis + r0, t1 = top_axis + r1;
        if (current) {
            if (!bottom) outline_edge(outline, b0, b1, N, up);
            if (!top) outline_edge(outline, t1, t0, N, up);
            if (!next) outline_edge(outline, b1, t1, N, up);
            if (!previous) outline_edge(outline, t0, b0, N, up);
        } else {
            if (top) outline_edge(outline, t0, t1, N, up);
            if (bottom) outline_edge(outline, b1, b0, N, up);
        }
        previous = current;
        current = next;
        r0 = r1;
    }
    return outline_projected_solid_angle(outline, N);
}

// The projected solid angle about N of what object k blocks above N's and up's
// horizons, seen from o: a sphere's silhouette (a cone, as a disk: the circle
// where the tangents from o touch it), where its rim is wholly above up's
// horizon or that horizon is N's; a box's faces that face o (a convex box's front faces cover its
// silhouette once), each a rect clipped to both horizons. -1 where neither applies.
float occluder_shape_projected(int k, vec3 o, vec3 N, vec3 up) {
    float shape = u_sky_occluder_half[k].w;
    if (shape == kOccluderSphere) {
        vec4 sphere = u_sky_occluder_sphere[k];
        vec3 to_centre = sphere.xyz - o;
        float d2 = dot(to_centre, to_centre), r2 = sphere.w * sphere.w;
        if (d2 <= 1.001 * r2) return -1.0;  // on or in it: it blocks nothing above a convex surface's own horizon
        float shrink = 1.0 - r2 / d2;
        vec3 axis = to_centre * inversesqrt(d2), c = to_centre * shrink;
        float rim = sphere.w * sqrt(shrink);
        // Its rim wholly above up's horizon, or up's horizon N's (a floor under a sphere resting
        // on it: the rim touches the horizon there, and N's clipping is up's).
        bool up_is_N = length(cross(up, N)) < 1e-6 && dot(up, N) > 0.0;
        if (!up_is_N && dot(up, c) <= rim * length(cross(up, axis))) return -1.0;
        vec3 T, B;
        complete_frame(axis, T, B);
        return disk_projected_solid_angle(c, rim * T, rim * B, N);
    }
    if (shape == kOccluderBox) {
        vec3 centre = u_sky_occluder_frame[4 * k + 3].xyz - o;
        float sum = 0.0;
        for (int face = 0; face < 6; ++face) {
            int a = face % 3;
            float side = face < 3 ? 1.0 : -1.0;
            vec4 n = u_sky_occluder_frame[4 * k + a], u = u_sky_occluder_frame[4 * k + (a + 1) % 3],
                 v = u_sky_occluder_frame[4 * k + (a + 2) % 3];
            if (u.w <= 0.0 || v.w <= 0.0) continue;  // a plane's sides: no area
            vec3 c = centre + side * n.w * n.xyz;       // the face's centre from o
            if (dot(side * n.xyz, c) >= 0.0) continue;  // o behind or in its plane
            vec3 e0 = u.w * u.xyz, e1 = v.w * v.xyz;
            sum += face_projected_solid_angle(c - e0 - e1, c + e0 - e1, c + e0 + e1, c - e0 + e1, up, N);
        }
        return sum;
    }
    if (shape == kOccluderPrism) {
        vec3 face;
        if (!prism_own_face(k, o, N, face)) return prism_projected(k, o, N, up);
        OccluderCone lune;  // as occluder_cone draws it
        lune.axis = N;
        lune.z = kOccluderLune;
        lune.one_minus = acos(clamp(dot(N, face), -1.0, 1.0));
        lune.face = face;
        return lune_projected_solid_angle(lune, up);
    }
    return -1.0;
}

// The exact part of what the objects of `mask` block above P: the sum of their
// silhouettes' closed forms, and (exact_mask) the objects that have one here.
float occluder_exact_part(int mask, vec3 P, vec3 N, vec3 up, out int exact_mask) {
    vec3 o = shadow_ray_origin(P, N);
    exact_mask = 0;
    float exact = 0.0;
    for (int k = 0; k < MAX_SKY_OCCLUDERS; ++k) {
        if (((mask >> k) & 1) == 0) continue;
        float projected = occluder_shape_projected(k, o, N, up);
        if (projected < 0.0) continue;
        exact += projected;
        exact_mask |= 1 << k;
    }
    return exact;
}

// Of `per` samples a technique (occluder_techniques): the sum of weight x N . L over those that
// meet an exact shape of `exact_mask`, and of the same times the number of shapes
// each meets beyond the first (the overlap's excess).
vec2 exact_shape_sums(int per, int mask, vec4 lobe, vec2 rotation, vec3 P, vec3 N, vec3 up, int exact_mask) {
    vec3 o = shadow_ray_origin(P, N);
    vec2 sums = vec2(0.0);
    int count = occluder_techniques(mask, lobe) * per;
    for (int j = 0; j < count; ++j) {
        float weight;
        vec3 L = occluder_sample(j, per, mask, lobe, rotation, P, N, up, weight);
        float c = dot(N, L);
        if (!(weight > 0.0 && c > 0.0 && dot(up, L) > 0.0)) continue;
        int hits = 0;
        for (int k = 0; k < MAX_SKY_OCCLUDERS; ++k)
            if (((exact_mask >> k) & 1) != 0 && occluder_shape_meets(k, o, L)) ++hits;
        if (hits > 0) sums += weight * c * vec2(1.0, float(hits - 1));
    }
    return sums;
}

// The factor for the blocked samples that meet an exact shape of `mask`
// (occluder_sample, `per` a technique of `mask`): the exact part over the
// samples' estimate of it (their sum of weight x N . L). The closed forms'
// sum counts twice where two silhouettes overlap; an estimate of that excess
// (samples that meet more than one shape) is taken off it, so only the overlap
// is noisy; it is drawn from overlap_per samples a technique, more than the
// walk's `per` (it walks no model, and its noise was most of a floor's error
// under a sphere beside a cube). 1 where no object of `mask` has a closed form
// here. Walks the samples ahead of the model, with no ray: the factor depends
// only on the exact shapes, so a shadow ray that other hardware's rounding
// turns cannot move it.
float occluder_exact_ratio(int per, int overlap_per, int mask, vec4 lobe, vec2 rotation, vec3 P, vec3 N, vec3 up,
                           int exact_mask, float exact) {
    if (exact_mask == 0) return 1.0;
    vec2 sums = exact_shape_sums(per, mask, lobe, rotation, P, N, up, exact_mask);
    float twice = sums.y;
    if (overlap_per != per && bit_count(exact_mask) > 1)
        twice = exact_shape_sums(overlap_per, mask, lobe, rotation, P, N, up, exact_mask).y;
    return sums.x > 0.0 && exact > twice ? (exact - twice) / sums.x : 1.0;
}

// What blocks a sample of the blocked part: nothing, an exact shape of
// `exact_mask` (no ray needed), or another object.
const int kBlockedByNothing = 0;
const int kBlockedByOther = 1;
const int kBlockedByExactShape = 2;

int occluder_blocker(int mask, int exact_mask, vec3 P, vec3 N, vec3 L) {
    vec3 o = shadow_ray_origin(P, N);
    bool other = false;
    for (int k = 0; k < MAX_SKY_OCCLUDERS; ++k) {
        if (((mask >> k) & 1) == 0 || !occluder_shape_meets(k, o, L)) continue;
        if (((exact_mask >> k) & 1) != 0) return kBlockedByExactShape;
        other = true;
    }
    return other || occluded(P, N, L, -1.0) ? kBlockedByOther : kBlockedByNothing;
}
