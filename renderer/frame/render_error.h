// What Renderer::render throws that a caller tells apart from a plain
// std::runtime_error: a ShaderError (a broken build or driver, which fails
// every scene, so a batch or a class run stops) and a RenderTimeout (this
// scene passed its deadline). The frame library's own header for them, so
// callers need not reach into gl/ and passes/, where they are thrown.
#pragma once

#include "gl/shader_error.h"
#include "passes/render_timeout.h"
