#pragma once
// The registration of contact laws: the one the solvers (both backends), the time step and
// the material table use. A contact law is a policy struct (physics/potential_law.hpp lists
// its members); a new one is a new file beside potential_law.hpp, registered here.
#include "physics/potential_law.hpp"

namespace tridem::physics {

using SceneContactLaw = PotentialLaw;

/// The table entry of a pair of materials under that law.
template <class Real>
using LawParameters = SceneContactLaw::Parameters<Real>;

}  // namespace tridem::physics
