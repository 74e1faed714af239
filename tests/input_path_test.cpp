// io/input_path.h: a file opened inside a folder and named relative to it,
// and read_input_file naming it so in every message.
#include "io/input_file.h"
#include "io/input_path.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <string>

namespace m3055 {
namespace {

using io::InputPath;

TEST(InputPath, ARelativeNameIsOpenedInTheFolder) {
    const InputPath in = InputPath::in_folder("class", "alice/scene.json");
    EXPECT_EQ(in.path, "class/alice/scene.json");
    EXPECT_EQ(in.shown, "alice/scene.json");
    const InputPath absolute = InputPath::in_folder("class", "/tmp/scene.json");
    EXPECT_EQ(absolute.path, "/tmp/scene.json");
    const InputPath here = InputPath::in_folder("", "scene.json");
    EXPECT_EQ(here.path, "scene.json");
    EXPECT_EQ(InputPath::in_folder("class", "").path, "") << "an empty name stays empty: the read says so";
}

TEST(InputPath, ReadsNameTheShownPath) {
    test::TempDir dir;
    test::write_text(dir.file("scene.json"), "{}");
    EXPECT_EQ(io::read_input_file(InputPath::in_folder(dir.path(), "scene.json")), "{}");
    try {
        io::read_input_file(InputPath::in_folder(dir.path(), "missing.json"));
        FAIL() << "a missing file was read";
    } catch (const io::InputError& e) {
        EXPECT_EQ(std::string(e.what()), "missing.json: cannot read file: No such file or directory");
    }
    try {
        io::read_input_file(InputPath::in_folder(dir.path(), ""));
        FAIL() << "an empty name was read";
    } catch (const io::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("the name is empty"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace m3055
