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
  CHUTE_ERROR_SOLVER = 2,  /* the structure could not advance (step below dt_min) */
  CHUTE_ERROR_STATE = 3,   /* e.g. restoring without a saved checkpoint */
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
CHUTE_COUPLING_API int chute_coupling_reference_coordinates(const chute_coupling* h, double* xyz);

/* Write data (writeData): the state at the current time. */
CHUTE_COUPLING_API int chute_coupling_current_coordinates(const chute_coupling* h, double* xyz);
CHUTE_COUPLING_API int chute_coupling_displacements(const chute_coupling* h, double* xyz);
CHUTE_COUPLING_API int chute_coupling_velocities(const chute_coupling* h, double* xyz);
CHUTE_COUPLING_API int chute_coupling_accelerations(const chute_coupling* h, double* xyz);
CHUTE_COUPLING_API int chute_coupling_face_normals(const chute_coupling* h, double* xyz);
CHUTE_COUPLING_API int chute_coupling_face_areas(const chute_coupling* h, double* areas);

/* Read data (readData): loads for the next advance, held over the window. */
CHUTE_COUPLING_API int chute_coupling_set_face_pressures(chute_coupling* h, const double* p);
CHUTE_COUPLING_API int chute_coupling_set_vertex_pressures(chute_coupling* h, const double* p);
CHUTE_COUPLING_API int chute_coupling_set_vertex_forces(chute_coupling* h, const double* f);

/* Time (getMaxTimeStepSize, advance). */
CHUTE_COUPLING_API int chute_coupling_time(const chute_coupling* h, double* t);
CHUTE_COUPLING_API int chute_coupling_preferred_time_step(const chute_coupling* h, double* dt);
CHUTE_COUPLING_API int chute_coupling_end_time(const chute_coupling* h, double* t);
/* Advances by dt (sub-stepping inside); *taken (may be NULL) receives the step taken. */
CHUTE_COUPLING_API int chute_coupling_advance(chute_coupling* h, double dt, double* taken);

/* Checkpoints (requiresWritingCheckpoint / requiresReadingCheckpoint): in-memory deep copies. */
CHUTE_COUPLING_API int chute_coupling_save_checkpoint(chute_coupling* h);
CHUTE_COUPLING_API int chute_coupling_restore_checkpoint(chute_coupling* h);

#ifdef __cplusplus
}
#endif

#endif /* CHUTE_COUPLING_H */
