#include "explore/current_error.h"

namespace m3055::explore {

bool CurrentError::update(const Messages& messages) {
    const std::string* now[3] = {&messages.error, &messages.load_error, &messages.brdf_error};
    std::string next = current_;
    bool still_standing = false;
    const std::string* newest = nullptr;
    for (int i = 0; i < 3; ++i) {
        if (*now[i] != seen_[i] && !now[i]->empty() && !newest) newest = now[i];
        seen_[i] = *now[i];
        still_standing |= !current_.empty() && *now[i] == current_;
    }
    if (newest) {
        next = *newest;
    } else if (!still_standing) {
        next.clear();
        for (const std::string* message : now)
            if (!message->empty()) {
                next = *message;
                break;
            }
    }
    const bool changed = next != current_;
    current_ = std::move(next);
    return changed;
}

}  // namespace m3055::explore
