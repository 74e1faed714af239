#include "fuzz_corpus.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>

namespace m3055::test {

namespace fs = std::filesystem;

std::vector<fs::path> corpus_files(const std::string& folder, const std::string& extension) {
    std::vector<fs::path> files;
    if (!fs::is_directory(folder)) return files;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file() && (extension.empty() || entry.path().extension() == extension))
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::string file_bytes(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

int expect_property_holds(const std::vector<std::string>& folders,
                          const std::function<std::string(const std::string& bytes)>& check) {
    int checked = 0;
    for (const std::string& folder : folders)
        for (const fs::path& path : corpus_files(source_path(folder))) {
            EXPECT_EQ(check(file_bytes(path)), "") << path;
            ++checked;
        }
    return checked;
}

}  // namespace m3055::test
