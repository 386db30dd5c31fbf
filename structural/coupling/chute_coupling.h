/* chute_coupling.h: C interface to chute as the structural participant of a partitioned
 * fluid-structure simulation (libchute_coupling.so). For flow solvers in C, Fortran (bind(C)) or
 * Python (ctypes). Over chute::coupling::CouplingInterface; the preCICE call each function sits
 * next to in an adapter is named in its comment.
 *
 * Every function returns CHUTE_OK (0) or an error code; chute_coupling_last_error() gives the
 * message. No C++ exception crosses this interface. Arrays are caller-allocated and laid out
 * vertex-major: 3 doubles (x, y, z) per vertex or face, or 1 per vertex or face. */
#ifndef CHUTE_COUPLING_H
#define CHUTE_COUPLING_H

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
#define CHUTE_COUPLING_API __attribute__((visibility("default")))
#else
#define CHUTE_COUPLING_API
#endif

enum chute_status {
  CHUTE_OK = 0,
  CHUTE_ERROR_INPUT = 1,   /* bad case file, argument or array size */
  CHUTE_ERROR_SOLVER = 2,  /* the structure could not advance (a step below dt_min: the state
                              is back at the window's start), or a window refused */
  CHUTE_ERROR_STATE = 3,   /* a call out of order: restoring without a saved checkpoint,
                              initializing with loads after the first advance */
  CHUTE_ERROR_INTERNAL = 4 /* anything else */
};

typedef struct chute_coupling chute_coupling; /* opaque handle */

/* Reads a dynamic case file (overrides: "dotted.key=value" strings as `chute run --set`, may be
 * NULL) and initialises the structure (preCICE: before initialize()). The wet surface is every
 * membrane of the case; the case's pressure on it is dropped (the flow solver supplies it).
 * On failure *handle is NULL and the message is in chute_coupling_last_error(NULL). */
CHUTE_COUPLING_API int chute_coupling_create(const char* case_file, const char* const* overrides,
                                             int num_overrides, chute_coupling** handle);
CHUTE_COUPLING_API void chute_coupling_destroy(chute_coupling* handle);
/* The last error on this handle, or of the last failed create (handle NULL). Never NULL. */
CHUTE_COUPLING_API const char* chute_coupling_last_error(const chute_coupling* handle);

/* Mesh (setMeshVertices, setMeshTriangles, setMeshQuads). */
CHUTE_COUPLING_API int chute_coupling_num_vertices(const chute_coupling* h, int* n);
CHUTE_COUPLING_API int chute_coupling_num_faces(const chute_coupling* h, int* n);
/* 4 vertex indices per face, the 4th -1 for a triangle. */
CHUTE_COUPLING_API int chute_coupling_face_vertices(const chute_coupling* h, int* faces);
/* 1 per face: 3 (triangle) or 4 (quadrilateral). */
CHUTE_COUPLING_API int chute_coupling_face_sizes(const chute_coupling* h, int* sizes);
/* 1 per vertex: the model node it is (0-based, in the order of the case's nodes and mesh). */
CHUTE_COUPLING_API int chute_coupling_vertex_nodes(const chute_coupling* h, int* nodes);
/* 1 per face: the model membrane element it is (0-based). */
CHUTE_COUPLING_API int chute_coupling_face_elements(const chute_coupling* h, int* elements);
CHUTE_COUPLING_API int chute_coupling_reference_coordinates(const chute_coupling* h, double* xyz);
/* 1 per face: 3 (triangle) or 4 (quadrilateral). */
CHUTE_COUPLING_API int chute_coupling_face_sizes(const chute_coupling* h, int* sizes);
/* 1 per vertex: the model node it is (0-based, ascending), as chute's own output numbers nodes. */
CHUTE_COUPLING_API int chute_coupling_vertex_nodes(const chute_coupling* h, int* nodes);
/* 1 per face: the model membrane element it is (0-based). */
CHUTE_COUPLING_API int chute_coupling_face_elements(const chute_coupling* h, int* elements);
/* The membrane sets the surface covers (indices into the case's [[membranes]], 0-based). */
CHUTE_COUPLING_API int chute_coupling_num_surface_sets(const chute_coupling* h, int* n);
CHUTE_COUPLING_API int chute_coupling_surface_sets(const chute_coupling* h, int* sets);
/* The number of model nodes: the size / 3 of the full vectors chute_coupling_gather takes. */
CHUTE_COUPLING_API int chute_coupling_num_model_nodes(const chute_coupling* h, int* n);

