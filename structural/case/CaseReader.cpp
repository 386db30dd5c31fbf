// Case file -> CaseSpec. The schema is documented in docs/case-files.md; each
// section is read in case/sections/.
#include <algorithm>
#include <filesystem>
#include <memory>

#include "case/CaseSpec.hpp"
#include "case/CaseText.hpp"
#include "case/MeshGroups.hpp"
#include "case/TomlTable.hpp"
#include "case/sections/Sections.hpp"

namespace chute {

CaseSpec readCase(const std::string& file, const std::vector<std::string>& overrides) {
  return readCaseFromString(caseio::readText(file), file, overrides);
}

CaseSpec readCaseFromString(const std::string& text, const std::string& file,
                            const std::vector<std::string>& overrides) {
  toml::value root = caseio::parseText(text, file);
  for (const auto& o : overrides) caseio::applyOverride(root, file, o);
  TomlTable top(root, "", file);
  // Unknown top-level keys first: a misspelt table would otherwise surface as
  // something missing.
  top.finish({"name", "description", "units", "nodes", "materials", "cables", "sliding_groups",
              "membranes", "point_masses", "boundary", "loads", "solver", "output", "reference",
              "mesh", "events", "air", "initial", "contact"});
  CaseSpec c;
  c.file = file;
  c.name = top.string("name", std::filesystem::path(file).stem().string());
  // The name is the default output directory out/<name>/: one plain path
  // component.
  if (c.name.empty() || c.name == "." || c.name == ".." ||
      c.name.find_first_of("/\\") != std::string::npos ||
      std::any_of(c.name.begin(), c.name.end(), [](char ch) { return ch >= 0 && ch < 32; }))
    top.fail("name", "must be a plain file name (no '/', not empty, '.' or '..')");
  c.description = top.string("description", "");
  c.units = top.string("units", "");
  Model& m = c.model;

  if (top.has("nodes")) caseio::readNodes(m, top.table("nodes"));
  std::unique_ptr<MeshImport> mesh;  // [mesh]: a gmsh mesh whose physical groups entries map
  if (top.has("mesh")) mesh = importMesh(m, top.table("mesh"), file);
  if (top.has("materials")) caseio::readMaterials(m, top.table("materials"));
  caseio::readCables(m, mesh.get(), top);
  caseio::readSlidingGroups(m, mesh.get(), top);
  caseio::readMembranes(m, mesh.get(), top);
  if (m.numNodes() == 0) top.fail("nodes", "the case has no nodes (no [nodes] and no meshes)");
  caseio::readPointMasses(m, mesh.get(), top);
  if (top.has("boundary")) caseio::readBoundary(m, top.table("boundary"));
  if (top.has("air")) caseio::readAir(c, top.table("air"));
  if (top.has("initial")) caseio::readInitial(m, top.table("initial"));
  if (top.has("loads")) caseio::readLoads(m, mesh.get(), top.table("loads"));
  caseio::readEvents(m, top);
  if (top.has("contact")) caseio::readContact(m, top.table("contact"));
  caseio::readSolver(c, top.table("solver"));
  if (top.has("output")) caseio::readOutput(c, top.table("output"));
  if (top.has("reference")) caseio::readReference(c, top.table("reference"));
  if (mesh) holdUnusedMeshNodes(m, *mesh);
  const long equations = DofMap(m).numEquations();
  if (equations == 0)
    top.fail(top.has("boundary") ? "boundary" : "nodes",
             "every degree of freedom is fixed or prescribed: there is nothing "
             "to solve");
  if (equations > c.solver.maxEquations)
    top.table("solver").fail(
        "max_equations", "the model has " + std::to_string(equations) +
                             " equations, more than the limit " +
                             std::to_string(c.solver.maxEquations) +
                             " (raise solver.max_equations to run it: expect minutes per step)");
  top.finish();
  return c;
}

}  // namespace chute
