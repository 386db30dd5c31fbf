// The C interface (chute_coupling.h) against the C++ one it wraps: every wet-surface accessor's C
// twin gives exactly (bit for bit) what the C++ accessor gives on an interface built from the same
// case, before and after a window advanced under the same loads.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "case/CaseSpec.hpp"
#include "coupling/CouplingInterface.hpp"
#include "coupling/chute_coupling.h"

using chute::coupling::CouplingInterface;

namespace {

const std::string kCase = std::string(CHUTE_SOURCE_DIR) + "/cases/canopy_coupled.toml";

// Bitwise equality of n doubles (so that a NaN equals itself and -0 differs from +0).
long bitDifferences(const double* a, const double* b, long n) {
  long d = 0;
  for (long i = 0; i < n; ++i) d += std::memcmp(a + i, b + i, sizeof(double)) != 0;
  return d;
}

using DoubleAccessor = int (*)(const chute_coupling*, double*);

struct Compared {
  long values = 0, differences = 0;
};

// Every 3-per-vertex, 3-per-face and 1-per-face accessor, C against C++.
Compared compareState(const chute_coupling* h, const CouplingInterface& s) {
  const long nv = s.numVertices(), nf = s.numFaces();
  const struct {
    const char* name;
    DoubleAccessor c;
    Eigen::VectorXd cpp;
    long size;
  } fields[] = {
      {"reference_coordinates", chute_coupling_reference_coordinates, s.referenceCoordinates(),
       3 * nv},
      {"current_coordinates", chute_coupling_current_coordinates, s.currentCoordinates(), 3 * nv},
      {"displacements", chute_coupling_displacements, s.displacements(), 3 * nv},
      {"velocities", chute_coupling_velocities, s.velocities(), 3 * nv},
      {"accelerations", chute_coupling_accelerations, s.accelerations(), 3 * nv},
      {"face_normals", chute_coupling_face_normals, s.faceNormals(), 3 * nf},
      {"face_areas", chute_coupling_face_areas, s.faceAreas(), nf},
      {"face_area_vectors", chute_coupling_face_area_vectors, s.faceAreaVectors(), 3 * nf},
      {"face_centres", chute_coupling_face_centres, s.faceCentres(), 3 * nf},
  };
  Compared r;
  for (const auto& f : fields) {
    EXPECT_EQ(f.cpp.size(), f.size) << f.name;
    std::vector<double> out(static_cast<size_t>(f.size), -1.0);
    EXPECT_EQ(f.c(h, out.data()), CHUTE_OK) << f.name << ": " << chute_coupling_last_error(h);
    const long d = bitDifferences(out.data(), f.cpp.data(), f.size);
    EXPECT_EQ(d, 0) << f.name;
    r.values += f.size, r.differences += d;
    EXPECT_EQ(f.c(h, nullptr), CHUTE_ERROR_INPUT) << f.name;  // no array: refused, no crash
  }
  // The layout helpers on the state's own vectors.
  const Eigen::VectorXd v = s.velocities();
  std::vector<double> means(static_cast<size_t>(3 * nf));
  EXPECT_EQ(chute_coupling_face_means(h, v.data(), means.data()), CHUTE_OK);
  const Eigen::VectorXd meansCpp = s.surface().faceMeans(v);
  r.differences += bitDifferences(means.data(), meansCpp.data(), 3 * nf);
  r.values += 3 * nf;
  const Eigen::VectorXd& x = s.state().x;
  std::vector<double> gathered(static_cast<size_t>(3 * nv));
  EXPECT_EQ(chute_coupling_gather(h, x.data(), gathered.data()), CHUTE_OK);
  const Eigen::VectorXd gatheredCpp = s.surface().gather(x);
  r.differences += bitDifferences(gathered.data(), gatheredCpp.data(), 3 * nv);
  r.values += 3 * nv;
  EXPECT_EQ(r.differences, 0);
  return r;
}

}  // namespace

