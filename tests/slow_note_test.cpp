// app/slow_note.h: the line a slow step prints on a terminal, and nothing else.
#include "slow_note.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>

namespace m3055 {
namespace {

using namespace std::chrono_literals;

// What a stream written by SlowNote holds.
class Stream {
public:
    std::FILE* file() const { return file_.get(); }
    std::string text() const {
        std::fflush(file_.get());
        std::rewind(file_.get());
        std::string all;
        char buffer[256];
        while (std::fgets(buffer, sizeof buffer, file_.get())) all += buffer;
        return all;
    }

private:
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_{std::tmpfile(), &std::fclose};
};

TEST(SlowNote, AStepThatOutlastsItIsNamedThenTimed) {
    Stream stream;
    {
        SlowNote note(10ms, "drawing", "why it takes long", true, stream.file());
        std::this_thread::sleep_for(300ms);
        note.finished();
    }
    const std::string text = stream.text();
    const std::string first = "m3055: drawing: why it takes long...\nm3055: drawing took ";
    EXPECT_EQ(text.substr(0, first.size()), first) << text;
    EXPECT_EQ(text.substr(text.size() - 3), " s\n") << text;  // whole seconds: 0 unless the machine is loaded
}

TEST(SlowNote, AStepThatFailsSaysItStopped) {
    Stream stream;
    {
        const SlowNote note(10ms, "drawing", "why", true, stream.file());
        std::this_thread::sleep_for(300ms);
    }
    EXPECT_NE(stream.text().find("m3055: drawing stopped after "), std::string::npos) << stream.text();
}

TEST(SlowNote, AStepThatEndsFirstPrintsNothing) {
    Stream stream;
    { const SlowNote note(60s, "drawing", "why", true, stream.file()); }  // ends at once, not after 60 s
    EXPECT_EQ(stream.text(), "");
}

TEST(SlowNote, OffATerminalNothingIsPrinted) {
    Stream stream;
    {
        const SlowNote note(0ms, "drawing", "why", false, stream.file());
        std::this_thread::sleep_for(50ms);
    }
    EXPECT_EQ(stream.text(), "");
}

}  // namespace
}  // namespace m3055
