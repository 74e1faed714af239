// The temporary files the atomic writers (image/atomic_file.cpp) hold at any
// moment, so that an interrupted run can remove them (app/interrupt.cpp), and
// the lock that makes creating, renaming and removing them indivisible for it.
#pragma once

#include <mutex>

namespace m3055::temporary_files {

// Held while a temporary is created and registered, while a group of them (a
// PNG and its PFM) is renamed into place, and while they are removed. An
// interrupt takes it and keeps it until the process ends, so it never sees a
// group half renamed, nor a temporary created but not yet registered.
std::mutex& lock();

// With lock() held: remember the temporary `name` in the folder open as
// `folder_fd` (kept open until forget()); returns its slot. Throws
// std::runtime_error when more than 256 are held at once.
int add(int folder_fd, const char* name);
// With lock() held: the temporary is gone (renamed into place or removed).
void forget(int slot);

// Removes every temporary still registered. Async-signal-safe: it only reads
// a fixed table and calls unlinkat(), so a fatal-signal handler may call it.
void remove_all() noexcept;

}  // namespace m3055::temporary_files
