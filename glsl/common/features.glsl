// What a program supports. A general program is compiled with every HAS_*
// define (every model and light kind, chosen at run time); a specialized one
// with SPECIALIZED, LIGHT_COUNT and the HAS_* of one scene's models and lights
// (renderer/passes/shader_plan.cpp), so the branches and loops it does not
// need vanish. The models' HAS_<MODEL> and HAS_FAMILY_<FAMILY> defines come
// from the model table (renderer/models/glsl_generator.cpp); the lights' are
// HAS_POINT_LIGHTS, HAS_SPOT_LIGHTS and HAS_LIGHT_LOBES; HAS_SPECTRAL_TABLES
// where a material reads a spectral table (a measured metal, a colour
// spectrum: passes/spectral_tables.h), whose second shading path otherwise
// doubles the code llvmpipe compiles for the model (29 ms of a cold capture's 146).

// Lights loop to a compile-time count when specialized (the compiler unrolls it).
#ifdef LIGHT_COUNT
#define MAX_LIGHTS (LIGHT_COUNT > 0 ? LIGHT_COUNT : 1)
#define LIGHT_LOOP_END LIGHT_COUNT
#else
#define MAX_LIGHTS 16
#define LIGHT_LOOP_END u_light_count
#endif
