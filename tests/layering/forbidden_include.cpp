// Compiled only by the test Layering.ForbiddenIncludeFailsToCompile (never by
// the build): the scene library may not reach the frame (the GPU renderer sits
// above it), so this include must fail with "No such file or directory".
#include "frame/renderer.h"