TEST(CouplingCApi, EveryWetSurfaceAccessorsCTwinEqualsTheCppAccessorBitForBit) {
  chute_coupling* h = nullptr;
  ASSERT_EQ(chute_coupling_create(kCase.c_str(), nullptr, 0, &h), CHUTE_OK)
      << chute_coupling_last_error(nullptr);
  CouplingInterface s(chute::readCase(kCase, {}));

  // Topology.
  int nv = -1, nf = -1, nsets = -1, nodes = -1;
  ASSERT_EQ(chute_coupling_num_vertices(h, &nv), CHUTE_OK);
  ASSERT_EQ(chute_coupling_num_faces(h, &nf), CHUTE_OK);
  ASSERT_EQ(chute_coupling_num_surface_sets(h, &nsets), CHUTE_OK);
  ASSERT_EQ(chute_coupling_num_model_nodes(h, &nodes), CHUTE_OK);
  ASSERT_EQ(nv, s.numVertices());
  ASSERT_EQ(nf, s.numFaces());
  ASSERT_EQ(nsets, static_cast<int>(s.surface().sets.size()));
  ASSERT_EQ(nodes, s.spec().model.numNodes());
  std::vector<int> faces(4 * nf), sizes(nf), vertexNodes(nv), elements(nf), sets(nsets);
  ASSERT_EQ(chute_coupling_face_vertices(h, faces.data()), CHUTE_OK);
  ASSERT_EQ(chute_coupling_face_sizes(h, sizes.data()), CHUTE_OK);
  ASSERT_EQ(chute_coupling_vertex_nodes(h, vertexNodes.data()), CHUTE_OK);
  ASSERT_EQ(chute_coupling_face_elements(h, elements.data()), CHUTE_OK);
  ASSERT_EQ(chute_coupling_surface_sets(h, sets.data()), CHUTE_OK);
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < 4; ++i) EXPECT_EQ(faces[4 * f + i], s.surface().faceVertices[f][i]);
  EXPECT_EQ(sizes, s.surface().faceSize);
  EXPECT_EQ(vertexNodes, s.surface().node);
  EXPECT_EQ(elements, s.surface().element);
  EXPECT_EQ(sets, s.surface().sets);
  EXPECT_EQ(chute_coupling_face_sizes(h, nullptr), CHUTE_ERROR_INPUT);
  EXPECT_EQ(chute_coupling_face_sizes(nullptr, sizes.data()), CHUTE_ERROR_INPUT);

  const Compared atStart = compareState(h, s);

  // A window under the same face pressure on both, from initial data, with a checkpoint.
  std::vector<double> p(nf, 25.0);
  ASSERT_EQ(chute_coupling_set_face_pressures(h, p.data()), CHUTE_OK);
  s.setFacePressures(Eigen::Map<const Eigen::VectorXd>(p.data(), nf));
  ASSERT_EQ(chute_coupling_initialize_with_loads(h), CHUTE_OK) << chute_coupling_last_error(h);
  s.initializeWithLoads();
  int has = -1;
  ASSERT_EQ(chute_coupling_has_checkpoint(h, &has), CHUTE_OK);
  EXPECT_EQ(has, 0);
  ASSERT_EQ(chute_coupling_save_checkpoint(h), CHUTE_OK);
  s.saveCheckpoint();
  ASSERT_EQ(chute_coupling_has_checkpoint(h, &has), CHUTE_OK);
  EXPECT_EQ(has, 1);
  EXPECT_EQ(static_cast<bool>(has), s.hasCheckpoint());
  double dt = 0, taken = 0;
  ASSERT_EQ(chute_coupling_preferred_time_step(h, &dt), CHUTE_OK);
  ASSERT_EQ(chute_coupling_advance(h, 2 * dt, &taken), CHUTE_OK) << chute_coupling_last_error(h);
  EXPECT_EQ(taken, s.advance(2 * dt));
  const Compared afterWindow = compareState(h, s);
  double t = 0;
  ASSERT_EQ(chute_coupling_time(h, &t), CHUTE_OK);
  EXPECT_EQ(t, s.time());
  // After an advance the start's data can no longer be set.
  EXPECT_NE(chute_coupling_initialize_with_loads(h), CHUTE_OK);
  std::printf(
      "C interface vs C++: %d vertices, %d faces, %d set(s); %ld values compared at the "
      "start, %ld after a window of %.3g s: %ld and %ld differ\n",
      nv, nf, nsets, atStart.values, afterWindow.values, taken, atStart.differences,
      afterWindow.differences);
  chute_coupling_destroy(h);
}
