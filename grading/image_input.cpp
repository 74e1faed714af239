#include "grading/image_input.h"

#include "io/input_file.h"
#include "io/message_text.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

namespace m3055::grading {

namespace {

bool ends_with_nocase(const std::string& text, const std::string& end) {
    if (text.size() < end.size()) return false;
    return std::equal(end.begin(), end.end(), text.end() - std::ptrdiff_t(end.size()),
                      [](char a, char b) { return std::tolower((unsigned char)a) == std::tolower((unsigned char)b); });
}

void require_regular_file(const io::InputPath& file) {
    struct stat info {};
    if (::stat(file.path.c_str(), &info) != 0)
        throw io::InputError(text::quote_name(file.shown) + ": cannot read: " + std::strerror(errno));
    if (!S_ISREG(info.st_mode))
        throw io::InputError(text::quote_name(file.shown) + ": cannot read: it is " +
                             io::describe_file_type(info.st_mode) + ", not a regular file");
}

}  // namespace

InputKind input_kind(const std::string& path) {
    if (ends_with_nocase(path, ".png")) return InputKind::png;
    if (ends_with_nocase(path, ".pfm")) return InputKind::pfm;
    return InputKind::scene;
}

LevelImage read_level_image(const std::string& path, int bits) {
    return read_level_image(io::InputPath::as_given(path), bits);
}

LevelImage read_level_image(const io::InputPath& file, int bits) {
    require_regular_file(file);
    if (input_kind(file.shown) == InputKind::pfm) return levels_from_pfm(read_pfm(file), bits);
    return levels_from_png(read_png(file), bits);
}

LevelImage render_levels(Renderer& renderer, const Scene& scene, bool linear) {
    renderer.render(scene);
    if (!linear) return levels_from_png(renderer.read_display(), scene.display.bits);
    return levels_from_render(renderer.read_display(), renderer.read_raw(), scene.display.bits);
}

}  // namespace m3055::grading
