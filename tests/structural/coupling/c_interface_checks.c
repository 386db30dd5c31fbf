/* c_interface_checks.c: the C interface (chute_coupling.h) checked from C, as a flow solver in C
 * sees it: every wet-surface accessor against what it must equal (face centres and means against
 * the vertex data averaged here, area vectors against areas and normals, sizes against the
 * connectivity, the loads read back as set), the call-order rules (initial data, checkpoints),
 * the counters, and a window that fails: CHUTE_ERROR_SOLVER leaves the structure where the window
 * started and the next advance goes on from there. Prints what it measured; exit 0 when every
 * check passes.
 *
 *   build/bin/c_interface_checks cases/canopy_coupled.toml
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chute_coupling.h"

static int failures = 0;
#define CHECK(cond, ...)                       \
  do {                                         \
    if (!(cond)) {                             \
      fprintf(stderr, "FAILED: " __VA_ARGS__); \
      fprintf(stderr, "\n");                   \
      ++failures;                              \
    }                                          \
  } while (0)
#define CALL(h, expr)                                                                        \
  do {                                                                                       \
    int status_ = (expr);                                                                    \
    if (status_ != CHUTE_OK) {                                                               \
      fprintf(stderr, "%s failed (%d): %s\n", #expr, status_, chute_coupling_last_error(h)); \
      exit(1);                                                                               \
    }                                                                                        \
  } while (0)

static double* doubles(int n) {
  return calloc((size_t)(n > 0 ? n : 1), sizeof(double));
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s CASE.toml\n", argv[0]);
    return 2;
  }
  const char* overrides[] = {"membranes.0.rings=3"};
  chute_coupling* h = NULL;
  CALL(NULL, chute_coupling_create(argv[1], overrides, 1, &h));
  int nv = 0, nf = 0;
  CALL(h, chute_coupling_num_vertices(h, &nv));
  CALL(h, chute_coupling_num_faces(h, &nf));
  int* faces = malloc(sizeof(int) * 4 * (size_t)nf);
  int* sizes = malloc(sizeof(int) * (size_t)nf);
  int* nodes = malloc(sizeof(int) * (size_t)nv);
  int* elements = malloc(sizeof(int) * (size_t)nf);
  double *x = doubles(3 * nv), *v = doubles(3 * nv), *centres = doubles(3 * nf),
         *means = doubles(3 * nf), *av = doubles(3 * nf), *areas = doubles(nf),
         *normals = doubles(3 * nf), *p = doubles(nf), *pBack = doubles(nf), *vp = doubles(nv),
         *vf = doubles(3 * nv), *back = doubles(3 * nv), *before = doubles(3 * nv),
         *after = doubles(3 * nv);
  CALL(h, chute_coupling_face_vertices(h, faces));
  CALL(h, chute_coupling_face_sizes(h, sizes));
  CALL(h, chute_coupling_vertex_nodes(h, nodes));
  CALL(h, chute_coupling_face_elements(h, elements));
  printf("wet surface: %d vertices, %d faces\n", nv, nf);

  /* Sizes and ids against the connectivity. */
  for (int f = 0; f < nf; ++f) {
    CHECK(sizes[f] == (faces[4 * f + 3] < 0 ? 3 : 4), "face %d: size %d", f, sizes[f]);
    CHECK(f == 0 || elements[f] > elements[f - 1], "face elements not distinct and ordered");
  }
  for (int i = 1; i < nv; ++i) CHECK(nodes[i] > nodes[i - 1], "vertex nodes not ascending");

  /* A window of motion first, so that the geometry is not the flat start. */
  double dt = 0.0, t0 = 0.0, t = 0.0;
  CALL(h, chute_coupling_preferred_time_step(h, &dt));
  for (int f = 0; f < nf; ++f) p[f] = 40.0;
  CALL(h, chute_coupling_set_face_pressures(h, p));
  CALL(h, chute_coupling_initialize_with_loads(h)); /* initial data: allowed before advancing */
  CALL(h, chute_coupling_advance(h, 4 * dt, NULL));
  CHECK(chute_coupling_initialize_with_loads(h) == CHUTE_ERROR_STATE,
        "initialize_with_loads after an advance not refused");

  /* Face centres and face means: the mean of the face's vertices, averaged here. */
  CALL(h, chute_coupling_current_coordinates(h, x));
  CALL(h, chute_coupling_velocities(h, v));
  CALL(h, chute_coupling_face_centres(h, centres));
  CALL(h, chute_coupling_face_means(h, v, means));
  double centreError = 0.0, meanError = 0.0, scale = 0.0, vscale = 0.0;
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      double c = 0.0, m = 0.0;
      for (int i = 0; i < sizes[f]; ++i) {
        c += x[3 * faces[4 * f + i] + k];
        m += v[3 * faces[4 * f + i] + k];
      }
      c /= sizes[f], m /= sizes[f];
      centreError = fmax(centreError, fabs(c - centres[3 * f + k]));
      meanError = fmax(meanError, fabs(m - means[3 * f + k]));
      scale = fmax(scale, fabs(c));
      vscale = fmax(vscale, fabs(m));
    }
  printf("face centres: largest difference from the vertex mean %.3e (coordinates up to %.3g)\n",
         centreError, scale);
  printf("face means of the velocities: largest difference %.3e (velocities up to %.3g)\n",
         meanError, vscale);
  CHECK(centreError <= 1e-15 * scale, "face centres are not the vertex means");
  CHECK(meanError <= 1e-15 * vscale + 1e-300, "face means are not the vertex means");

  /* Area vectors: |A| n, their length the face area, their direction the face normal. */
  CALL(h, chute_coupling_face_area_vectors(h, av));
  CALL(h, chute_coupling_face_areas(h, areas));
  CALL(h, chute_coupling_face_normals(h, normals));
  double areaError = 0.0, normalError = 0.0;
  for (int f = 0; f < nf; ++f) {
    const double* a = av + 3 * f;
    const double len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    areaError = fmax(areaError, fabs(len - areas[f]) / areas[f]);
    for (int k = 0; k < 3; ++k)
      normalError = fmax(normalError, fabs(a[k] / len - normals[3 * f + k]));
  }
  printf("area vectors: |A| against the areas %.3e (relative), A/|A| against the normals %.3e\n",
         areaError, normalError);
  CHECK(areaError <= 1e-14 && normalError <= 1e-14, "area vectors disagree with areas/normals");

  /* The loads read back exactly as set. */
  for (int f = 0; f < nf; ++f) p[f] = 10.0 + 0.25 * f;
  for (int i = 0; i < nv; ++i) vp[i] = -1.0 - 0.5 * i;
  for (int i = 0; i < 3 * nv; ++i) vf[i] = 1e-3 * i;
  CALL(h, chute_coupling_set_face_pressures(h, p));
  CALL(h, chute_coupling_set_vertex_pressures(h, vp));
  CALL(h, chute_coupling_set_vertex_forces(h, vf));
  CALL(h, chute_coupling_face_pressures(h, pBack));
  CHECK(memcmp(p, pBack, sizeof(double) * (size_t)nf) == 0, "face pressures not read back");
  CALL(h, chute_coupling_vertex_pressures(h, back));
  CHECK(memcmp(vp, back, sizeof(double) * (size_t)nv) == 0, "vertex pressures not read back");
  CALL(h, chute_coupling_vertex_forces(h, back));
  CHECK(memcmp(vf, back, sizeof(double) * 3 * (size_t)nv) == 0, "vertex forces not read back");
  memset(vp, 0, sizeof(double) * (size_t)nv);
  memset(vf, 0, sizeof(double) * 3 * (size_t)nv);
  CALL(h, chute_coupling_set_vertex_pressures(h, vp));
  CALL(h, chute_coupling_set_vertex_forces(h, vf));

  /* Checkpoint flag and counters. */
  int saved = -1;
  CALL(h, chute_coupling_has_checkpoint(h, &saved));
  CHECK(saved == 0, "has_checkpoint before a save");
  CALL(h, chute_coupling_save_checkpoint(h));
  CALL(h, chute_coupling_has_checkpoint(h, &saved));
  CHECK(saved == 1, "has_checkpoint after a save");
  long steps0 = 0, steps1 = 0, rejected = 0, retries = 0, newton = 0;
  CALL(h, chute_coupling_counters(h, &steps0, NULL, NULL, NULL));
  CALL(h, chute_coupling_advance(h, dt, NULL));
  CALL(h, chute_coupling_counters(h, &steps1, &rejected, &retries, &newton));
  printf(
      "counters: %ld steps (%ld before this window), %ld rejected, %ld event retries, %ld "
      "Newton iterations\n",
      steps1, steps0, rejected, retries, newton);
  CHECK(steps1 == steps0 + 1 && newton > 0, "counters did not count the window");

  /* A window that fails (a face pressure no structure can carry): CHUTE_ERROR_SOLVER, the state
   * of the window's start kept, and the next advance with sane loads goes on from there. */
  CALL(h, chute_coupling_time(h, &t0));
  CALL(h, chute_coupling_current_coordinates(h, before));
  for (int f = 0; f < nf; ++f) p[f] = 1e300;
  CALL(h, chute_coupling_set_face_pressures(h, p));
  const int status = chute_coupling_advance(h, dt, NULL);
  printf("advance under 1e300 Pa: status %d, \"%s\"\n", status, chute_coupling_last_error(h));
  CHECK(status == CHUTE_ERROR_SOLVER, "the impossible window did not fail with CHUTE_ERROR_SOLVER");
  CALL(h, chute_coupling_time(h, &t));
  CALL(h, chute_coupling_current_coordinates(h, after));
  CHECK(t == t0, "time moved to %.17g after the failed window (was %.17g)", t, t0);
  CHECK(memcmp(before, after, sizeof(double) * 3 * (size_t)nv) == 0,
        "positions changed by the failed window");
  for (int f = 0; f < nf; ++f) p[f] = 40.0;
  CALL(h, chute_coupling_set_face_pressures(h, p));
  const int next = chute_coupling_advance(h, dt, NULL);
  CALL(h, chute_coupling_time(h, &t));
  printf("next advance with 40 Pa: status %d, t = %.9g (window start %.9g)\n", next, t, t0);
  CHECK(next == CHUTE_OK && fabs(t - (t0 + dt)) <= 1e-12 * dt,
        "the advance after a failed window did not go on from the window's start");

  chute_coupling_destroy(h);
  free(faces), free(sizes), free(nodes), free(elements);
  free(x), free(v), free(centres), free(means), free(av), free(areas), free(normals), free(p);
  free(pBack), free(vp), free(vf), free(back), free(before), free(after);
  printf("%s\n", failures ? "C interface checks FAILED" : "C interface checks passed");
  return failures ? 1 : 0;
}
