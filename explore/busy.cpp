#include "explore/busy.h"

namespace m3055::explore {

namespace {
std::string file_name_of(const std::string& path) {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}
}  // namespace

std::string busy_line(const BrdfWatch& watch, std::size_t deferred, bool refining) {
    if (!watch.reload_pending.empty()) {
        std::string files;
        for (const std::string& path : watch.reload_pending) files += (files.empty() ? "" : ", ") + file_name_of(path);
        return "reloading " + files + "...";
    }
    if (refining) return "refining...";
    if (deferred > 0) return "compiling...";
    return "";
}

}  // namespace m3055::explore
