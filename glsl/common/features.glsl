// What a program supports. A general program (no SPECIALIZED define) has every
// model and light kind and chooses at run time; a specialized one is compiled
// for one scene's needs (renderer/passes/shader_plan.cpp sets the HAS_* and
// LIGHT_COUNT defines), so the branches and loops it does not need vanish.
#ifndef SPECIALIZED
#define HAS_HIGHLIGHT
#define HAS_METAL
#define HAS_METAL_BLINN
#define HAS_METAL_PHONG
#define HAS_POINT_LIGHTS
#define HAS_SPOT_LIGHTS
#define HAS_LIGHT_LOBES
#define HAS_LAMBERT
#define HAS_HALF_LAMBERT
#define HAS_HALF_LAMBERT_CLAMPED
#define HAS_HALF_LAMBERT_NORMALIZED
#define HAS_OREN_NAYAR
#define HAS_PHONG
#define HAS_BLINN_PHONG
#define HAS_MICROFACET
#define HAS_WARD
#define HAS_HEIDRICH_SEIDEL
#endif

// The classic models of SPEC 5 (models/classic.glsl).
// (GLSL 3.30 has no line continuation: two short tests.)
#if defined(HAS_LAMBERT) || defined(HAS_HALF_LAMBERT) || defined(HAS_HALF_LAMBERT_CLAMPED) || defined(HAS_OREN_NAYAR)
#define HAS_CLASSIC_FAMILY
#elif defined(HAS_HALF_LAMBERT_NORMALIZED) || defined(HAS_PHONG) || defined(HAS_BLINN_PHONG)
#define HAS_CLASSIC_FAMILY
#elif defined(HAS_MICROFACET) || defined(HAS_WARD) || defined(HAS_HEIDRICH_SEIDEL)
#define HAS_CLASSIC_FAMILY
#endif

#if defined(HAS_METAL) || defined(HAS_METAL_BLINN) || defined(HAS_METAL_PHONG)
#define HAS_METAL_FAMILY
#endif

// Lights loop to a compile-time count when specialized (the compiler unrolls it).
#ifdef LIGHT_COUNT
#define MAX_LIGHTS (LIGHT_COUNT > 0 ? LIGHT_COUNT : 1)
#define LIGHT_LOOP_END LIGHT_COUNT
#else
#define MAX_LIGHTS 16
#define LIGHT_LOOP_END u_light_count
#endif
