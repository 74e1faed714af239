#include "interrupt.h"

#include <atomic>
#include <csignal>
#include <cstdio>

namespace m3055 {
namespace {

// Written by the handler, read by the command's threads: a lock-free atomic is
// async-signal-safe, and nothing else is done inside the handler.
std::atomic<int> received{0};
static_assert(std::atomic<int>::is_always_lock_free);

struct sigaction previous_int, previous_term;

extern "C" void on_signal(int signal) { received.store(signal); }

}  // namespace

InterruptWatch::InterruptWatch() {
    received.store(0);
    struct sigaction action = {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    // SA_RESTART: writes and waits in progress carry on rather than fail with
    // EINTR. SA_RESETHAND: a second Ctrl-C takes the default action, at once.
    action.sa_flags = SA_RESTART | SA_RESETHAND;
    sigaction(SIGINT, &action, &previous_int);
    sigaction(SIGTERM, &action, &previous_term);
}

InterruptWatch::~InterruptWatch() {
    sigaction(SIGINT, &previous_int, nullptr);
    sigaction(SIGTERM, &previous_term, nullptr);
}

int InterruptWatch::signal() const { return received.load(); }

const char* signal_name(int signal) {
    if (signal == SIGINT) return "SIGINT";
    if (signal == SIGTERM) return "SIGTERM";
    static thread_local char text[32];
    std::snprintf(text, sizeof text, "signal %d", signal);
    return text;
}

}  // namespace m3055
