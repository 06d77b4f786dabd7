#pragma once
// The kernels, by name. A kernel is a policy type with the interface of CubicSpline<D>
// (cubic_spline.hpp); h is the full support radius of every one. Adding a kernel: its header and
// one line in Kernels below. A run-time name is resolved once, by with_kernel, into the kernel's
// type; the pair loops then take it as a template parameter (no test per pair).
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sph/kernel/cubic_spline.hpp"
#include "sph/kernel/quartic_spline.hpp"
#include "sph/kernel/quintic_spline.hpp"
#include "sph/kernel/wendland_c2.hpp"
#include "sph/kernel/wendland_c4.hpp"
#include "sph/kernel/wendland_c6.hpp"

namespace sph {

template <template <int> class... K>
struct KernelList {};

// The registry, the default (the chapter's cubic spline, (6)) first.
using Kernels = KernelList<CubicSpline, QuarticSpline, QuinticSpline, WendlandC2, WendlandC4, WendlandC6>;

template <template <int> class... K>
std::vector<std::string> kernel_names(KernelList<K...>) {
  return {K<1>::name...};
}
inline std::vector<std::string> kernel_names() { return kernel_names(Kernels{}); }

// f(K<D>{}) for the kernel named `name` among those of the list (default: all); throws
// std::invalid_argument naming the choices for an unknown name.
template <int D, template <int> class... K, class F>
void with_kernel(const std::string& name, F&& f, KernelList<K...>) {
  if (((name == K<D>::name ? (f(K<D>{}), true) : false) || ...)) return;
  std::string known;
  for (const auto& k : kernel_names(KernelList<K...>{})) known += (known.empty() ? "" : ", ") + k;
  throw std::invalid_argument("unknown kernel '" + name + "' (" + known + ")");
}
template <int D, class F>
void with_kernel(const std::string& name, F&& f) {
  with_kernel<D>(name, std::forward<F>(f), Kernels{});
}

// f.template operator()<K>() for the kernel template K named `name` (every dimension at once, as
// K<1>, K<2>, K<3>); throws std::invalid_argument as with_kernel.
template <template <int> class... K, class F>
void with_kernel_family(const std::string& name, F&& f, KernelList<K...>) {
  if (((name == K<1>::name ? (f.template operator()<K>(), true) : false) || ...)) return;
  with_kernel<1>(name, [](auto) {}, KernelList<K...>{});  // throws, naming the choices
}
template <class F>
void with_kernel_family(const std::string& name, F&& f) {
  with_kernel_family(name, std::forward<F>(f), Kernels{});
}

}  // namespace sph
