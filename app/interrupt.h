// Ctrl-C (SIGINT) or SIGTERM during a long command (`m3055 batch`): the first
// signal only asks the command to stop at its next safe point, between scenes,
// so every finished file is kept and none is left half-written (each write is
// a temporary file renamed into place, and writes already started complete).
// A second signal kills at once: the handler is one-shot (SA_RESETHAND).
#pragma once

namespace m3055 {

// 128 + SIGINT: the shell's status for a command stopped by Ctrl-C.
inline constexpr int kExitInterrupted = 130;

class InterruptWatch {
public:
    InterruptWatch();   // installs the handlers for SIGINT and SIGTERM
    ~InterruptWatch();  // restores the previous ones
    InterruptWatch(const InterruptWatch&) = delete;
    InterruptWatch& operator=(const InterruptWatch&) = delete;

    // The signal received since construction, or 0. Safe from any thread.
    int signal() const;
    bool raised() const { return signal() != 0; }
};

// "SIGINT", "SIGTERM", or "signal N".
const char* signal_name(int signal);

}  // namespace m3055