/* Write data (writeData): the state at the current time. */
CHUTE_COUPLING_API int chute_coupling_current_coordinates(const chute_coupling* h, double* xyz);
CHUTE_COUPLING_API int chute_coupling_displacements(const chute_coupling* h, double* xyz);
CHUTE_COUPLING_API int chute_coupling_velocities(const chute_coupling* h, double* xyz);
CHUTE_COUPLING_API int chute_coupling_accelerations(const chute_coupling* h, double* xyz);
CHUTE_COUPLING_API int chute_coupling_face_normals(const chute_coupling* h, double* xyz);
CHUTE_COUPLING_API int chute_coupling_face_areas(const chute_coupling* h, double* areas);
/* 3 per face: |A| n, the area times the unit normal (the force of a unit pressure). */
CHUTE_COUPLING_API int chute_coupling_face_area_vectors(const chute_coupling* h, double* xyz);
/* 3 per face: the mean of its current vertex positions (where a face value sits). */
CHUTE_COUPLING_API int chute_coupling_face_centres(const chute_coupling* h, double* xyz);

/* Helpers on the surface's layout (no state read or changed). */
/* 3 per face out: the face means (1/N) sum_i of 3-per-vertex values in (e.g. face velocities). */
CHUTE_COUPLING_API int chute_coupling_face_means(const chute_coupling* h, const double* vertex_xyz,
                                                 double* face_xyz);
/* 3 per vertex out: the surface's values of a full 3-per-model-node vector in. */
CHUTE_COUPLING_API int chute_coupling_gather(const chute_coupling* h, const double* node_xyz,
                                             double* vertex_xyz);

/* Read data (readData): loads for the next advance, held over the window. */
CHUTE_COUPLING_API int chute_coupling_set_face_pressures(chute_coupling* h, const double* p);
CHUTE_COUPLING_API int chute_coupling_set_vertex_pressures(chute_coupling* h, const double* p);
CHUTE_COUPLING_API int chute_coupling_set_vertex_forces(chute_coupling* h, const double* f);
/* The loads held for the next advance, as last set (zero before any). */
CHUTE_COUPLING_API int chute_coupling_face_pressures(const chute_coupling* h, double* p);
CHUTE_COUPLING_API int chute_coupling_vertex_pressures(const chute_coupling* h, double* p);
CHUTE_COUPLING_API int chute_coupling_vertex_forces(const chute_coupling* h, double* f);
/* preCICE's initial data: before the first advance, the loads set now act from t = 0 and the
 * start's acceleration is recomputed under them. CHUTE_ERROR_STATE after the first advance. */
CHUTE_COUPLING_API int chute_coupling_initialize_with_loads(chute_coupling* h);

/* Time (getMaxTimeStepSize, advance). */
CHUTE_COUPLING_API int chute_coupling_time(const chute_coupling* h, double* t);
CHUTE_COUPLING_API int chute_coupling_preferred_time_step(const chute_coupling* h, double* dt);
CHUTE_COUPLING_API int chute_coupling_end_time(const chute_coupling* h, double* t);
/* Advances by dt (sub-stepping inside); *taken (may be NULL) receives the step taken.
 * CHUTE_ERROR_SOLVER: a step fell below dt_min. The structure is then restored to the state it
 * had when this advance was called (time, positions, velocities, every history: the end of the
 * last good window), so the next advance, with other loads or a shorter dt, starts from there;
 * no checkpoint needs to be restored. A dt that is not positive and finite, too short to move
 * time or longer than 1e9 steps of dt_min is refused the same way and changes nothing. */
CHUTE_COUPLING_API int chute_coupling_advance(chute_coupling* h, double dt, double* taken);
/* Steps taken so far by all advances, steps rejected (and retried shorter), steps cut at an
 * event, Newton iterations; any pointer may be NULL. */
CHUTE_COUPLING_API int chute_coupling_counters(const chute_coupling* h, long* steps, long* rejected,
                                               long* event_retries, long* newton_iterations);

/* Checkpoints (requiresWritingCheckpoint / requiresReadingCheckpoint): in-memory deep copies. */
CHUTE_COUPLING_API int chute_coupling_save_checkpoint(chute_coupling* h);
CHUTE_COUPLING_API int chute_coupling_restore_checkpoint(chute_coupling* h);
/* *saved = 1 once a checkpoint has been saved, else 0. */
CHUTE_COUPLING_API int chute_coupling_has_checkpoint(const chute_coupling* h, int* saved);

#ifdef __cplusplus
}
#endif

#endif /* CHUTE_COUPLING_H */
