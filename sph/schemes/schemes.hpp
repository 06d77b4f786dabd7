#pragma once
// The schemes, by name. A scheme is a type with the phases of scheme.hpp; its registry entry has
// `name` and `with<D, K>(options, f, extra...)`, which calls f with the scheme built for the
// options' forms. Adding a scheme: its header and one line in Schemes below. A run-time name is
// resolved once, by with_scheme, into the scheme's type (no test per pair).
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sph/schemes/chapter.hpp"
#include "sph/schemes/gradh_switches.hpp"

namespace sph {

template <class... S>
struct SchemeList {};

// The registry, the default (the chapter's scheme) first.
using Schemes = SchemeList<ChapterScheme, GradhSwitchesScheme>;

template <class... S>
std::vector<std::string> scheme_names(SchemeList<S...>) {
  return {S::name...};
}
inline std::vector<std::string> scheme_names() { return scheme_names(Schemes{}); }
inline std::string default_scheme() { return scheme_names().front(); }

template <class... S>
[[noreturn]] void unknown_scheme(const std::string& name, SchemeList<S...> list) {
  std::string known;
  for (const auto& s : scheme_names(list)) known += (known.empty() ? "" : ", ") + s;
  throw std::invalid_argument("unknown scheme '" + name + "' (" + known + ")");
}

// f(scheme) for the scheme named `name` with the kernel K, built for the options o, with the extra
// force terms (held by reference); throws std::invalid_argument naming the choices for an unknown
// name, and whatever the scheme throws for options it lacks.
template <int D, class K, class F, class... S, class... Extra>
void with_scheme(const std::string& name, const SchemeOptions& o, F&& f, SchemeList<S...>, Extra&... extra) {
  if (((name == S::name ? (S::template with<D, K>(o, f, extra...), true) : false) || ...)) return;
  unknown_scheme(name, SchemeList<S...>{});
}
template <int D, class K, class F, class... Extra>
void with_scheme(const std::string& name, const SchemeOptions& o, F&& f, Extra&... extra) {
  with_scheme<D, K>(name, o, std::forward<F>(f), Schemes{}, extra...);
}

// f(scheme) for the scheme named with its default forms (Default in its entry) and the options'
// numbers: one type a scheme, where a caller times a scheme rather than choosing its forms.
template <int D, class K, class F, class... S>
void with_default_scheme(const std::string& name, const SchemeOptions& o, F&& f, SchemeList<S...>) {
  auto run = [&]<class T>() {
    T s(o);
    f(s);
    return true;
  };
  if (((name == S::name ? run.template operator()<typename S::template Default<D, K>>() : false) || ...)) return;
  unknown_scheme(name, SchemeList<S...>{});
}
template <int D, class K, class F>
void with_default_scheme(const std::string& name, const SchemeOptions& o, F&& f) {
  with_default_scheme<D, K>(name, o, std::forward<F>(f), Schemes{});
}

}  // namespace sph
