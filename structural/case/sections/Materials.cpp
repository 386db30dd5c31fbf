// [materials]: line materials (cable, truss) and membrane materials.
#include <string>

#include "case/sections/Sections.hpp"

namespace chute::caseio {

namespace {

kernels::MembraneMaterial readMembraneMaterial(TomlTable t) {
  kernels::MembraneMaterial m;
  t.string("kind");
  m.E = t.positive("E");
  m.nu = t.number("nu", 0.3);
  if (m.nu < 0.0 || m.nu >= 0.5) t.fail("nu", "must be in [0, 0.5)");
  m.thickness = t.positive("thickness");
  m.density = t.nonNegative("density", 0.0);
  // Optional: without it the utilisation field is NaN (docs/output.md).
  if (t.has("strength")) m.strength = t.positive("strength");
  t.finish();
  return m;
}

kernels::LineMaterial readMaterial(TomlTable t) {
  kernels::LineMaterial m;
  const std::string kind = t.choice("kind", "cable", {"cable", "truss", "membrane"});
  m.tensionOnly = kind == "cable";
  m.E = t.positive("E");
  m.area = t.positive("area");
  m.density = t.nonNegative("density", 0.0);
  m.compressionStiffnessRatio = t.nonNegative("compression_stiffness_ratio", 0.0);
  // E_c / E: a cable or cord no stiffer in compression than in tension (1: a truss member);
  // 1e300 overflowed the mass and was refused as "mass not finite", naming no key.
  if (m.compressionStiffnessRatio > 1.0) t.fail("compression_stiffness_ratio", "must be in [0, 1]");
  t.finish();
  return m;
}

}  // namespace

void readMaterials(Model& m, TomlTable mats) {
  for (const auto& name : mats.keys()) {
    TomlTable t = mats.table(name);
    if (t.has("kind") && t.string("kind") == "membrane") {
      m.membraneMaterialName.push_back(name);
      m.membraneMaterials.push_back(readMembraneMaterial(t));
    } else {
      m.materialName.push_back(name);
      m.materials.push_back(readMaterial(t));
    }
  }
}

}  // namespace chute::caseio
