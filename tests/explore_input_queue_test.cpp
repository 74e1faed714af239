// The input queue (explore/input_queue.h): a burst of presses and releases
// reaches Dear ImGui one transition per key or button per frame, characters
// and clicks stay in order with the keys around them, and nothing is dropped.
#include "explore/input_queue.h"

#include <gtest/gtest.h>

#include <deque>
#include <string>
#include <vector>

namespace m3055::explore {
namespace {

constexpr int kBackspace = 259, kShift = 340, kA = 65, kCtrl = 341;
constexpr int kLeftButton = 0;

InputEvent key(int code, bool down) {
    InputEvent e;
    e.key = code;
    e.action = down ? 1 : 0;
    e.press = down;
    e.edit_key = code == kBackspace;
    return e;
}

InputEvent button(int code, bool down) {
    InputEvent e;
    e.kind = InputEvent::Kind::mouse_button;
    e.key = code;
    e.action = down ? 1 : 0;
    e.press = down;
    return e;
}

InputEvent pointer(double x, double y) {
    InputEvent e;
    e.kind = InputEvent::Kind::pointer;
    e.x = x, e.y = y;
    return e;
}

InputEvent character(unsigned c) {
    InputEvent e;
    e.kind = InputEvent::Kind::character;
    e.codepoint = c;
    return e;
}

// Feeds the queue frame by frame; each frame's events as a string
// ("B+" press, "B-" release, "'a'" character), frames separated by "|".
std::string frames(std::deque<InputEvent> queue) {
    std::string out;
    while (!queue.empty()) {
        const std::size_t n = events_for_this_frame(queue);
        EXPECT_GE(n, 1u);
        if (!out.empty()) out += "|";
        for (std::size_t i = 0; i < n; ++i) {
            const InputEvent& e = queue.front();
            if (e.kind == InputEvent::Kind::character) out += "'" + std::string(1, char(e.codepoint)) + "'";
            else if (e.kind == InputEvent::Kind::pointer) out += "P";
            else if (e.kind == InputEvent::Kind::mouse_button) out += "M" + std::string(e.press ? "+" : "-");
            else out += (e.key == kBackspace ? "B" : e.key == kShift ? "S" : e.key == kCtrl ? "C" : "K") +
                        std::string(e.press ? "+" : "-");
            queue.pop_front();
        }
    }
    return out;
}

TEST(ExploreInputQueue, ABurstOfBackspacesIsOnePressAndReleaseAFrameEach) {
    std::deque<InputEvent> queue;
    for (int i = 0; i < 5; ++i) {
        queue.push_back(key(kBackspace, true));
        queue.push_back(key(kBackspace, false));
    }
    EXPECT_EQ(frames(queue), "B+|B-|B+|B-|B+|B-|B+|B-|B+|B-") << "10 transitions, 10 frames: none lost";
}

TEST(ExploreInputQueue, CharactersGoTogetherButNeverAfterAKeyPressInTheSameFrame) {
    std::deque<InputEvent> queue = {character('0'), character('.'), character('6'), key(kBackspace, true),
                                    key(kBackspace, false), character('7')};
    EXPECT_EQ(frames(queue), "'0''.''6'B+|B-'7'") << "'7' after the BackSpace's release, never before its press";
}

TEST(ExploreInputQueue, ALetterAndItsCharacterShareAFrameItsReleaseWaits) {
    std::deque<InputEvent> queue = {key(kShift, true), key(kA, true), character('A'), key(kA, false),
                                    key(kShift, false), key(kA, true), character('a'), key(kA, false)};
    EXPECT_EQ(frames(queue), "S+K+'A'|K-S-|K+'a'|K-");
}

// xdotool's "key BackSpace BackSpace keydown ctrl click 1 keyup ctrl" in one
// busy frame: the click reaches ImGui with the Ctrl press, never before it.
TEST(ExploreInputQueue, ACtrlClickBehindQueuedKeysKeepsItsCtrl) {
    std::deque<InputEvent> queue = {key(kBackspace, true), key(kBackspace, false), key(kBackspace, true),
                                    key(kBackspace, false), key(kCtrl, true), button(kLeftButton, true),
                                    button(kLeftButton, false), key(kCtrl, false)};
    EXPECT_EQ(frames(queue), "B+|B-|B+|B-C+M+|M-C-");
}

TEST(ExploreInputQueue, AClickBetweenTwoFramesIsAPressAndAReleaseAFrameEach) {
    std::deque<InputEvent> queue = {button(kLeftButton, true), button(kLeftButton, false), button(kLeftButton, true),
                                    button(kLeftButton, false)};
    EXPECT_EQ(frames(queue), "M+|M-|M+|M-") << "a double click: two clicks, none lost";
}

// A drag made while a frame was busy (a program compiling) arrives whole:
// it is still the press where it began, the moves with the button held, and
// the release where it ended, never a click at its end.
TEST(ExploreInputQueue, ADragThatArrivedWholeIsPressMovesAndRelease) {
    std::deque<InputEvent> queue = {pointer(10, 10), button(kLeftButton, true), pointer(20, 10), pointer(40, 12),
                                    button(kLeftButton, false), pointer(41, 12)};
    EXPECT_EQ(frames(queue), "P|M+|PP|M-|P");
}

TEST(ExploreInputQueue, MovesAndKeysShareAFrameButNotAButtonsChange) {
    std::deque<InputEvent> queue = {key(kCtrl, true), pointer(5, 5), pointer(6, 5), button(kLeftButton, true),
                                    key(kCtrl, false), button(kLeftButton, false)};
    EXPECT_EQ(frames(queue), "C+PP|M+C-|M-");
}

TEST(ExploreInputQueue, AnEmptyQueueFeedsNothing) { EXPECT_EQ(events_for_this_frame({}), 0u); }

// Tab then a digit typed before the next field is active: the digit waits
// kFocusFrames frames after the Tab's press is fed (the keys after it do not),
// so it reaches the field Tab moved to (a sanitizer build's slow frames lost it).
TEST(ExploreInputQueue, CharactersWaitForAFocusKeysMove) {
    constexpr int kTab = 258;
    InputEvent tab = key(kTab, true);
    tab.edit_key = tab.focus_key = true;
    std::deque<InputEvent> queue = {tab, key(kTab, false), character('7'), key(kBackspace, true)};
    InputFeed feed;
    std::vector<std::size_t> fed;
    while (!queue.empty() && fed.size() < 10) {
        const std::size_t n = feed.this_frame(queue);
        fed.push_back(n);
        for (std::size_t i = 0; i < n; ++i) {
            feed.fed(queue.front());
            queue.pop_front();
        }
    }
    // The press; its release; kFocusFrames - 1 frames more of nothing; the digit with the key after it.
    std::vector<std::size_t> expected = {1, 1};
    for (int frame = 1; frame < kFocusFrames; ++frame) expected.push_back(0);
    expected.push_back(2);
    EXPECT_EQ(fed, expected);
    EXPECT_EQ(events_for_this_frame({character('a'), character('b')}, true), 0u) << "held, however many";
    EXPECT_EQ(events_for_this_frame({key(kA, true), character('a')}, true), 1u) << "the keys before them go";
}

}  // namespace
}  // namespace m3055::explore
