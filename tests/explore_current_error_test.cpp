// The page's one error line (explore/current_error.h): the newest of the
// explorer's error messages, cleared with it, never an older one that is gone.
#include "explore/current_error.h"

#include <gtest/gtest.h>

namespace m3055::explore {
namespace {

TEST(CurrentError, TheNewestMessageOfAnyKindIsTheCurrentOne) {
    Messages messages;
    CurrentError current;
    EXPECT_FALSE(current.update(messages));
    EXPECT_EQ(current.text(), "");
    messages.brdf_error = "mine.brdf:8: error: 'x' : undeclared identifier";
    EXPECT_TRUE(current.update(messages));
    EXPECT_EQ(current.text(), messages.brdf_error);
    messages.error = "m3055: cannot read scene.json";  // newer: it replaces the .brdf's
    EXPECT_TRUE(current.update(messages));
    EXPECT_EQ(current.text(), messages.error);
    EXPECT_FALSE(current.update(messages)) << "nothing changed";
}

TEST(CurrentError, ClearedItGivesWayToOneStillStandingOrToNone) {
    Messages messages;
    CurrentError current;
    messages.brdf_error = "mine.brdf:8: error";
    current.update(messages);
    messages.error = "render failed";
    current.update(messages);
    messages.error.clear();  // dismissed, or a later success cleared it
    EXPECT_TRUE(current.update(messages));
    EXPECT_EQ(current.text(), "mine.brdf:8: error") << "the .brdf file is still broken";
    messages.brdf_error.clear();
    EXPECT_TRUE(current.update(messages));
    EXPECT_EQ(current.text(), "");
}

TEST(CurrentError, ALoadFailureSetsTwoMessagesAndIsOneError) {
    Messages messages;
    CurrentError current;
    messages.error = messages.load_error = "scene.json: display.bits: must be in [1, 8], got 9";
    EXPECT_TRUE(current.update(messages));
    EXPECT_EQ(current.text(), messages.error);
    messages.error.clear();  // the Load field keeps its own message
    EXPECT_FALSE(current.update(messages));
    EXPECT_EQ(current.text(), messages.load_error);
}

}  // namespace
}  // namespace m3055::explore
