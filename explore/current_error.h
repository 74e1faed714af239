// The explorer's one current error, for a platform that shows errors in one
// place (the web page's bar, app/web/): the newest of its error messages (a
// failed load's, a .brdf file's, any other), or the one still standing once
// that is cleared, or "" when none is left.
#pragma once

#include "explore/session.h"

#include <string>

namespace m3055::explore {

class CurrentError {
public:
    // Notes the messages as they are now; true when the current error changed.
    bool update(const Messages& messages);
    const std::string& text() const { return current_; }

private:
    std::string seen_[3];  // error, load_error, brdf_error at the last update
    std::string current_;
};

}  // namespace m3055::explore
