// The C interface (chute_coupling.h) over CouplingInterface: every call catches every exception
// and turns it into a status code and a message.
#include "coupling/chute_coupling.h"

#include <algorithm>
#include <exception>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "case/CaseError.hpp"
#include "coupling/CouplingInterface.hpp"

struct chute_coupling {
  std::unique_ptr<chute::coupling::CouplingInterface> structure;
  mutable std::string lastError;
};

namespace {
thread_local std::string gCreateError;

// Runs f, mapping exceptions to status codes and remembering the message on the handle.
template <class F>
int guarded(const chute_coupling* h, F&& f) {
  std::string* err = h ? &h->lastError : &gCreateError;
  if (!h) {
    *err = "null chute_coupling handle";
    return CHUTE_ERROR_INPUT;
  }
  try {
    f(*h->structure);
    err->clear();
    return CHUTE_OK;
  } catch (const chute::CaseError& e) {
    *err = e.what();
    return CHUTE_ERROR_INPUT;
  } catch (const std::invalid_argument& e) {
    *err = e.what();
    return CHUTE_ERROR_INPUT;
  } catch (const chute::coupling::NoCheckpointError& e) {
    *err = e.what();
    return CHUTE_ERROR_STATE;
  } catch (const chute::coupling::CallOrderError& e) {
    *err = e.what();
    return CHUTE_ERROR_STATE;
  } catch (const chute::coupling::CouplingError& e) {
    *err = e.what();
    return CHUTE_ERROR_SOLVER;
  } catch (const std::exception& e) {
    *err = e.what();
    return CHUTE_ERROR_INTERNAL;
  } catch (...) {
    *err = "unknown error";
    return CHUTE_ERROR_INTERNAL;
  }
}

int copyOut(const Eigen::VectorXd& v, double* out) {
  if (!out) throw std::invalid_argument("null output array");
  std::copy(v.data(), v.data() + v.size(), out);
  return CHUTE_OK;
}
void copyOutInts(const std::vector<int>& v, int* out) {
  if (!out) throw std::invalid_argument("null output array");
  std::copy(v.begin(), v.end(), out);
}
Eigen::VectorXd copyIn(const double* in, long n) {
  if (!in) throw std::invalid_argument("null input array");
  return Eigen::Map<const Eigen::VectorXd>(in, n);
}
}  // namespace

