#pragma once
// The parameter `scheme` of the cases that run their own assembly of the chapter's forms (sod,
// sod2d, sod3d, extreme_tubes, conservation_dt): "forms", that assembly as a scene, or a scheme of
// the registry (sph/schemes/) by name, with its own forms and h rule. One list, so that a scheme
// added to the registry is offered by every such case alike.
#include <string>
#include <vector>

#include "sph/schemes/schemes.hpp"
#include "verification/harness/params.hpp"

namespace sphv {

// help: what "forms" means in the case, and what a scheme brings there.
inline ParamSpec forms_or_scheme_param(std::string help) {
  std::vector<std::string> choices = {"forms"};
  for (const auto& name : sph::scheme_names()) choices.push_back(name);
  return choice_param("scheme", "forms", std::move(help), std::move(choices));
}

}  // namespace sphv
