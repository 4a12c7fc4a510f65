/* The example of docs/c-api.md, built against the installed library and run as a test: a 3D
   joint of the granite set with the azimuthal RIA (3 azimuths), 8 interface points pressed to
   s_N = -0.024 mm (sigma_N ~ -1.4 MPa) over pseudo-time 0 .. 0.2, then slid 0.4 mm along t1
   and t2, in increments of 0.01 through the batched update; an increment is retried with the
   smallest step fraction the points ask for. */
#include <stdio.h>
#include <stdlib.h>

#include <interlock.h>

#define N_POINTS 8

int main(void) {
  const char *names[] = {"sigma0_n", "sigma0_t", "gc",         "eta",        "mu",  "h_n",
                         "theta0_deg", "thetaf_deg", "zeta0", "ria", "n_azimuths"};
  const double values[] = {0.025, 0.025, 0.0005, 0.99, 0.6898538, 4.0, 30.0, 9.0, 6.666, 1, 3};
  char message[512];
  interlock_material *m = NULL;
  if (interlock_material_from_names(3, 11, names, values, &m, message, sizeof message) !=
      INTERLOCK_OK) {
    fprintf(stderr, "material refused: %s\n", message);
    return 1;
  }
  const int dim = interlock_dim(m), ns = interlock_state_size(m);
  double *state = malloc(sizeof(double) * N_POINTS * ns);
  double *trial = malloc(sizeof(double) * N_POINTS * ns);
  double separation[N_POINTS * 3], traction[N_POINTS * 3], tangent[N_POINTS * 9];
  double fraction[N_POINTS];
  int status[N_POINTS];
  interlock_state_init(m, 0, N_POINTS, state);  /* virgin */

  double t = 0.0, dt = 0.01;                    /* pseudo-time 0 .. 1 */
  while (t < 1.0) {
    if (t + dt > 1.0) dt = 1.0 - t;
    const double end = t + dt, slip = end > 0.2 ? 0.5 * (end - 0.2) : 0.0;
    for (int p = 0; p < N_POINTS; ++p) {        /* the separations at the increment's end */
      separation[p * dim + 0] = end < 0.2 ? -0.024 * end / 0.2 : -0.024;
      separation[p * dim + 1] = slip * (1.0 + 0.01 * p);
      separation[p * dim + 2] = slip;
    }
    size_t failed = interlock_update(m, N_POINTS, separation, state, trial, traction, tangent,
                                     status, fraction);
    double smallest = 1.0;                      /* the cut the points ask for */
    for (int p = 0; p < N_POINTS; ++p)
      if (fraction[p] < smallest) smallest = fraction[p];
    if (failed > 0 || smallest < 1.0) {
      for (int p = 0; p < N_POINTS; ++p) {
        if (status[p] == INTERLOCK_BAD_INPUT) { /* no cut helps: stop, saying why */
          interlock_update_message(m, separation + p * dim, state + p * ns, message,
                                   sizeof message);
          fprintf(stderr, "point %d: %s\n", p, message);
          return 1;
        }
      }
      dt *= smallest;                           /* retry a shorter increment */
      if (dt < 1e-9) {
        fprintf(stderr, "increment below 1e-9 at t = %g\n", t);
        return 1;
      }
      continue;
    }
    double *swap = state;                       /* accept: the trial state is the state */
    state = trial;
    trial = swap;
    t += dt;
    dt = 0.01;
  }
  printf("traction of point 0 at s = (%g, %g, %g) mm: (%.6f, %.6f, %.6f) MPa\n", separation[0],
         separation[1], separation[2], traction[0], traction[1], traction[2]);
  free(state);
  free(trial);
  interlock_material_free(m);
  return 0;
}
