#include "models/range.h"

#include "io/message_text.h"

#include <cmath>

namespace m3055 {

bool Range::contains(double x) const {
    const bool above = lo_open ? x > lo : x >= lo;
    const bool below = hi_open ? x < hi : x <= hi;
    return above && below;
}

std::string Range::text() const {
    if (std::isinf(hi)) return (lo_open ? "> " : ">= ") + text::format_number(lo);
    return std::string("in ") + (lo_open ? "(" : "[") + text::format_number(lo) + ", " +
           text::format_number(hi) + (hi_open ? ")" : "]");
}

Range closed(double lo, double hi) { return Range{lo, hi}; }

}  // namespace m3055
