// Reading an untrusted input file (a scene, a manifest) safely: whatever the
// path names, the read neither blocks nor runs on without end.
#pragma once

#include "io/input_path.h"

#include <cstddef>
#include <stdexcept>
#include <string>

namespace m3055::io {

// The largest scene file or manifest accepted (docs/limits.md). The largest
// scene in scenes/ is a few kB and 100 000 spheres take about 12 MB.
inline constexpr std::size_t kMaxInputBytes = std::size_t(16) << 20;

// what(): "NAME: problem", NAME as text::quote_name shows it.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The whole content of the file at `path`, which must be a regular file after
// following symbolic links: a FIFO, a device (/dev/zero, /dev/tty), a socket or
// a folder is refused by its type before it is opened (opening a device can
// have effects of its own), and the file is opened with O_NONBLOCK, so nothing
// waits for a writer. A file larger than `max_bytes` is refused from its size
// before anything is read, and the read stops there should it grow meanwhile.
// Throws InputError naming the file and the reason.
std::string read_input_file(const std::string& path, std::size_t max_bytes = kMaxInputBytes);
// The same for a file opened at `file.path`, every message naming `file.shown`.
std::string read_input_file(const InputPath& file, std::size_t max_bytes = kMaxInputBytes);

// "a FIFO", "a character device", "a folder", ... for a stat mode.
const char* describe_file_type(unsigned mode);

}  // namespace m3055::io
