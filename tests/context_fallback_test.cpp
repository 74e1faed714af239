// Failure paths of the headless context (docs/spec.md#8-command-line):
// - neither EGL nor OSMesa can be opened: one line naming what to install, exit 1;
// - an EGL that offers no OpenGL 3.3 core context (tests/fakes/fake_egl.c):
//   m3055 falls back to OSMesa and renders the same bytes.
// The libraries are chosen with $M3055_EGL_LIBRARY / $M3055_OSMESA_LIBRARY
// (gl/context.h), which the m3055 child processes inherit.
#include "gl/context.h"
#include "image/image.h"
#include "test_support.h"

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace m3055::test {
namespace {

#ifndef M3055_FAKE_EGL
#error "M3055_FAKE_EGL (the fake libEGL's path) comes from tests/fakes/CMakeLists.txt"
#endif

// Sets an environment variable for the life of the object.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old, had_ = true;
        setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (had_) setenv(name_, old_.c_str(), 1);
        else unsetenv(name_);
    }

private:
    const char* name_;
    std::string old_;
    bool had_ = false;
};

constexpr const char* kMissingEgl = "libEGL-m3055-missing.so.1";
constexpr const char* kMissingOsMesa = "libOSMesa-m3055-missing.so.8";

std::string spec_scene() { return source_path("scenes/spec_example.json"); }

bool one_line(const std::string& text) {
    return !text.empty() && text.find('\n') == text.size() - 1;
}

TEST(ContextFallback, NoEglAndNoOsMesaNamesWhatToInstall) {
    ScopedEnv egl("M3055_EGL_LIBRARY", kMissingEgl);
    ScopedEnv osmesa("M3055_OSMESA_LIBRARY", kMissingOsMesa);
    TempDir dir;
    const RunResult run = run_m3055({"render", "--scene", spec_scene(), "--out", dir.file("out.png")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_TRUE(one_line(run.err)) << run.err;
    EXPECT_NE(run.err.find("no OpenGL 3.3 core context"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(kMissingEgl), std::string::npos) << run.err;     // what was tried
    EXPECT_NE(run.err.find(kMissingOsMesa), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("install libegl1 and libgl1-mesa-dri (EGL) or libosmesa6 (OSMesa)"), std::string::npos)
        << run.err;
    EXPECT_FALSE(file_exists(dir.file("out.png")));
}

TEST(ContextFallback, EachBackendAloneNamesItsOwnPackage) {
    ScopedEnv egl("M3055_EGL_LIBRARY", kMissingEgl);
    ScopedEnv osmesa("M3055_OSMESA_LIBRARY", kMissingOsMesa);
    try {
        HeadlessContext::create(Backend::egl);
        FAIL() << "EGL context from a missing library";
    } catch (const ContextError& error) {
        EXPECT_NE(std::string(error.what()).find("(install libegl1 and libgl1-mesa-dri)"), std::string::npos)
            << error.what();
    }
    try {
        HeadlessContext::create(Backend::osmesa);
        FAIL() << "OSMesa context from a missing library";
    } catch (const ContextError& error) {
        EXPECT_NE(std::string(error.what()).find("(install libosmesa6)"), std::string::npos) << error.what();
    }
}

// The fake EGL's own record of what it was asked for. The test keeps the
// library loaded itself, so the context code's dlopen gets this same copy and
// its dlclose after the failed attempt does not reset the counters.
class FakeEgl {
public:
    FakeEgl() : handle_(dlopen(M3055_FAKE_EGL, RTLD_NOW | RTLD_LOCAL)) {}
    ~FakeEgl() {
        if (handle_) dlclose(handle_);
    }
    bool loaded() const { return handle_ != nullptr; }
    int read(const char* name) const {
        const int* value = handle_ ? static_cast<const int*>(dlsym(handle_, name)) : nullptr;
        return value ? *value : -1;
    }

private:
    void* handle_;
};

TEST(ContextFallback, EglWithoutCoreContextFallsBackToOsMesa) {
    ScopedEnv egl("M3055_EGL_LIBRARY", M3055_FAKE_EGL);
    // EGL alone: both the surfaceless display and the device refuse a 3.3 core context.
    try {
        HeadlessContext::create(Backend::egl);
        FAIL() << "the fake EGL gave a context";
    } catch (const ContextError& error) {
        const std::string what = error.what();
        EXPECT_NE(what.find("egl-surfaceless: no OpenGL 3.3 core context"), std::string::npos) << what;
        EXPECT_NE(what.find("egl-device: no OpenGL 3.3 core context"), std::string::npos) << what;
    }
    // Automatic: asks the fake EGL (once per display) for 3.3 core, then takes OSMesa.
    const FakeEgl fake;
    ASSERT_TRUE(fake.loaded()) << dlerror();
    const int before = fake.read("m3055_fake_egl_context_requests");
    auto context = HeadlessContext::create(Backend::automatic);
    ASSERT_TRUE(context);
    EXPECT_EQ(context->backend_name(), "osmesa");
    EXPECT_EQ(fake.read("m3055_fake_egl_context_requests") - before, 2);  // surfaceless, then the device
    EXPECT_EQ(fake.read("m3055_fake_egl_last_major"), 3);
    EXPECT_EQ(fake.read("m3055_fake_egl_last_minor"), 3);
    EXPECT_EQ(fake.read("m3055_fake_egl_last_profile"), 0x1);  // EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT
    EXPECT_NE(context->renderer_string(), "unknown");
}

TEST(ContextFallback, RenderWithBrokenEglWritesTheSameBytesAsOsMesa) {
    TempDir dir;
    const RunResult osmesa =
        run_m3055({"render", "--scene", spec_scene(), "--out", dir.file("osmesa.png"), "--backend", "osmesa"});
    ASSERT_EQ(osmesa.exit_code, 0) << osmesa.err;
    ScopedEnv egl("M3055_EGL_LIBRARY", M3055_FAKE_EGL);
    const RunResult fallback = run_m3055({"render", "--scene", spec_scene(), "--out", dir.file("auto.png")});
    ASSERT_EQ(fallback.exit_code, 0) << fallback.err;
    EXPECT_EQ(fallback.err, "");
    EXPECT_EQ(read_text(dir.file("auto.png")), read_text(dir.file("osmesa.png")));
    const RunResult egl_only =
        run_m3055({"render", "--scene", spec_scene(), "--out", dir.file("egl.png"), "--backend", "egl"});
    EXPECT_EQ(egl_only.exit_code, 1);
    EXPECT_NE(egl_only.err.find("no OpenGL 3.3 core context"), std::string::npos) << egl_only.err;
    EXPECT_FALSE(file_exists(dir.file("egl.png")));
}

}  // namespace
}  // namespace m3055::test
