#pragma once
// The readers of a case file's sections, in the order readCase() calls them (later sections
// refer to what earlier ones defined: nodes, materials, sets, probes). Each reads its table (or
// the entries of its array of tables in `top`) into the model or case and fails on bad input.
#include "case/CaseSpec.hpp"
#include "case/TomlTable.hpp"

namespace chute {
struct MeshImport;
}

namespace chute::caseio {

void readNodes(Model& m, TomlTable nodes);     // [nodes]
void readMaterials(Model& m, TomlTable mats);  // [materials]
// [[cables]], [[sliding_groups]], [[membranes]], [[point_masses]]: mesh may be null (no [mesh]).
void readCables(Model& m, const MeshImport* mesh, TomlTable& top);
void readSlidingGroups(Model& m, const MeshImport* mesh, TomlTable& top);
void readMembranes(Model& m, const MeshImport* mesh, TomlTable& top);
void readPointMasses(Model& m, const MeshImport* mesh, TomlTable& top);
void readBoundary(Model& m, TomlTable b);                       // [boundary]
void readAir(CaseSpec& c, TomlTable a);                         // [air]
void readInitial(Model& m, TomlTable i);                        // [initial]
void readLoads(Model& m, const MeshImport* mesh, TomlTable l);  // [loads]
void readEvents(Model& m, TomlTable& top);                      // [[events]]
void readContact(Model& m, TomlTable c);                        // [contact]
void readSolver(CaseSpec& c, TomlTable s);                      // [solver]
void readOutput(CaseSpec& c, TomlTable o);                      // [output]
void readReference(CaseSpec& c, TomlTable r);                   // [reference]

}  // namespace chute::caseio
