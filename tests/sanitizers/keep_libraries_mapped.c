/* Sanitizer builds only (-DM3055_SANITIZE=ON links this into every target of
 * the build; see the root CMakeLists.txt): dlclose() does nothing, so every
 * shared library stays mapped until the process exits.
 *
 * Why: Mesa's EGL unloads its driver (swrast_dri.so) in eglTerminate. The
 * memory the driver still holds through its own globals then looks leaked to
 * LeakSanitizer, which scans only mapped modules, and the allocation stacks
 * point into an unmapped "<unknown module>" that no suppression can name.
 * With the driver kept mapped, that memory is reachable again (no report), and
 * any real leak inside a GL library has a stack that names it
 * (tests/sanitizers/lsan.supp). Leaving a library loaded is otherwise
 * harmless: every GL library is opened once or twice per process. */
#include <dlfcn.h>

int dlclose(void* handle) {
    (void)handle;
    return 0;
}
