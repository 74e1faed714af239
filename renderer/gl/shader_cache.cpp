#include "gl/shader_cache.h"

#include "io/message_text.h"

#include <pwd.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

namespace m3055 {
namespace {

std::string env(const char* name) {
    const char* value = std::getenv(name);
    return value ? value : "";
}

// Mesa's debug_get_bool_option: unset, "", "0", "n", "no", "f", "false" are false.
bool env_true(const char* name) {
    const std::string value = env(name);
    return !(value.empty() || value == "0" || value == "n" || value == "no" || value == "f" || value == "false" ||
             value == "N" || value == "NO" || value == "F" || value == "FALSE");
}

std::string home_folder() {
    const std::string home = env("HOME");
    if (!home.empty()) return home;
    const passwd* entry = ::getpwuid(::getuid());
    return entry && entry->pw_dir ? entry->pw_dir : "";
}

std::string mebibytes(std::uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// What is wrong with writing into `folder` (created by Mesa when missing), or "".
std::string folder_problem(std::string folder) {
    // The nearest folder that exists: Mesa creates the rest there.
    struct stat info {};
    while (::stat(folder.c_str(), &info) != 0) {
        const std::size_t slash = folder.find_last_of('/');
        if (slash == std::string::npos || slash == 0) {
            folder = slash == 0 ? "/" : ".";
            if (::stat(folder.c_str(), &info) != 0) return std::string("cannot be found: ") + std::strerror(errno);
            break;
        }
        folder.resize(slash);
    }
    if (!S_ISDIR(info.st_mode)) return text::quote_name(folder) + " is not a folder";
    if (::access(folder.c_str(), W_OK | X_OK) != 0) return std::string("is not writable: ") + std::strerror(errno);
    struct statvfs space {};
    if (::statvfs(folder.c_str(), &space) != 0) return std::string("cannot be checked: ") + std::strerror(errno);
    const std::uint64_t free_bytes = std::uint64_t(space.f_bavail) * space.f_frsize;
    if (free_bytes < kMinShaderCacheFreeBytes)
        return "has " + mebibytes(free_bytes) + " free, less than " + mebibytes(kMinShaderCacheFreeBytes);
    if (space.f_files != 0 && space.f_favail == 0) return "has no free inode";
    return "";
}

}  // namespace

std::string mesa_shader_cache_folder() {
    if (env_true("MESA_SHADER_CACHE_DISABLE") || env_true("MESA_GLSL_CACHE_DISABLE")) return "";
    std::string base = env("MESA_SHADER_CACHE_DIR");
    if (base.empty()) base = env("MESA_GLSL_CACHE_DIR");
    if (base.empty()) base = env("XDG_CACHE_HOME");
    if (base.empty()) {
        const std::string home = home_folder();
        if (home.empty()) return "";
        base = home + "/.cache";
    }
    return base + "/mesa_shader_cache";
}

void keep_shader_cache_in(const std::string& folder) {
    ::setenv("MESA_SHADER_CACHE_DIR", folder.c_str(), 1);
    ::setenv("MESA_GLSL_CACHE_DIR", folder.c_str(), 1);  // the older name, for older Mesa
}

void switch_shader_cache_off() {
    ::setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    ::setenv("MESA_GLSL_CACHE_DISABLE", "true", 1);
}

std::string disable_shader_cache_if_unusable() {
    const std::string folder = mesa_shader_cache_folder();
    if (folder.empty()) return "";
    const std::string problem = folder_problem(folder);
    if (problem.empty()) return "";
    // Read by Mesa when the first context is made; both names, old and new.
    switch_shader_cache_off();
    return "note: the Mesa shader cache " + text::quote_name(folder) + " " + problem +
           ": shaders are compiled without it this run";
}

}  // namespace m3055
