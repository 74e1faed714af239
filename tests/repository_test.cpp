// Properties of the repository itself, read from its git checkout:
// - it stands alone: no tracked file but .ci/run refers to the `shared` folder
//   that sits beside the project's checkout (a user's clone has nothing there);
// - every link into a section of a Markdown page (`docs/spec.md#43-metal` in a
//   comment, `[spec §7](...)` in a page) names a heading that exists, so that
//   the code's citations of the spec cannot rot.
// The file list comes from `git ls-files`; when the source folder is not a git
// checkout (an unpacked release tarball), these tests are skipped, and say so.
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace m3055 {
namespace {

namespace fs = std::filesystem;

// The only file allowed to use the folder beside the checkout: CI's entry point.
const std::set<std::string> kMayUseSharedFolder = {".ci/run"};

// Tracked files (and files about to be: untracked but not ignored), relative
// to the source folder. Sets `error` when git cannot list them.
std::vector<std::string> repository_files(std::string& error) {
    const std::string command = "git -C '" + test::source_path("") +
                                "' ls-files -z --cached --others --exclude-standard 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) {
        error = "cannot run: " + command;
        return {};
    }
    std::string output;
    char buffer[65536];
    for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
    const int status = pclose(pipe);
    if (status != 0) {
        error = "`" + command + "` failed: " + output;
        return {};
    }
    std::vector<std::string> files;
    std::istringstream names(output);
    std::set<std::string> seen;  // --cached and --others never overlap, but be safe
    for (std::string name; std::getline(names, name, '\0');)
        if (!name.empty() && seen.insert(name).second) files.push_back(name);
    return files;
}

class Repository : public ::testing::Test {
protected:
    void SetUp() override {
        if (!fs::exists(test::source_path(".git")))
            GTEST_SKIP() << test::source_path("") << " is not a git checkout: cannot list the tracked files";
        std::string error;
        files_ = repository_files(error);
        ASSERT_TRUE(error.empty()) << error;
        ASSERT_GT(files_.size(), 50u) << "git ls-files listed too few files";
    }

    // Regular files only: a deleted but still tracked file, or a submodule, is skipped.
    std::string read(const std::string& relative) const {
        const std::string path = test::source_path(relative);
        if (!fs::is_regular_file(path)) return "";
        return test::read_text(path);
    }

    std::vector<std::string> files_;
};

// "Mentions" means any spelling that reaches the folder beside the checkout:
// the parent folder (two dots, then slashes or backslashes, also after more
// dots, or built in CMake from the source dir) followed by the name `shared`,
// and the names of what it holds after `shared` and a slash without the dots
// (its SPEC.md, DESIGN-NOTES.md, reference-images and seeds). Ordinary words
// are not: "shared library", "shared_ptr", "shared by two triangles", a
// sibling folder with a longer name. This file spells its examples out at run
// time so that it does not match itself.
bool mentions_shared_folder(const std::string& text) {
    static const std::regex parent_shared(R"(\.\.[/\\]+shared(?![\w-]))");
    static const std::regex shared_content(
        R"((^|[^\w.-])shared[/\\]+(SPEC\.md|DESIGN-NOTES\.md|reference-images|seeds)\b)");
    return std::regex_search(text, parent_shared) || std::regex_search(text, shared_content);
}

// "FILE:LINE: text" for each line of `text` that mentions the folder. The
// patterns run on a short window around each "shared" only: files can be
// binary, with megabyte-long "lines" that std::regex should not walk.
std::vector<std::string> shared_folder_mentions(const std::string& file, const std::string& text) {
    std::vector<std::string> found;
    std::size_t line_number = 1, counted_to = 0, last_line = 0;
    for (std::size_t at = text.find("shared"); at != std::string::npos; at = text.find("shared", at + 1)) {
        line_number += std::count(text.begin() + counted_to, text.begin() + at, '\n');
        counted_to = at;
        const std::size_t line_start = text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
        const std::size_t line_end = std::min(text.find('\n', at), text.size());
        const std::size_t from = std::max(line_start, at < 8 ? std::size_t(0) : at - 8);
        const std::size_t to = std::min(line_end, at + 48);
        if (line_number == last_line || !mentions_shared_folder(text.substr(from, to - from))) continue;
        last_line = line_number;
        found.push_back(file + ":" + std::to_string(line_number) + ": " + text.substr(from, to - from));
    }
    return found;
}

TEST_F(Repository, NoTrackedFileButCiMentionsTheSharedFolder) {
    std::vector<std::string> offenders;
    for (const std::string& file : files_) {
        if (kMayUseSharedFolder.count(file)) continue;
        for (const std::string& mention : shared_folder_mentions(file, read(file))) offenders.push_back(mention);
    }
    std::string list;
    for (const std::string& offender : offenders) list += "\n  " + offender;
    EXPECT_TRUE(offenders.empty()) << "a clone has no shared folder beside it; use docs/spec.md or "
                                      "tests/data/ instead:" << list;
}

// The patterns catch what they must and nothing else (the test above would
// pass trivially if they matched nothing), also inside a long binary-like line.
TEST(SharedFolderMentions, CatchReferencesAndNotOrdinaryWords) {
    const std::string up = std::string(".") + ".", shared = std::string("sha") + "red";
    const std::vector<std::string> mentions = {
        "see " + up + "/" + shared + "/SPEC.md", "DIR=\"${PROJECT_SOURCE_DIR}/" + up + "/" + shared + "\"",
        "cp " + up + "/" + up + "/" + shared + "/x .", "dir " + up + "\\" + shared,
        "`" + up + "/" + shared + "`.", "(see " + up + "/" + shared + ".)",
        "in " + shared + "/reference-images/NAME", shared + "/SPEC.md section 4",
        "seeds in " + shared + "/seeds/000.txt", "/work/" + shared + "/DESIGN-NOTES.md"};
    for (const std::string& line : mentions) EXPECT_EQ(shared_folder_mentions("f", line).size(), 1u) << line;
    const std::vector<std::string> ordinary = {
        "a shared library", "std::shared_ptr<Image>", "shared by two triangles", up + "/" + shared + "_cache",
        up + "/" + shared + "lib", "tests/data/reference-images/", "my_" + shared + "/reference-images",
        "docs/spec.md#43-metal"};
    for (const std::string& line : ordinary) EXPECT_TRUE(shared_folder_mentions("f", line).empty()) << line;
    const std::string binary =
        std::string(1 << 20, '\x7f') + "x/" + up + "/" + shared + "/y" + std::string(1 << 20, 'z');
    const auto found = shared_folder_mentions("blob", "line one\n" + binary);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].substr(0, 7), "blob:2:");
}

