// The library layering (cmake/m3055_library.cmake, docs/architecture.md):
// - docs/architecture.md's library table is the graph the CMake files declare
//   (library_graph.txt, written at configure time), row for row;
// - every #include "folder/file.h" in a library's folder names its own folder
//   or a library it uses, directly or through what those use (the compiler
//   enforces the same through the include roots; this names the line);
// - no file reaches around the include roots with "../";
// - GLFW and Dear ImGui headers are included only by the explorer's window
//   (app/explore_ui/), so nothing else can come to need a window;
// - every path of the repository that a comment names exists, so that the
//   comments pointing at a file do not rot when it moves.
// Layering.ForbiddenIncludeFailsToCompile (tests/CMakeLists.txt) shows the
// compiler refusing one.
#include "test_paths.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
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

// The repository's own source files: everything under the source folder but
// third_party/, npm's installs (tests/web/node_modules), hidden folders and
// build trees (a folder with a CMakeCache.txt).
std::vector<fs::path> repository_files() {
    std::vector<fs::path> files;
    const fs::path root = test::source_path("");
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
        const fs::path& path = it->path();
        const std::string name = path.filename().string();
        if (it->is_directory()) {
            if (name == "third_party" || name == "node_modules" || name.front() == '.' ||
                fs::exists(path / "CMakeCache.txt"))
                it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file()) files.push_back(path);
    }
    return files;
}

std::string relative_name(const fs::path& file) {
    return file.lexically_relative(test::source_path("")).generic_string();
}

bool is_code(const fs::path& file) {
    static const std::set<std::string> extensions = {".cpp", ".h", ".c", ".cc", ".hpp"};
    return extensions.count(file.extension().string()) > 0;
}

enum class CommentStyle { none, c, hash };

// C, C++, GLSL and JavaScript: // and /* */; CMake, shell and Python: #.
CommentStyle comment_style(const fs::path& file) {
    const std::string ext = file.extension().string(), name = file.filename().string();
    if (is_code(file) || ext == ".glsl" || ext == ".vert" || ext == ".frag" || ext == ".js") return CommentStyle::c;
    if (name == "CMakeLists.txt" || ext == ".cmake" || ext == ".sh" || ext == ".py") return CommentStyle::hash;
    const std::string parent = file.parent_path().filename().string();
    if (ext.empty() && (parent == "scripts" || parent == "slurm" || parent == ".ci")) return CommentStyle::hash;
    return CommentStyle::none;
}

struct CommentLine {
    int line;
    std::string text;
};

// The text of every comment, a piece per line it spans; string literals
// (raw ones too) and code are left out.
std::vector<CommentLine> comments(const std::string& text, CommentStyle style) {
    std::vector<CommentLine> out;
    int line = 1;
    std::string current;
    auto flush = [&]() {
        if (!current.empty()) out.push_back({line, current});
        current.clear();
    };
    enum { code, line_comment, block_comment, quoted } state = code;
    char quote = 0;
    std::string raw_end;  // `)delim"` of a C++ raw string, when in one
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') {
            flush();
            ++line;
            if (state == line_comment) state = code;
            if (state == quoted && quote != '`' && raw_end.empty() && style == CommentStyle::hash) state = code;
            continue;
        }
        switch (state) {
            case code:
                if (style == CommentStyle::c && c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
                    state = line_comment, ++i;
                } else if (style == CommentStyle::c && c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
                    state = block_comment, ++i;
                } else if (style == CommentStyle::hash && c == '#' &&
                           (i == 0 || std::isspace((unsigned char)text[i - 1]) || text[i - 1] == ';')) {
                    state = line_comment;
                } else if (style == CommentStyle::c && c == '"' && i > 0 && text[i - 1] == 'R') {
                    const std::size_t open = text.find('(', i);
                    raw_end = ")" + text.substr(i + 1, open - i - 1) + "\"";
                    state = quoted, quote = '"', i = open;
                } else if (c == '"' || c == '`' || (c == '\'' && style == CommentStyle::hash)) {
                    state = quoted, quote = c;
                } else if (c == '\'' && style == CommentStyle::c) {
                    const std::size_t close = text.find('\'', i + (text[i + 1] == '\\' ? 3 : 2));
                    if (close != std::string::npos && close - i <= 4) i = close;  // a character literal
                }
                break;
            case line_comment: current += c; break;
            case block_comment:
                if (c == '*' && i + 1 < text.size() && text[i + 1] == '/') state = code, ++i;
                else current += c;
                break;
            case quoted:
                if (!raw_end.empty()) {
                    if (text.compare(i, raw_end.size(), raw_end) == 0) i += raw_end.size() - 1, raw_end.clear(), state = code;
                } else if (c == '\\' && quote != '\'') {
                    ++i;
                } else if (c == quote) {
                    state = code;
                }
                break;
        }
    }
    flush();
    return out;
}

// "a/b.{vert,frag}" -> "a/b.vert", "a/b.frag".
std::vector<std::string> expand_braces(const std::string& path) {
    const auto open = path.find('{'), close = path.find('}');
    if (open == std::string::npos || close == std::string::npos || close < open) return {path};
    std::vector<std::string> out;
    std::istringstream choices(path.substr(open + 1, close - open - 1));
    for (std::string choice; std::getline(choices, choice, ',');)
        for (const std::string& rest : expand_braces(path.substr(close + 1)))
            out.push_back(path.substr(0, open) + choice + rest);
    return out;
}

