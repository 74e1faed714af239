// The page's share link (explore/share_link.h): every figure preset survives
// the round trip exactly, and a damaged or hostile link is one clear error.
#include "explore/figure_scenes.h"
#include "explore/share_link.h"
#include "scene/load.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <zlib.h>

#include <vector>

namespace m3055::explore {
namespace {

TEST(ShareLink, Base64MatchesRfc4648TestVectors) {
    EXPECT_EQ(base64_encode(""), "");
    EXPECT_EQ(base64_encode("f"), "Zg==");
    EXPECT_EQ(base64_encode("fo"), "Zm8=");
    EXPECT_EQ(base64_encode("foo"), "Zm9v");
    EXPECT_EQ(base64_encode("foobar"), "Zm9vYmFy");
    EXPECT_EQ(base64url_encode("fo"), "Zm8");  // no padding in links
    EXPECT_EQ(base64url_encode("\xfb\xff"), "-_8");
    EXPECT_EQ(base64url_decode("-_8"), "\xfb\xff");
    EXPECT_EQ(base64url_decode("Zm9vYmFy"), "foobar");
}

TEST(ShareLink, EveryFigurePresetComesBackAsTheSameScene) {
    for (const FigureScene& figure : figure_scenes()) {
        SCOPED_TRACE(figure.name);
        const Scene scene = scene_from_json(nlohmann::json::parse(figure.json), figure.name);
        const std::string token = share_token(scene);
        EXPECT_EQ(token.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_"),
                  std::string::npos);
        const Scene back = scene_from_json(nlohmann::json::parse(scene_text_from_share_token(token)), "link");
        EXPECT_EQ(scene_to_json(back), scene_to_json(scene));
    }
}

TEST(ShareLink, ADamagedLinkIsOneClearError) {
    const std::string token = share_token(scene_from_json(nlohmann::json::parse(figure_scenes().front().json), "x"));
    EXPECT_THROW(scene_text_from_share_token(token.substr(0, token.size() / 2)), std::runtime_error);
    EXPECT_THROW(scene_text_from_share_token("abc$def"), std::runtime_error);
    EXPECT_THROW(scene_text_from_share_token("bm90IHpsaWI"), std::runtime_error);  // "not zlib"
    try {
        scene_text_from_share_token("abc$def");
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("share link: ", 0), 0u) << e.what();
    }
}

TEST(ShareLink, ALinkThatUnpacksPastTheLimitIsRefused) {
    const std::string zeros(kMaxSharedSceneBytes + 1, ' ');
    uLongf size = compressBound(uLong(zeros.size()));
    std::vector<Bytef> packed(size);
    ASSERT_EQ(compress2(packed.data(), &size, reinterpret_cast<const Bytef*>(zeros.data()), uLong(zeros.size()), 9), Z_OK);
    const std::string token = base64url_encode(std::string(reinterpret_cast<const char*>(packed.data()), size));
    EXPECT_LT(token.size(), 20000u);  // a short link ...
    EXPECT_THROW(scene_text_from_share_token(token), std::runtime_error);  // ... refused, not unpacked
}

}  // namespace
}  // namespace m3055::explore
