// The fuzzers' seeds and the inputs they once failed on, as the tests re-check
// them in every build: each file of some folders of the source tree, through
// the fuzzer's own property (a function of the bytes: "" when it holds).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace m3055::test {

// Every regular file under `folder` (recursively; those ending in `extension`
// when one is given), sorted; none when the folder does not exist.
std::vector<std::filesystem::path> corpus_files(const std::string& folder, const std::string& extension = "");

// The file's bytes.
std::string file_bytes(const std::filesystem::path& path);

// `check` on every file of corpus_files(source_path(folder)) for each of
// `folders`, each failure a GoogleTest failure naming its file; how many were checked.
int expect_property_holds(const std::vector<std::string>& folders,
                          const std::function<std::string(const std::string& bytes)>& check);

}  // namespace m3055::test
