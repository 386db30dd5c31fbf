#pragma once
// Fabric contact as a case declares it (`[contact]`, docs/contact.md and docs/case-files.md):
// which membrane and line sets take part and the parameters of the contact law (CT4-CT9). A
// model without it (enabled = false) has no contact term and pays nothing for contact.
#include <vector>

namespace chute {

struct ContactDef {
  bool enabled = false;
  double thickness = 0.0;         // dHat: the pairs closer than this push apart (CT4)
  double stiffnessScale = 0.01;   // kappa of CT9: k = kappa m / dt_i^2 = kappa S_i / 4
  double dampingRatio = 0.0;      // zeta of CT6: c = 2 zeta sqrt(k m)
  double friction = 0.0;          // Coulomb's mu (CT7)
  double slipSpeed = 0.0;         // eps_v of CT7 (speed units)
  double skin = 0.0;              // the broad phase's skin (CT10)
  std::vector<int> membraneSets;  // indices into Model::membraneSets
  std::vector<int> lineSets;      // indices into Model::lineSets (cables and sliding groups)
};

}  // namespace chute
