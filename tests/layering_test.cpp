// The library layering (cmake/m3055_library.cmake, docs/architecture.md):
// - docs/architecture.md's library table is the graph the CMake files declare
//   (library_graph.txt, written at configure time), row for row;
// - every #include "folder/file.h" in a library's folder names its own folder
//   or a library it uses, directly or through what those use (the compiler
//   enforces the same through the include roots; this names the line);
// - no file reaches around the include roots with "../".
// Layering.ForbiddenIncludeFailsToCompile (tests/CMakeLists.txt) shows the
// compiler refusing one.
#include "test_paths.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace m3055 {
namespace {

namespace fs = std::filesystem;

struct Library {
    std::string folder;             // relative to the source folder, e.g. "renderer/scene"
    std::vector<std::string> uses;  // library names, as declared
};
using Graph = std::map<std::string, Library>;

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string word; in >> word;) out.push_back(word);
    return out;
}

// Written by cmake/m3055_library.cmake at configure time.
std::string library_graph_path() { return std::string(test::build_dir()) + "/library_graph.txt"; }

// library_graph.txt: "NAME FOLDER: USES..." a line.
Graph cmake_graph() {
    Graph graph;
    std::istringstream lines(read_text(library_graph_path()));
    for (std::string line; std::getline(lines, line);) {
        const auto colon = line.find(':');
        if (colon == std::string::npos) continue;
        const std::vector<std::string> head = words(line.substr(0, colon));
        if (head.size() != 2) continue;
        graph[head[0]] = {head[1], words(line.substr(colon + 1))};
    }
    return graph;
}

// docs/architecture.md's rows "| `NAME` | `FOLDER/` | `USES` `...` | ... |".
Graph documented_graph() {
    Graph graph;
    const std::regex row(R"(^\| `([a-z_]+)` \| `([a-z_/]+)/` \| ([^|]*)\|)");
    const std::regex name("`([a-z_]+)`");
    std::istringstream lines(read_text(test::source_path("docs/architecture.md")));
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (!std::regex_search(line, m, row)) continue;
        Library library{m[2], {}};
        const std::string uses = m[3];
        for (std::sregex_iterator it(uses.begin(), uses.end(), name), end; it != end; ++it)
            library.uses.push_back((*it)[1]);
        graph[m[1]] = library;
    }
    return graph;
}

std::string leaf(const std::string& folder) { return fs::path(folder).filename().string(); }

// The library and everything it uses, directly or not.
std::set<std::string> closure(const Graph& graph, const std::string& start) {
    std::set<std::string> seen;
    std::vector<std::string> todo{start};
    while (!todo.empty()) {
        const std::string name = todo.back();
        todo.pop_back();
        if (!seen.insert(name).second || !graph.count(name)) continue;
        for (const std::string& dep : graph.at(name).uses) todo.push_back(dep);
    }
    return seen;
}

std::vector<fs::path> sources_in(const fs::path& folder) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder)) {
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && (ext == ".cpp" || ext == ".h" || ext == ".c")) files.push_back(entry.path());
    }
    return files;
}

TEST(Layering, ArchitectureDocShowsTheCMakeGraph) {
    const Graph built = cmake_graph();
    const Graph documented = documented_graph();
    ASSERT_FALSE(built.empty()) << library_graph_path();
    for (const auto& [name, library] : built) {
        SCOPED_TRACE("library " + name);
        ASSERT_TRUE(documented.count(name)) << "docs/architecture.md has no row for it";
        EXPECT_EQ(documented.at(name).folder, library.folder);
        EXPECT_EQ(std::set<std::string>(documented.at(name).uses.begin(), documented.at(name).uses.end()),
                  std::set<std::string>(library.uses.begin(), library.uses.end()));
    }
    for (const auto& [name, library] : documented)
        EXPECT_TRUE(built.count(name)) << "docs/architecture.md names library " << name << ", CMake has none";
}

TEST(Layering, EveryIncludeNamesTheLibraryOrOneItUses) {
    const Graph graph = cmake_graph();
    std::map<std::string, std::string> library_of_leaf;  // "scene" -> "scene"
    for (const auto& [name, library] : graph) library_of_leaf[leaf(library.folder)] = name;
    const std::regex include(R"(^\s*#\s*include\s*"([^"]+)\")");
    int checked = 0;
    for (const auto& [name, library] : graph) {
        const std::set<std::string> allowed = closure(graph, name);
        for (const fs::path& file : sources_in(test::source_path(library.folder))) {
            std::istringstream lines(read_text(file));
            int number = 0;
            for (std::string line; std::getline(lines, line);) {
                ++number;
                std::smatch m;
                if (!std::regex_search(line, m, include)) continue;
                const std::string target = m[1];
                const std::string where = library.folder + "/" + file.filename().string() + ":" +
                                          std::to_string(number) + " includes \"" + target + "\"";
                EXPECT_EQ(target.find(".."), std::string::npos) << where << ": around the include roots";
                const auto slash = target.find('/');
                if (slash == std::string::npos) continue;  // its own folder's file
                const auto owner = library_of_leaf.find(target.substr(0, slash));
                if (owner == library_of_leaf.end()) continue;  // a third-party header (<GLFW/...> style)
                ++checked;
                EXPECT_TRUE(allowed.count(owner->second))
                    << where << ": library " << name << " does not use " << owner->second;
            }
        }
    }
    EXPECT_GT(checked, 100);  // the walk really read the sources
}

}  // namespace
}  // namespace m3055
