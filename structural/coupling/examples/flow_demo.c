/* flow_demo.c: a flow solver written in C driving chute through libchute_coupling.so.
 *
 * The "flow solver" is the quasi-steady law of the coupled demo,
 *   p = q(t) - rho_air (C_n/2 v_n |v_n| + L_a a_n),
 * evaluated from what the structure writes (vertex velocities and accelerations, face normals).
 * Implicit coupling with Aitken under-relaxation and a checkpoint per window, as a preCICE
 * serial-implicit scheme would drive it. Also checks the C interface's error paths and that a
 * restored window is repeated bit for bit. Exit status 0 when every check passes.
 *
 *   build/bin/flow_demo cases/canopy_coupled.toml [windows]
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

typedef struct {
  int nv, nf;
  int* faces;
  double *vel, *acc, *normal, *pIn, *pOut, *r, *rPrev;
} Flow;

/* The flow participant: face pressures from the structure's state at time t. */
static void flowSolve(chute_coupling* h, Flow* f, double t, double* p) {
  const double q = 60.0, ramp = 0.002, rho = 1.2, cn = 1.0, la = 0.03;
  CALL(h, chute_coupling_velocities(h, f->vel));
  CALL(h, chute_coupling_accelerations(h, f->acc));
  CALL(h, chute_coupling_face_normals(h, f->normal));
  for (int e = 0; e < f->nf; ++e) {
    double v[3] = {0, 0, 0}, a[3] = {0, 0, 0};
    int n = f->faces[4 * e + 3] < 0 ? 3 : 4;
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) {
        v[k] += f->vel[3 * f->faces[4 * e + i] + k] / n;
        a[k] += f->acc[3 * f->faces[4 * e + i] + k] / n;
      }
    const double* nn = f->normal + 3 * e;
    double vn = v[0] * nn[0] + v[1] * nn[1] + v[2] * nn[2];
    double an = a[0] * nn[0] + a[1] * nn[1] + a[2] * nn[2];
    double qt = t < ramp ? q * t / ramp : q;
    p[e] = qt - rho * (0.5 * cn * vn * fabs(vn) + la * an);
  }
}

static double norm(const double* x, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += x[i] * x[i];
  return sqrt(s);
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s CASE.toml [windows]\n", argv[0]);
    return 2;
  }
  const int windows = argc > 2 ? atoi(argv[2]) : 10;

  /* Errors come back as codes and messages, never as exceptions. */
  chute_coupling* bad = NULL;
  int status = chute_coupling_create("/nonexistent/case.toml", NULL, 0, &bad);
  printf("create(missing file): status %d, \"%s\"\n", status, chute_coupling_last_error(NULL));
  CHECK(status == CHUTE_ERROR_INPUT && bad == NULL, "missing case file not reported");

  const char* overrides[] = {"membranes.0.rings=3"};
  chute_coupling* h = NULL;
  CALL(NULL, chute_coupling_create(argv[1], overrides, 1, &h));
  CHECK(chute_coupling_restore_checkpoint(h) == CHUTE_ERROR_STATE,
        "restore without a checkpoint not reported");
  printf("restore before save: \"%s\"\n", chute_coupling_last_error(h));

  Flow f;
  CALL(h, chute_coupling_num_vertices(h, &f.nv));
  CALL(h, chute_coupling_num_faces(h, &f.nf));
  f.faces = malloc(sizeof(int) * 4 * f.nf);
  f.vel = malloc(sizeof(double) * 3 * f.nv);
  f.acc = malloc(sizeof(double) * 3 * f.nv);
  f.normal = malloc(sizeof(double) * 3 * f.nf);
  f.pIn = malloc(sizeof(double) * f.nf);
  f.pOut = malloc(sizeof(double) * f.nf);
  f.r = malloc(sizeof(double) * f.nf);
  f.rPrev = malloc(sizeof(double) * f.nf);
  double* x0 = malloc(sizeof(double) * 3 * f.nv);
  double* xa = malloc(sizeof(double) * 3 * f.nv);
  double* xb = malloc(sizeof(double) * 3 * f.nv);
  double* u = malloc(sizeof(double) * 3 * f.nv);
  CALL(h, chute_coupling_face_vertices(h, f.faces));
  CALL(h, chute_coupling_reference_coordinates(h, x0));
  double dt, t;
  CALL(h, chute_coupling_preferred_time_step(h, &dt));
  CALL(h, chute_coupling_time(h, &t));
  printf("wet surface: %d vertices, %d faces; window %g s\n", f.nv, f.nf, dt);

  flowSolve(h, &f, t, f.pIn);
  long total = 0;
  for (int w = 0; w < windows; ++w) {
    CALL(h, chute_coupling_save_checkpoint(h)); /* requiresWritingCheckpoint */
    double omega = 0.5, res = 1.0, taken = 0.0;
    int k;
    for (k = 0; k < 100; ++k) {
      CALL(h, chute_coupling_set_face_pressures(h, f.pIn)); /* readData */
      CALL(h, chute_coupling_advance(h, dt, &taken));
      flowSolve(h, &f, t + dt, f.pOut); /* writeData -> the flow's solve */
      for (int e = 0; e < f.nf; ++e) f.r[e] = f.pOut[e] - f.pIn[e];
      res = norm(f.r, f.nf) / (norm(f.pOut, f.nf) > 0 ? norm(f.pOut, f.nf) : 1.0);
      if (res <= 1e-10) break;
      if (k > 0) { /* Aitken */
        double d2 = 0, num = 0;
        for (int e = 0; e < f.nf; ++e) {
          double dr = f.r[e] - f.rPrev[e];
          d2 += dr * dr;
          num += f.rPrev[e] * dr;
        }
        if (d2 > 0) omega = -omega * num / d2;
      }
      for (int e = 0; e < f.nf; ++e) f.pIn[e] += omega * f.r[e], f.rPrev[e] = f.r[e];
      CALL(h, chute_coupling_restore_checkpoint(h)); /* requiresReadingCheckpoint */
    }
    CHECK(res <= 1e-10, "window %d did not converge (residual %.3e)", w + 1, res);
    CHECK(taken == dt, "advance took %g instead of %g", taken, dt);
    total += k + 1;
    t += dt;
    /* Repeat the converged window from its checkpoint: bit for bit. */
    CALL(h, chute_coupling_current_coordinates(h, xa));
    CALL(h, chute_coupling_restore_checkpoint(h));
    CALL(h, chute_coupling_set_face_pressures(h, f.pIn));
    CALL(h, chute_coupling_advance(h, dt, NULL));
    CALL(h, chute_coupling_current_coordinates(h, xb));
    CHECK(memcmp(xa, xb, sizeof(double) * 3 * f.nv) == 0, "window %d not repeated exactly", w + 1);
    CALL(h, chute_coupling_displacements(h, u));
    double uz = 0;
    for (int v = 0; v < f.nv; ++v) uz = fabs(u[3 * v + 2]) > fabs(uz) ? u[3 * v + 2] : uz;
    printf("window %3d  t = %.5f  sub-iterations %2d  residual %.2e  max |u_z| %.6f m\n", w + 1, t,
           k + 1, res, uz);
  }
  printf("%ld structural solves over %d windows (%.2f per window); %s\n", total, windows,
         (double)total / windows, failures ? "CHECKS FAILED" : "all checks passed");
  chute_coupling_destroy(h);
  free(f.faces), free(f.vel), free(f.acc), free(f.normal), free(f.pIn), free(f.pOut);
  free(f.r), free(f.rPrev), free(x0), free(xa), free(xb), free(u);
  return failures ? 1 : 0;
}
