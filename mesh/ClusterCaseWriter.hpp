#pragma once
// Writes a case file that flies a generated cluster (ClusterGenerator.hpp): per canopy i the
// settings of a generated parachute case (ParachuteCaseWriter.hpp: its materials, canopy
// pressure and face drag, line and slider drag) on the sets suffixed _<i>; the risers with the
// section of the lines each gathers; the common payload held in the frame of the falling payload
// (gravity 0, the air streaming up at the speed whose dynamic pressure is the canopy pressure);
// central differences; probes of each canopy's skirt radius, the riser forces and energy. Fabric
// contact between canopies is not part of it: a [contact] section can be added to the file.
#include <string>

#include "ClusterGenerator.hpp"
#include "ParachuteCaseWriter.hpp"

namespace chute::mesh {

// Throws std::invalid_argument for bad options and std::runtime_error if the file cannot be
// written; msh is referenced relative to the case file's folder.
void writeClusterCase(const ClusterSpec& spec, const GeneratedCluster& cluster,
                      const std::string& caseFile, const std::string& msh,
                      const ParachuteCaseOptions& options);

}  // namespace chute::mesh
