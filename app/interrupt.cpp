#include "interrupt.h"

#include "image/temporary_files.h"
#include "io/message_text.h"

#include <poll.h>
#include <sys/eventfd.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdint>

namespace m3055 {
namespace {

sigset_t interrupt_signals() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);
    return set;
}

void write_all(int fd, const std::string& text) {
    const char* p = text.data();
    std::size_t left = text.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;  // a closed terminal (SIGHUP) or pipe: nothing more to do
        p += n;
        left -= std::size_t(n);
    }
}

// The SIGBUS line, made before any fault (a handler may not allocate).
char bus_line[512];
std::size_t bus_line_length = 0;

extern "C" void on_bus_error(int) {
    temporary_files::remove_all();
    if (::write(STDERR_FILENO, bus_line, bus_line_length) < 0) {
        // nothing more can be done
    }
    ::_exit(1);
}

}  // namespace

void report_bus_errors(const std::string& shader_cache_folder) {
    const std::string cause =
        shader_cache_folder.empty()
            ? "a memory-mapped file could not be written (a full disk?)"
            : "a memory-mapped file could not be written; if the disk of the Mesa shader cache " +
                  text::quote_name(shader_cache_folder) + " is full, free space there or set MESA_SHADER_CACHE_DISABLE=true";
    const std::string line = text::one_line("m3055: bus error (SIGBUS): " + cause) + "\n";
    bus_line_length = std::min(line.size(), sizeof bus_line);
    std::memcpy(bus_line, line.data(), bus_line_length);
    struct sigaction action {};
    action.sa_handler = on_bus_error;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;  // a fault inside the handler ends the process plainly
    sigaction(SIGBUS, &action, nullptr);
}

InterruptGuard::InterruptGuard(std::function<std::string(int)> line) : line_(std::move(line)) {
    // A signalfd and a thread, not a handler: the watcher may take locks,
    // format text and remove files, none of which a signal handler may do.
    const sigset_t set = interrupt_signals();
    pthread_sigmask(SIG_BLOCK, &set, &previous_mask_);
    signal_fd_ = ::signalfd(-1, &set, SFD_CLOEXEC);
    stop_fd_ = ::eventfd(0, EFD_CLOEXEC);
    watcher_ = std::thread([this] { watch(); });
}

InterruptGuard::~InterruptGuard() {
    const std::uint64_t one = 1;
    if (::write(stop_fd_, &one, sizeof one) < 0) {
        // eventfd writes do not fail short of overflow; nothing to do
    }
    watcher_.join();
    ::close(signal_fd_);
    ::close(stop_fd_);
    pthread_sigmask(SIG_SETMASK, &previous_mask_, nullptr);
}

void InterruptGuard::watch() {
    // A reader gone (SIGHUP with stderr on a pipe) must not end the process
    // before the temporaries are removed: writes here fail with EPIPE instead.
    sigset_t pipe_only;
    sigemptyset(&pipe_only);
    sigaddset(&pipe_only, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_only, nullptr);
    pollfd fds[2] = {{signal_fd_, POLLIN, 0}, {stop_fd_, POLLIN, 0}};
    for (;;) {
        if (::poll(fds, 2, -1) < 0) {
            if (errno == EINTR) continue;
            return;
        }
        if (fds[1].revents) return;
        signalfd_siginfo info{};
        if (fds[0].revents && ::read(signal_fd_, &info, sizeof info) == ssize_t(sizeof info))
            end_process(int(info.ssi_signo));
    }
}

void InterruptGuard::end_process(int signal) {
    // Taken and never given back: no rename starts after this, and one under
    // way (a PNG and its PFM) has finished.
    temporary_files::lock().lock();
    temporary_files::remove_all();
    write_all(STDERR_FILENO, line_(signal) + "\n");
    // End by the signal itself: its default action, delivered to this thread.
    ::signal(signal, SIG_DFL);
    sigset_t only;
    sigemptyset(&only);
    sigaddset(&only, signal);
    pthread_sigmask(SIG_UNBLOCK, &only, nullptr);
    ::raise(signal);
    ::_exit(128 + signal);  // not reached
}

std::string signal_name(int signal) {
    if (signal == SIGINT) return "SIGINT";
    if (signal == SIGTERM) return "SIGTERM";
    if (signal == SIGHUP) return "SIGHUP";
    return "signal " + std::to_string(signal);
}

}  // namespace m3055
