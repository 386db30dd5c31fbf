#pragma once
// Lookups and value helpers the case sections share: nodes, materials and sets by name, checked
// coordinates and lengths, and the model-size budget.
#include <string>
#include <vector>

#include "case/TomlTable.hpp"
#include "model/Model.hpp"

namespace chute::caseio {

// Largest model a case may generate (nodes): a typo in a count must give an error, not exhaust
// memory. About 0.3 GB of model data; meshes this size come from a mesh file, not a count.
inline constexpr long kMaxNodes = 1000000;
// Largest coordinate or length a case may give: squared distances must not overflow.
inline constexpr double kMaxLength = 1e100;

// x with three significant digits, for messages.
std::string shortNumber(double x);

// A coordinate triple within +-kMaxLength (required, or `fallback` when absent).
Vec3 point(TomlTable& t, const std::string& key, const Vec3* fallback = nullptr);
// A positive length up to kMaxLength.
double length(TomlTable& t, const std::string& key);

// The node named `name` (read from `key` of t); fails if there is none.
int nodeRef(const Model& m, TomlTable& t, const std::string& key, const std::string& name);
// The line material t's `material` names.
int materialRef(const Model& m, TomlTable& t);
// The membrane material t's `material` names.
int membraneMaterialRef(const Model& m, TomlTable& t);

// Cables, sliding groups and membranes name the nodes they generate after themselves, and probes
// and loads refer to them by name: one name, one entry.
std::string setName(const Model& m, TomlTable& t, const std::string& fallback);

// Fails when adding `extra` nodes would take the model past kMaxNodes.
void checkNodeBudget(const Model& m, TomlTable& t, const std::string& key, long extra);

// The names a case can refer to, for did-you-mean suggestions (CaseText.hpp, nameSuggestion).
std::vector<std::string> nodeNames(const Model& m);
std::vector<std::string> nodeSetNames(const Model& m);
std::vector<std::string> membraneSetNames(const Model& m);
// Line sets: cable sets and / or sliding groups.
std::vector<std::string> lineSetNames(const Model& m, bool cables, bool sliding);

// The nodes of `nodes = [...]` and / or `set = "..."`; fails if neither names any.
std::vector<int> nodesOf(const Model& m, TomlTable& t);

}  // namespace chute::caseio
