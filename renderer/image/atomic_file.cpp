// write_file_atomic: temporary file in the target's own folder, then rename().
// rename() within one filesystem is atomic, which is why the temporary file
// must live beside the target and not in /tmp.
//
// The folder is opened once and every step names files relative to it
// (openat, renameat, unlinkat), so a target whose full path is near PATH_MAX
// works, and the temporary's name is cut to fit NAME_MAX beside a long target
// name. Every temporary is registered (image/temporary_files.h) so that an
// interrupt removes it; the target is only ever replaced if it is a regular
// file or does not exist (a FIFO, a device, a folder or a symbolic link is an
// error, checked again just before the rename).
#include "image/image.h"
#include "image/temporary_files.h"
#include "io/input_file.h"
#include "io/message_text.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <random>
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

[[noreturn]] void fail(const std::string& path, const std::string& what, int error) {
    throw ImageError(text::quote_name(path) + ": " + what + (error ? std::string(": ") + std::strerror(error) : ""));
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

// TEST-ONLY (tests/untrusted_signals_test.cpp): with M3055_FAULT_WRITE_PAUSE_MS=N,
// every group of files waits N ms once its temporaries are written, before
// they are renamed into place, so a test can interrupt a run exactly while
// temporaries exist. Unset: no pause.
void fault_pause_before_commit() {
    const char* text = std::getenv("M3055_FAULT_WRITE_PAUSE_MS");
    if (!text || !*text) return;
    const long ms = std::strtol(text, nullptr, 10);
    if (ms > 0) ::usleep(useconds_t(std::min(ms, 600000L)) * 1000);
}

// Writes everything, retrying short writes and EINTR. Returns 0 or an errno;
// `budget` is what the test-only limit above still allows.
int write_all(int fd, const void* bytes, std::size_t size, std::size_t& budget) {
    const auto* p = static_cast<const unsigned char*>(bytes);
    while (size > 0) {
        if (budget == 0) return ENOSPC;  // the test-only limit above
        // At most 64 MiB a call: the kernel caps one write() near 2 GiB anyway.
        const ssize_t n = ::write(fd, p, std::min({size, budget, std::size_t(64) << 20}));
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

// ".NAME.tmp-XXXXXX", NAME's end cut (at a character boundary) so that the
// whole fits in `name_max` bytes: a 254-byte target name is legal, and so must
// be its temporary.
std::string temporary_name(const std::string& name, std::size_t name_max, std::mt19937_64& random) {
    static const char kLetters[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    std::string suffix = ".tmp-";
    for (int i = 0; i < 6; ++i) suffix += kLetters[random() % (sizeof kLetters - 1)];
    std::size_t keep = std::min(name.size(), name_max - 1 - suffix.size());
    while (keep > 0 && keep < name.size() && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80) --keep;
    return "." + name.substr(0, keep) + suffix;
}

// One temporary file beside its target, open for writing and registered.
struct Temporary {
    std::string path;  // the target, as given (for messages)
    std::string name;  // the target's name in its folder
    std::string temp;  // the temporary's name in the same folder
    int folder = -1;   // the folder, open
    int fd = -1;       // the temporary, open until written
    int slot = -1;     // its entry in temporary_files

    // Removes the temporary (if still there) and releases everything.
    void abandon() {
        std::lock_guard<std::mutex> hold(temporary_files::lock());
        if (fd >= 0) ::close(fd);
        if (slot >= 0) {
            ::unlinkat(folder, temp.c_str(), 0);
            temporary_files::forget(slot);
        }
        if (folder >= 0) ::close(folder);
        fd = folder = slot = -1;
    }
};

// Creates the temporary beside `path`; the target itself is not touched.
Temporary create_temporary(const std::string& path) {
    Temporary t;
    t.path = path;
    t.name = name_of(path);
    if (t.name.empty() || t.name == "." || t.name == "..") fail(path, "not a file name", EISDIR);
    t.folder = ::open(folder_of(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    // Said as what it is (and as the command line's check says it): a missing
    // folder is the usual mistake, and "cannot create temporary file" hid it.
    if (t.folder < 0) fail(path, "cannot write into its folder", errno);
    const long name_max = ::fpathconf(t.folder, _PC_NAME_MAX);
    std::random_device seed;
    std::mt19937_64 random((std::uint64_t(seed()) << 32) ^ seed());
    int error = EEXIST;
    for (int attempt = 0; attempt < 100 && error == EEXIST; ++attempt) {
        t.temp = temporary_name(t.name, name_max > 16 ? std::size_t(name_max) : 255, random);
        // Created and registered under the lock, so an interrupt cannot come between.
        std::lock_guard<std::mutex> hold(temporary_files::lock());
        t.fd = ::openat(t.folder, t.temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (t.fd >= 0) {
            try {
                t.slot = temporary_files::add(t.folder, t.temp.c_str());
            } catch (const std::exception& e) {
                ::close(t.fd);
                ::unlinkat(t.folder, t.temp.c_str(), 0);
                ::close(t.folder);
                fail(path, std::string("cannot create temporary file: ") + e.what(), 0);
            }
            return t;
        }
        error = errno;
    }
    ::close(t.folder);
    fail(path, "cannot create temporary file", error);
}

// Writes and syncs the temporary; on failure removes it and throws.
void fill_temporary(Temporary& t, const void* bytes, std::size_t size, const void* more, std::size_t more_size) {
    std::size_t budget = fault_write_limit();
    int error = 0;
    const char* what = "cannot write";
    // Output images are ordinary files everyone may read (the temporary was made 0600).
    if (::fchmod(t.fd, 0644) != 0) error = errno, what = "cannot set file mode";
    if (!error) error = write_all(t.fd, bytes, size, budget);
    if (!error && more_size) error = write_all(t.fd, more, more_size, budget);
    if (!error && ::fsync(t.fd) != 0) error = errno, what = "cannot sync";
    if (!error && ::close(t.fd) != 0) error = errno, what = "cannot close";
    else if (error) ::close(t.fd);
    t.fd = -1;
    if (error) {
        t.abandon();
        fail(t.path, what, error);
    }
}

// "" when the target is a regular file or absent, else why it may not be replaced.
std::string target_problem(const Temporary& t) {
    struct stat info {};
    if (::fstatat(t.folder, t.name.c_str(), &info, AT_SYMLINK_NOFOLLOW) != 0)
        return errno == ENOENT ? "" : std::string("cannot write: ") + std::strerror(errno);
    if (S_ISREG(info.st_mode)) return "";
    return std::string("cannot write: it is ") + io::describe_file_type(info.st_mode) +
           ", not a regular file (outputs go only to regular files or new names)";
}

// Renames every temporary over its target, under the lock: all or, should a
// target turn out not to be a regular file, none. `committed` runs under the
// same lock once all are in place.
void commit(std::vector<Temporary>& temps, const std::function<void()>& committed) {
    fault_pause_before_commit();
    std::unique_lock<std::mutex> hold(temporary_files::lock());
    for (const Temporary& t : temps) {
        const std::string problem = target_problem(t);
        if (problem.empty()) continue;
        hold.unlock();
        for (Temporary& each : temps) each.abandon();
        throw ImageError(text::quote_name(t.path) + ": " + problem);
    }
    for (std::size_t i = 0; i < temps.size(); ++i) {
        Temporary& t = temps[i];
        if (::renameat(t.folder, t.temp.c_str(), t.folder, t.name.c_str()) != 0) {
            const int error = errno;
            hold.unlock();
            for (Temporary& each : temps) each.abandon();  // those renamed already stay
            fail(t.path, "cannot rename temporary file over target", error);
        }
        temporary_files::forget(t.slot);
        t.slot = -1;
    }
    if (committed) committed();
    hold.unlock();
    for (Temporary& t : temps) t.abandon();  // closes the folders
}

}  // namespace

void write_file_atomic(const std::string& path, const void* bytes, std::size_t size) {
    std::vector<Temporary> temps;
    temps.push_back(create_temporary(path));
    fill_temporary(temps.back(), bytes, size, nullptr, 0);
    commit(temps, {});
}

void write_files_atomic(const std::vector<FileContents>& files, const std::function<void()>& committed) {
    // Every file is written and synced before any is renamed, so a failure
    // while writing (a missing folder, a full disk) replaces none of them.
    std::vector<Temporary> temps;
    try {
        for (const auto& file : files) {
            temps.push_back(create_temporary(file.path));
            fill_temporary(temps.back(), file.bytes.data(), file.bytes.size(), file.more, file.more_size);
        }
    } catch (...) {
        for (Temporary& t : temps) t.abandon();
        throw;
    }
    commit(temps, committed);
}

}  // namespace m3055
