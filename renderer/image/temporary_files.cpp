#include "image/temporary_files.h"

#include <fcntl.h>
#include <limits.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <stdexcept>

namespace m3055::temporary_files {
namespace {

// A fixed table, not a std::vector: remove_all() may run in a signal handler,
// which must not see a container in the middle of growing.
struct Slot {
    std::atomic<bool> used{false};
    int folder_fd = -1;
    char name[NAME_MAX + 1] = {};
};
constexpr int kSlots = 256;
Slot slots[kSlots];

}  // namespace

std::mutex& lock() {
    static std::mutex mutex;
    return mutex;
}

int add(int folder_fd, const char* name) {
    for (int i = 0; i < kSlots; ++i) {
        Slot& slot = slots[i];
        if (slot.used.load(std::memory_order_relaxed)) continue;
        slot.folder_fd = folder_fd;
        std::strncpy(slot.name, name, NAME_MAX);
        slot.name[NAME_MAX] = '\0';
        slot.used.store(true, std::memory_order_release);  // published whole
        return i;
    }
    throw std::runtime_error("more than 256 temporary files at once");
}

void forget(int slot) { slots[slot].used.store(false, std::memory_order_release); }

void remove_all() noexcept {
    for (Slot& slot : slots)
        if (slot.used.load(std::memory_order_acquire)) {
            ::unlinkat(slot.folder_fd, slot.name, 0);
            slot.used.store(false, std::memory_order_release);
        }
}

}  // namespace m3055::temporary_files
