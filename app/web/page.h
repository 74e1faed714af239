// The explorer in a browser page: the one ExplorerSession of the page, and
// the platform pieces a page has instead of a desktop's (downloads, the file
// chooser, the share link). page_api.cpp exports the functions page.js calls.
#pragma once

#include "explore_ui/explore.h"

#include <memory>
#include <string>

namespace m3055::web {

// The page's explorer (null until main() has opened it, or when that failed).
ExplorerSession* session();
void set_session(std::unique_ptr<ExplorerSession> session);

// The folder (in the page's memory file system) where scenes, .brdf files and
// screenshots live, and relative names resolve: page.js writes picked,
// dropped and test files here.
inline constexpr const char* kWorkFolder = "/work";

}  // namespace m3055::web
