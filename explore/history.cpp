#include "explore/history.h"

#include <utility>

namespace m3055::explore {

void History::clear() {
    pending_ = Step{};
    undo_.clear();
    redo_.clear();
}

bool History::commit() {
    if (pending_.edits.empty()) return false;
    undo_.push_back(std::move(pending_));
    if (undo_.size() > kMaxSteps) undo_.pop_front();
    redo_.clear();
    pending_ = Step{};
    return true;
}

const Step& History::undo() {
    redo_.push_back(std::move(undo_.back()));
    undo_.pop_back();
    return redo_.back();
}

const Step& History::redo() {
    undo_.push_back(std::move(redo_.back()));
    redo_.pop_back();
    return undo_.back();
}

}  // namespace m3055::explore