extern "C" {

int chute_coupling_create(const char* case_file, const char* const* overrides, int num_overrides,
                          chute_coupling** handle) {
  if (handle) *handle = nullptr;
  try {
    if (!case_file || !handle) throw std::invalid_argument("null case file or handle pointer");
    std::vector<std::string> sets;
    for (int i = 0; i < num_overrides; ++i) {
      if (!overrides || !overrides[i]) throw std::invalid_argument("null override string");
      sets.emplace_back(overrides[i]);
    }
    auto h = std::make_unique<chute_coupling>();
    h->structure =
        std::make_unique<chute::coupling::CouplingInterface>(chute::readCase(case_file, sets));
    *handle = h.release();
    gCreateError.clear();
    return CHUTE_OK;
  } catch (const chute::CaseError& e) {
    gCreateError = e.what();
    return CHUTE_ERROR_INPUT;
  } catch (const std::invalid_argument& e) {
    gCreateError = e.what();
    return CHUTE_ERROR_INPUT;
  } catch (const std::exception& e) {
    gCreateError = e.what();
    return CHUTE_ERROR_INTERNAL;
  } catch (...) {
    gCreateError = "unknown error";
    return CHUTE_ERROR_INTERNAL;
  }
}

void chute_coupling_destroy(chute_coupling* handle) {
  delete handle;
}

const char* chute_coupling_last_error(const chute_coupling* h) {
  return h ? h->lastError.c_str() : gCreateError.c_str();
}

using chute::coupling::CouplingInterface;

int chute_coupling_num_vertices(const chute_coupling* h, int* n) {
  return guarded(h, [&](CouplingInterface& s) {
    if (!n) throw std::invalid_argument("null output");
    *n = s.numVertices();
  });
}
int chute_coupling_num_faces(const chute_coupling* h, int* n) {
  return guarded(h, [&](CouplingInterface& s) {
    if (!n) throw std::invalid_argument("null output");
    *n = s.numFaces();
  });
}
int chute_coupling_face_vertices(const chute_coupling* h, int* faces) {
  return guarded(h, [&](CouplingInterface& s) {
    if (!faces) throw std::invalid_argument("null output array");
    for (int f = 0; f < s.numFaces(); ++f)
      for (int i = 0; i < 4; ++i) faces[4 * f + i] = s.surface().faceVertices[f][i];
  });
}
int chute_coupling_face_sizes(const chute_coupling* h, int* sizes) {
  return guarded(h, [&](CouplingInterface& s) { copyOutInts(s.surface().faceSize, sizes); });
}
int chute_coupling_vertex_nodes(const chute_coupling* h, int* nodes) {
  return guarded(h, [&](CouplingInterface& s) { copyOutInts(s.surface().node, nodes); });
}
int chute_coupling_face_elements(const chute_coupling* h, int* elements) {
  return guarded(h, [&](CouplingInterface& s) { copyOutInts(s.surface().element, elements); });
}
int chute_coupling_num_surface_sets(const chute_coupling* h, int* n) {
  return guarded(h, [&](CouplingInterface& s) {
    if (!n) throw std::invalid_argument("null output");
    *n = static_cast<int>(s.surface().sets.size());
  });
}
int chute_coupling_surface_sets(const chute_coupling* h, int* sets) {
  return guarded(h, [&](CouplingInterface& s) { copyOutInts(s.surface().sets, sets); });
}
int chute_coupling_num_model_nodes(const chute_coupling* h, int* n) {
  return guarded(h, [&](CouplingInterface& s) {
    if (!n) throw std::invalid_argument("null output");
    *n = s.spec().model.numNodes();
  });
}
int chute_coupling_reference_coordinates(const chute_coupling* h, double* xyz) {
  return guarded(h, [&](CouplingInterface& s) { copyOut(s.referenceCoordinates(), xyz); });
}
int chute_coupling_current_coordinates(const chute_coupling* h, double* xyz) {
  return guarded(h, [&](CouplingInterface& s) { copyOut(s.currentCoordinates(), xyz); });
}
int chute_coupling_displacements(const chute_coupling* h, double* xyz) {
  return guarded(h, [&](CouplingInterface& s) { copyOut(s.displacements(), xyz); });
}
int chute_coupling_velocities(const chute_coupling* h, double* xyz) {
  return guarded(h, [&](CouplingInterface& s) { copyOut(s.velocities(), xyz); });
}
int chute_coupling_accelerations(const chute_coupling* h, double* xyz) {
  return guarded(h, [&](CouplingInterface& s) { copyOut(s.accelerations(), xyz); });
}
int chute_coupling_face_normals(const chute_coupling* h, double* xyz) {
  return guarded(h, [&](CouplingInterface& s) { copyOut(s.faceNormals(), xyz); });
}
int chute_coupling_face_areas(const chute_coupling* h, double* areas) {
  return guarded(h, [&](CouplingInterface& s) { copyOut(s.faceAreas(), areas); });
}
int chute_coupling_face_area_vectors(const chute_coupling* h, double* xyz) {
  return guarded(h, [&](CouplingInterface& s) { copyOut(s.faceAreaVectors(), xyz); });
}
int chute_coupling_face_centres(const chute_coupling* h, double* xyz) {
  return guarded(h, [&](CouplingInterface& s) { copyOut(s.faceCentres(), xyz); });
}
int chute_coupling_face_means(const chute_coupling* h, const double* vertex_xyz, double* face_xyz) {
  return guarded(h, [&](CouplingInterface& s) {
    copyOut(s.surface().faceMeans(copyIn(vertex_xyz, 3L * s.numVertices())), face_xyz);
  });
}
int chute_coupling_face_pressures(const chute_coupling* h, double* p) {
  return guarded(h, [&](CouplingInterface& s) { copyOut(s.loads().facePressures(), p); });
}
int chute_coupling_vertex_pressures(const chute_coupling* h, double* p) {
  return guarded(h, [&](CouplingInterface& s) { copyOut(s.loads().vertexPressures(), p); });
}
int chute_coupling_vertex_forces(const chute_coupling* h, double* f) {
  return guarded(h, [&](CouplingInterface& s) { copyOut(s.loads().vertexForces(), f); });
}
int chute_coupling_counters(const chute_coupling* h, long* steps, long* rejected,
                            long* event_retries, long* newton_iterations) {
  return guarded(h, [&](CouplingInterface& s) {
    const auto& c = s.counters();
    if (steps) *steps = c.steps;
    if (rejected) *rejected = c.rejectedSteps;
    if (event_retries) *event_retries = c.eventRetries;
    if (newton_iterations) *newton_iterations = c.newtonIterations;
  });
}
int chute_coupling_gather(const chute_coupling* h, const double* node_xyz, double* vertex_xyz) {
  return guarded(h, [&](CouplingInterface& s) {
    copyOut(s.surface().gather(copyIn(node_xyz, 3L * s.spec().model.numNodes())), vertex_xyz);
  });
}
int chute_coupling_set_face_pressures(chute_coupling* h, const double* p) {
  return guarded(h, [&](CouplingInterface& s) { s.setFacePressures(copyIn(p, s.numFaces())); });
}
int chute_coupling_set_vertex_pressures(chute_coupling* h, const double* p) {
  return guarded(h,
                 [&](CouplingInterface& s) { s.setVertexPressures(copyIn(p, s.numVertices())); });
}
int chute_coupling_set_vertex_forces(chute_coupling* h, const double* f) {
  return guarded(h,
                 [&](CouplingInterface& s) { s.setVertexForces(copyIn(f, 3L * s.numVertices())); });
}
int chute_coupling_initialize_with_loads(chute_coupling* h) {
  return guarded(h, [&](CouplingInterface& s) { s.initializeWithLoads(); });
}
int chute_coupling_time(const chute_coupling* h, double* t) {
  return guarded(h, [&](CouplingInterface& s) {
    if (!t) throw std::invalid_argument("null output");
    *t = s.time();
  });
}
int chute_coupling_preferred_time_step(const chute_coupling* h, double* dt) {
  return guarded(h, [&](CouplingInterface& s) {
    if (!dt) throw std::invalid_argument("null output");
    *dt = s.preferredTimeStep();
  });
}
int chute_coupling_end_time(const chute_coupling* h, double* t) {
  return guarded(h, [&](CouplingInterface& s) {
    if (!t) throw std::invalid_argument("null output");
    *t = s.endTime();
  });
}
int chute_coupling_advance(chute_coupling* h, double dt, double* taken) {
  return guarded(h, [&](CouplingInterface& s) {
    const double step = s.advance(dt);
    if (taken) *taken = step;
  });
}
int chute_coupling_save_checkpoint(chute_coupling* h) {
  return guarded(h, [&](CouplingInterface& s) { s.saveCheckpoint(); });
}
int chute_coupling_restore_checkpoint(chute_coupling* h) {
  return guarded(h, [&](CouplingInterface& s) { s.restoreCheckpoint(); });
}
int chute_coupling_has_checkpoint(const chute_coupling* h, int* saved) {
  return guarded(h, [&](CouplingInterface& s) {
    if (!saved) throw std::invalid_argument("null output");
    *saved = s.hasCheckpoint() ? 1 : 0;
  });
}

}  // extern "C"
