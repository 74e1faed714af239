// The CPU reference mirrors the GLSL by name (the design notes: "the GLSL term
// and its C++ reference side by side in review, with the same names"): every
// function defined in glsl/terms/ and glsl/models/ has a C++ function of the
// same name defined in renderer/reference/, model level included.
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>

namespace m3055 {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> files_in(const std::string& dir, const std::set<std::string>& extensions) {
    std::vector<std::string> out;
    for (const auto& entry : fs::directory_iterator(test::source_path(dir)))
        if (entry.is_regular_file() && extensions.count(entry.path().extension().string()))
            out.push_back(entry.path().string());
    return out;
}

// Names of the functions a GLSL file defines: "TYPE NAME(...) {" at the start of a line.
std::set<std::string> glsl_functions(const std::string& text) {
    static const std::regex definition(R"((?:^|\n)[A-Za-z_]\w*\s+([A-Za-z_]\w*)\s*\([^;{]*\)\s*\{)");
    std::set<std::string> names;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), definition); it != std::sregex_iterator(); ++it)
        names.insert((*it)[1].str());
    return names;
}

// True when C++ `text` defines a function `name`: a return type, the name, its
// parameter list and a body on the lines that follow.
bool cpp_defines(const std::string& text, const std::string& name) {
    const std::regex definition("(^|\\n)(static\\s+|inline\\s+)*[A-Za-z_][\\w:<>]*[\\s&*]+" + name +
                                "\\s*\\([^;{]*\\)\\s*(const\\s*)?\\{");
    return std::regex_search(text, definition);
}

TEST(ReferenceNamesakes, EveryGlslTermAndModelFunctionHasACppTwin) {
    std::string reference;
    for (const std::string& file : files_in("renderer/reference", {".cpp", ".h"}))
        reference += test::read_text(file) + "\n";
    int checked = 0;
    for (const char* dir : {"glsl/terms", "glsl/models"}) {
        for (const std::string& file : files_in(dir, {".glsl"})) {
            for (const std::string& name : glsl_functions(test::read_text(file))) {
                ++checked;
                EXPECT_TRUE(cpp_defines(reference, name))
                    << fs::path(file).filename().string() << ": " << name << " has no C++ namesake in renderer/reference/";
            }
        }
    }
    EXPECT_GT(checked, 40);  // the files were found and read
}

TEST(ReferenceNamesakes, TheCheckSeesAMissingTwin) {
    EXPECT_EQ(glsl_functions("float a_term(float x) {\n    return x;\n}\nvec3 b(vec3 v,\n  float s) {\n}\n"),
              (std::set<std::string>{"a_term", "b"}));
    EXPECT_TRUE(cpp_defines("double a_term(double x) {\n", "a_term"));
    EXPECT_TRUE(cpp_defines("dvec3 b(const dvec3& v,\n       double s) {\n", "b"));
    EXPECT_FALSE(cpp_defines("    return a_term(x);\n", "a_term"));  // a call is not a twin
    EXPECT_FALSE(cpp_defines("double a_term(double x);\n", "a_term"));  // nor a declaration alone
    EXPECT_TRUE(cpp_defines("static double a_term(double x) {\n", "a_term"));
}

}  // namespace
}  // namespace m3055