// GitHub's anchor for a heading: lower case, punctuation and symbols dropped,
// spaces to hyphens. Non-ASCII bytes are dropped too, which matches GitHub for
// the symbols our headings use (§, –, ×) but not for accented letters.
std::string heading_anchor(const std::string& heading) {
    std::string anchor;
    for (unsigned char c : heading) {
        if (std::isalnum(c) || c == '_' || c == '-') anchor += char(std::tolower(c));
        else if (c == ' ') anchor += '-';
    }
    return anchor;
}

TEST(HeadingAnchor, FollowsGitHub) {
    EXPECT_EQ(heading_anchor("§4.3 metal"), "43-metal");
    EXPECT_EQ(heading_anchor("§4 Paper models"), "4-paper-models");
    EXPECT_EQ(heading_anchor("Scene files"), "scene-files");
    EXPECT_EQ(heading_anchor("`microfacet`: D, F and G"), "microfacet-d-f-and-g");
    EXPECT_EQ(heading_anchor("Lobe weights of the cheap metals (Figs. 12, 13)"),
              "lobe-weights-of-the-cheap-metals-figs-12-13");
}

// Anchors of every heading in a Markdown file (a repeated heading gets -1, -2...).
std::set<std::string> anchors_of(const std::string& markdown) {
    std::set<std::string> anchors;
    std::map<std::string, int> count;
    std::istringstream lines(markdown);
    bool in_code = false;
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("```", 0) == 0) in_code = !in_code;
        if (in_code) continue;
        std::smatch m;
        static const std::regex heading(R"(^#{1,6}\s+(.*?)\s*$)");
        if (!std::regex_match(line, m, heading)) continue;
        const std::string base = heading_anchor(m[1].str());
        const int n = count[base]++;
        anchors.insert(n == 0 ? base : base + "-" + std::to_string(n));
    }
    return anchors;
}

TEST_F(Repository, EveryLinkToAMarkdownSectionNamesAHeading) {
    // A page's path, '#' and an anchor: in a Markdown page the path is relative
    // to the page (or, as in `docs/spec.md#43-metal` quoted in prose, to the
    // root); in code comments relative to the root. "](#anchor)" alone: a
    // heading of the same page.
    const std::regex link(R"(([\w./-]*\w\.md)#([\w-]+))");
    const std::regex same_page(R"(\]\(#([\w-]+)\))");
    std::vector<std::string> broken;
    std::size_t checked = 0;
    auto check = [&](const std::string& file, const std::string& target, const std::string& anchor,
                     const std::string& as_written) {
        ++checked;
        if (!anchors_of(read(target)).count(anchor))
            broken.push_back(file + ": " + as_written + " (no heading #" + anchor + " in " + target + ")");
    };
    for (const std::string& file : files_) {
        const bool markdown = fs::path(file).extension() == ".md";
        const std::string text = read(file);
        if (markdown)
            for (auto it = std::sregex_iterator(text.begin(), text.end(), same_page); it != std::sregex_iterator(); ++it)
                check(file, file, (*it)[1].str(), it->str());
        if (text.find(".md#") == std::string::npos) continue;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), link); it != std::sregex_iterator(); ++it) {
            const std::string written = (*it)[1].str();
            std::string target = fs::path(written).lexically_normal().string();
            if (markdown) {
                const std::string beside = (fs::path(file).parent_path() / written).lexically_normal().string();
                if (fs::is_regular_file(test::source_path(beside)) || !fs::is_regular_file(test::source_path(target)))
                    target = beside;
            }
            if (!fs::is_regular_file(test::source_path(target))) {
                ++checked;
                broken.push_back(file + ": " + it->str() + " (no file " + target + ")");
            } else {
                check(file, target, (*it)[2].str(), it->str());
            }
        }
    }
    std::string list;
    for (const std::string& b : broken) list += "\n  " + b;
    EXPECT_TRUE(broken.empty()) << list;
    EXPECT_GT(checked, 10u) << "expected the README and docs to link sections of docs/spec.md";
}

}  // namespace
}  // namespace m3055
