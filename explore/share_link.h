// A scene in a link: the compact scene JSON, deflated (zlib) and written in
// base64url (RFC 4648 §5, no padding), for the page's `#scene=` fragment
// (docs/web.md). A scene whose materials come from .brdf files travels with
// them, and one with a mesh from a model file with that file and the files it
// names (.mtl, .bin): the deflated JSON is then a bundle,
//   {"m3055_share": 1, "scene": SCENE, "brdf_files": {"NAME.brdf": TEXT, ...},
//    "model_files": {"NAME": BASE64URL, ...}},
// SCENE naming each file by the bundle's NAME; the same limits hold. Nothing here knows about
// browsers, so it is tested natively.
#pragma once

#include "scene/scene.h"

#include <cstddef>
#include <string>
#include <vector>

namespace m3055::explore {

// The largest scene (with its .brdf files) a link may unpack to (a hostile
// link must not fill memory).
inline constexpr std::size_t kMaxSharedSceneBytes = std::size_t(4) << 20;
// The longest token share_token makes: Chromium opens URLs up to 2 MB
// (url/url_constants.cc kMaxURLChars), the page's address and "#scene=" included.
inline constexpr std::size_t kMaxShareTokenChars = 2000000 - 4096;

// The token of `scene`: base64url(zlib(text)), the text the compact scene
// JSON, or the bundle when a material is a .brdf file: each named by its path
// relative to `folder` (PathWriting, scene/load_context.h; the page's work
// folder) and read from there. Throws std::runtime_error with one line
// ("share link: ...") when a .brdf file is outside `folder` or unreadable, or
// the token would be longer than kMaxShareTokenChars.
std::string share_token(const Scene& scene, const std::string& folder = "");

struct SharedFile {
    std::string name;  // relative, "/"-separated, no ".." (a .brdf, or a model file or one it names)
    std::string text;  // its bytes
};
struct SharedScene {
    std::string scene_text;  // loaded like any scene file, from the folder holding the files
    std::vector<SharedFile> files;
};

// What a token holds. Throws std::runtime_error with one line ("share link:
// ...") when it is not base64url, not zlib data, unpacks to more than
// kMaxSharedSceneBytes, or is a bundle with a malformed part or a file name
// that is not a plain relative NAME.brdf (a link must not write elsewhere).
SharedScene unpack_share_token(const std::string& token);

std::string base64url_encode(const std::string& bytes);
std::string base64url_decode(const std::string& text);  // throws on a character outside the alphabet
// Standard base64 with padding, for data: URLs.
std::string base64_encode(const std::string& bytes);

}  // namespace m3055::explore
