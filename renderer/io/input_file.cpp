#include "io/input_file.h"

#include "io/message_text.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace m3055::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
    throw InputError(text::quote_name(path) + ": " + problem);
}

std::string mebibytes(std::size_t bytes) {
    return bytes % (1 << 20) == 0 ? std::to_string(bytes >> 20) + " MiB" : std::to_string(bytes) + " bytes";
}

void check_size(const std::string& path, std::size_t size, std::size_t max_bytes) {
    if (size > max_bytes)
        fail(path, "too large: " + std::to_string(size) + " bytes, more than the " + mebibytes(max_bytes) +
                       " an input file may have");
}

// Closes the descriptor on every path out.
struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

const char* describe_file_type(unsigned mode) {
    switch (mode & S_IFMT) {
        case S_IFREG: return "a regular file";
        case S_IFDIR: return "a folder";
        case S_IFIFO: return "a FIFO";
        case S_IFCHR: return "a character device";
        case S_IFBLK: return "a block device";
        case S_IFSOCK: return "a socket";
        case S_IFLNK: return "a symbolic link";
        default: return "not a regular file";
    }
}

std::string read_input_file(const InputPath& file_name, std::size_t max_bytes) {
    const std::string& path = file_name.path;
    const std::string& shown = file_name.shown;
    if (shown.empty()) fail(shown, "cannot read file: the name is empty");
    if (path.find('\0') != std::string::npos) fail(shown, "cannot read file: the name holds a NUL character");
    struct stat named {};
    if (::stat(path.c_str(), &named) != 0) fail(shown, std::string("cannot read file: ") + std::strerror(errno));
    if (!S_ISREG(named.st_mode))
        fail(shown, std::string("cannot read file: it is ") + describe_file_type(named.st_mode) + ", not a regular file");
    check_size(shown, std::size_t(named.st_size), max_bytes);

    // O_NONBLOCK: should the name have been swapped for a FIFO since stat(),
    // open() still returns at once; fstat() then tells.
    const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
    if (file.fd < 0) fail(shown, std::string("cannot read file: ") + std::strerror(errno));
    struct stat opened {};
    if (::fstat(file.fd, &opened) != 0) fail(shown, std::string("cannot read file: ") + std::strerror(errno));
    if (!S_ISREG(opened.st_mode))
        fail(shown, std::string("cannot read file: it is ") + describe_file_type(opened.st_mode) + ", not a regular file");
    check_size(shown, std::size_t(opened.st_size), max_bytes);

    // Sized from fstat, read to the end (or one byte past the limit, for files
    // such as those in /proc that report size 0 or grow while being read).
    std::string text;
    text.reserve(std::size_t(opened.st_size));
    char buffer[65536];
    for (;;) {
        const ssize_t got = ::read(file.fd, buffer, sizeof buffer);
        if (got < 0) {
            if (errno == EINTR) continue;
            fail(shown, std::string("cannot read file: ") + std::strerror(errno));
        }
        if (got == 0) break;
        text.append(buffer, std::size_t(got));
        check_size(shown, text.size(), max_bytes);
    }
    return text;
}

std::string read_input_file(const std::string& path, std::size_t max_bytes) {
    return read_input_file(InputPath::as_given(path), max_bytes);
}

}  // namespace m3055::io
