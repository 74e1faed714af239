#pragma once
// Where the tests find the repository (and its tests/data/) and the built
// executables. The paths are compiled into one generated file in the build tree
// (tests/CMakeLists.txt: test_paths.cpp), not into every test's command line,
// so that the test files compile to the same objects in every clone and the
// compiler cache (ccache) serves a fresh clone from a warm cache.

namespace m3055::test {
const char* source_dir();     // the repository's root
const char* m3055_binary();   // the built m3055
const char* measure_child();  // tests/support/measure_child.c, built
const char* build_dir();      // the build tree (its library_graph.txt, ...)
}  // namespace m3055::test

#define M3055_SOURCE_DIR (::m3055::test::source_dir())
#define M3055_BINARY (::m3055::test::m3055_binary())
#define M3055_MEASURE_CHILD (::m3055::test::measure_child())
