// std::visit over a variant with one lambda per alternative.
#pragma once

namespace m3055::explore {

template <class... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

}  // namespace m3055::explore
