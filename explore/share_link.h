// A scene in a link: the compact scene JSON, deflated (zlib) and written in
// base64url (RFC 4648 §5, no padding), for the page's `#scene=` fragment
// (docs/web.md). Nothing here knows about browsers, so it is tested natively.
#pragma once

#include "scene/scene.h"

#include <cstddef>
#include <string>

namespace m3055::explore {

// The largest scene a link may unpack to (a hostile link must not fill memory).
inline constexpr std::size_t kMaxSharedSceneBytes = std::size_t(4) << 20;

// The token of `scene`: base64url(zlib(scene_to_json(scene).dump())).
std::string share_token(const Scene& scene);

// The scene JSON text a token holds. Throws std::runtime_error with one line
// ("share link: ...") when it is not base64url, not zlib data, or unpacks to
// more than kMaxSharedSceneBytes. The text is then loaded like any scene file.
std::string scene_text_from_share_token(const std::string& token);

std::string base64url_encode(const std::string& bytes);
std::string base64url_decode(const std::string& text);  // throws on a character outside the alphabet
// Standard base64 with padding, for data: URLs.
std::string base64_encode(const std::string& bytes);

}  // namespace m3055::explore