// The paths of files and folders a comment names: words "first/.../name.ext" or
// "first/.../" whose first component is in `firsts` (the repository's top
// folders and the libraries' include-root names); not globs, not parts of
// URLs, not patterns with a capitalized placeholder ("data/conductors/NAME.nk").
std::vector<std::string> mentioned_paths(const std::string& comment, const std::set<std::string>& firsts) {
    static const std::regex word(R"([A-Za-z0-9_.-]+(?:/(?:[A-Za-z0-9_.*-]|\{[A-Za-z0-9_.,-]*\})*)+)");
    static const std::regex placeholder(R"((^|/)[A-Z][A-Z0-9_]+(\.[A-Za-z0-9]+)?(/|$))");
    std::vector<std::string> out;
    for (std::sregex_iterator it(comment.begin(), comment.end(), word), end; it != end; ++it) {
        std::string path = (*it)[0];
        const std::size_t at = std::size_t(it->position(0));
        if (at > 0 && (comment[at - 1] == '/' || comment[at - 1] == ':' || comment[at - 1] == '$')) continue;
        while (!path.empty() && (path.back() == '.' || path.back() == '-')) path.pop_back();
        if (path.find('*') != std::string::npos || std::regex_search(path, placeholder) ||
            !firsts.count(path.substr(0, path.find('/'))))
            continue;
        for (const std::string& one : expand_braces(path)) {
            const std::string last = one.substr(one.rfind('/') + 1);
            const auto dot = last.rfind('.');
            if (one.back() == '/' || (dot != std::string::npos && dot > 0 && dot + 1 < last.size())) out.push_back(one);
        }
    }
    return out;
}

TEST(Layering, CommentPathsAreReadFromCommentsOnly) {
    const std::string source =
        "#include \"scene/load.h\"  // scene/load.cpp does the work\n"
        "const char* p = \"renderer/not_in_a_comment.h\";  /* see glsl/passes/mesh.{vert,frag}\n"
        "   and docs/spec.md#7-scene-files. */ auto r = R\"x(// renderer/raw.h)x\";\n"
        "// https://example.org/renderer/web.h, scenes/*.json, tests/NAME.json, a/b, tests/data/\n";
    std::vector<std::string> found;
    for (const CommentLine& comment : comments(source, CommentStyle::c))
        for (const std::string& path : mentioned_paths(comment.text, {"scene", "glsl", "docs", "renderer", "tests"}))
            found.push_back(std::to_string(comment.line) + ":" + path);
    EXPECT_EQ(found, (std::vector<std::string>{"1:scene/load.cpp", "2:glsl/passes/mesh.vert", "2:glsl/passes/mesh.frag",
                                               "3:docs/spec.md", "4:tests/data/"}));
    std::vector<std::string> cmake;
    for (const CommentLine& comment : comments("set(x \"a#b\")  # cmake/m3055_library.cmake\n", CommentStyle::hash))
        for (const std::string& path : mentioned_paths(comment.text, {"cmake"})) cmake.push_back(path);
    EXPECT_EQ(cmake, std::vector<std::string>{"cmake/m3055_library.cmake"});
}

TEST(Layering, EveryPathACommentNamesExists) {
    const Graph graph = cmake_graph();
    ASSERT_FALSE(graph.empty()) << library_graph_path();
    const fs::path root = test::source_path("");
    // A path starts at the repository's root, or at a library's include root
    // ("scene/load.h"), or in glsl/ (shader files are named from there). A
    // build tree (build/, build-web/: a CMakeCache.txt) is not the repository:
    // what it holds comes and goes with the builds run.
    std::map<std::string, std::vector<fs::path>> bases;
    for (const auto& entry : fs::directory_iterator(root))
        if (entry.is_directory() && entry.path().filename() != ".git" && !fs::exists(entry.path() / "CMakeCache.txt"))
            bases[entry.path().filename().string()].push_back(root);
    for (const auto& [name, library] : graph) bases[leaf(library.folder)].push_back(root / fs::path(library.folder).parent_path());
    for (const auto& entry : fs::directory_iterator(root / "glsl"))
        if (entry.is_directory()) bases[entry.path().filename().string()].push_back(root / "glsl");
    std::set<std::string> firsts;
    for (const auto& [first, where] : bases) firsts.insert(first);
    int checked = 0;
    for (const fs::path& file : repository_files()) {
        const CommentStyle style = comment_style(file);
        if (style == CommentStyle::none) continue;
        for (const CommentLine& comment : comments(read_text(file), style))
            for (const std::string& path : mentioned_paths(comment.text, firsts)) {
                ++checked;
                const std::vector<fs::path>& where = bases.at(path.substr(0, path.find('/')));
                const bool exists = std::any_of(where.begin(), where.end(), [&](const fs::path& base) {
                    std::error_code error;
                    return fs::exists(base / path, error);
                });
                EXPECT_TRUE(exists) << relative_name(file) << ":" << comment.line << ": the comment names " << path
                                    << ", which is not in the repository";
            }
    }
    EXPECT_GT(checked, 300);  // the walk really read the comments
}

TEST(Layering, OnlyTheExplorersWindowIncludesGlfwOrImgui) {
    const std::regex window_header(R"(^\s*#\s*include\s*[<"]\s*(GLFW/|imgui|backends/imgui))");
    int files = 0;
    for (const fs::path& file : repository_files()) {
        if (!is_code(file)) continue;
        ++files;
        const std::string name = relative_name(file);
        if (name.rfind("app/explore_ui/", 0) == 0) continue;
        std::istringstream lines(read_text(file));
        int number = 0;
        for (std::string line; std::getline(lines, line);) {
            ++number;
            EXPECT_FALSE(std::regex_search(line, window_header))
                << name << ":" << number << ": " << line << ": only app/explore_ui/ (the library explore_ui) sees GLFW and ImGui";
        }
    }
    EXPECT_GT(files, 200);
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
