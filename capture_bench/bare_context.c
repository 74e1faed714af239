/* m3055_bare_context: what a headless capture cannot do without, and nothing
 * more: opens libEGL at run time as m3055 does (renderer/gl/context_egl.cpp),
 * makes an OpenGL 3.3 core context current on Mesa's surfaceless platform and
 * exits. scripts/bench-capture measures `m3055 render` against it.
 * Exit status 0 when the context was made, 1 otherwise (the reason on stderr). */
#include "surfaceless_context.h"

int main(void) { return make_surfaceless_context("m3055_bare_context") ? 0 : 1; }
