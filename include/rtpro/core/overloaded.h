#pragma once
// The usual lambda-overload set for std::visit: a visit over a variant with a lambda per
// alternative fails to compile when an alternative has no lambda, which is how adding a geometry,
// light or material kind finds every place that must handle it.

namespace rtpro {

template <class... Fs>
struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

}  // namespace rtpro
