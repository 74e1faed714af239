// write_file_atomic: temporary file in the target's own folder, then rename().
// rename() within one filesystem is atomic, which is why the temporary file
// must live beside the target and not in /tmp.
#include "image/image.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace m3055 {
namespace {

std::string folder_of(const std::string& path) {
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    if (slash == 0) return "/";
    return path.substr(0, slash);
}

std::string name_of(const std::string& path) {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

[[noreturn]] void fail(const std::string& path, const char* what, int error) {
    throw ImageError(path + ": " + what + ": " + std::strerror(error));
}

// TEST-ONLY fault injection (tests/output_failures_test.cpp, docs/limits.md):
// with M3055_FAULT_WRITE_AFTER_BYTES=N in the environment, writing a file fails
// with ENOSPC after its first N bytes, as on a full disk, so the disk-full path
// is tested even where a small tmpfs cannot be mounted. Unset: no limit.
std::size_t fault_write_limit() {
    const char* text = std::getenv("M3055_FAULT_WRITE_AFTER_BYTES");
    if (!text || !*text) return SIZE_MAX;
    char* end = nullptr;
    const unsigned long long limit = std::strtoull(text, &end, 10);
    return *end == '\0' ? std::size_t(limit) : SIZE_MAX;
}

// Writes everything, retrying short writes and EINTR. Returns 0 or an errno.
int write_all(int fd, const void* bytes, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(bytes);
    std::size_t budget = fault_write_limit();
    while (size > 0) {
        if (budget == 0) return ENOSPC;  // the test-only limit above
        const ssize_t n = ::write(fd, p, std::min(size, budget));
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        if (n == 0) return EIO;  // should not happen for regular files; avoid looping forever
        p += n;
        size -= std::size_t(n);
        if (budget != SIZE_MAX) budget -= std::size_t(n);
    }
    return 0;
}

}  // namespace

// Writes `bytes` to a new temporary file beside `path` and returns its name;
// the target itself is not touched.
static std::string write_temporary(const std::string& path, const void* bytes, std::size_t size) {
    if (path.empty() || path.back() == '/') fail(path, "not a file name", EISDIR);
    std::string temp = folder_of(path) + "/." + name_of(path) + ".tmp-XXXXXX";
    const int fd = ::mkstemp(temp.data());
    if (fd < 0) fail(path, "cannot create temporary file", errno);

    // From here on, any failure removes the temporary file; the target is only
    // touched by the final rename().
    auto abandon = [&](const char* what, int error) {
        ::close(fd);
        ::unlink(temp.c_str());
        fail(path, what, error);
    };
    // mkstemp creates 0600; output images are ordinary files everyone may read.
    if (::fchmod(fd, 0644) != 0) abandon("cannot set file mode", errno);
    if (const int error = write_all(fd, bytes, size)) abandon("cannot write", error);
    if (::fsync(fd) != 0) abandon("cannot sync", errno);
    if (::close(fd) != 0) {
        const int error = errno;
        ::unlink(temp.c_str());
        fail(path, "cannot close", error);
    }
    return temp;
}

// Renames the temporary file over the target (atomic within one filesystem).
static void commit_temporary(const std::string& temp, const std::string& path) {
    if (::rename(temp.c_str(), path.c_str()) != 0) {
        const int error = errno;
        ::unlink(temp.c_str());
        fail(path, "cannot rename temporary file over target", error);
    }
}

void write_file_atomic(const std::string& path, const void* bytes, std::size_t size) {
    commit_temporary(write_temporary(path, bytes, size), path);
}

void write_files_atomic(const std::vector<FileContents>& files) {
    // Every file is written and synced before any is renamed, so a failure
    // while writing (a missing folder, a full disk) replaces none of them.
    std::vector<std::string> temps;
    try {
        for (const auto& file : files) temps.push_back(write_temporary(file.path, file.bytes.data(), file.bytes.size()));
    } catch (...) {
        for (const auto& temp : temps) ::unlink(temp.c_str());
        throw;
    }
    for (std::size_t i = 0; i < files.size(); ++i) {
        try {
            commit_temporary(temps[i], files[i].path);
        } catch (...) {
            for (std::size_t j = i + 1; j < files.size(); ++j) ::unlink(temps[j].c_str());
            throw;
        }
    }
}

}  // namespace m3055
