/*
 * The C and C++ tests' common part (tests/api/c_api/test_c_api.c, test_c_api_cxx.cpp): read a
 * history that export_history.py wrote from an interlock-history HDF5 file, make its material
 * by name, and replay it step by step through the batched update, checking every step's
 * traction and state against the file. C99 and C++ (static functions: one copy per test).
 */
#ifndef C_API_HISTORY_H
#define C_API_HISTORY_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <interlock.h>

/* Agreement asked of every step: |got - expected| <= tol * (the slot's largest magnitude over
   the history); a slot that is 0 all along must be exactly 0. */
#define HISTORY_TOL 1e-13

typedef struct {
  int n_material;
  char names[32][32];
  double values[32];
  int rows, dim, nstatv;
  double *data; /* rows x (2 dim + nstatv): separation, traction, STATEV */
} history_t;

static int history_read(const char *path, history_t *h) {
  FILE *f = fopen(path, "r");
  int i;
  long k, n;
  char word[32];
  if (!f) {
    fprintf(stderr, "cannot open %s\n", path);
    return 0;
  }
  if (fscanf(f, "%31s %d", word, &h->n_material) != 2 || strcmp(word, "material") != 0 ||
      h->n_material > 32) {
    fclose(f);
    return 0;
  }
  for (i = 0; i < h->n_material; ++i) {
    if (fscanf(f, "%31s %lf", h->names[i], &h->values[i]) != 2) {
      fclose(f);
      return 0;
    }
  }
  if (fscanf(f, " rows %d dim %d statev %d", &h->rows, &h->dim, &h->nstatv) != 3) {
    fclose(f);
    return 0;
  }
  n = (long)h->rows * (2 * h->dim + h->nstatv);
  h->data = (double *)malloc(sizeof(double) * (size_t)n);
  for (k = 0; k < n; ++k) {
    if (fscanf(f, "%lf", &h->data[k]) != 1) {
      fclose(f);
      return 0;
    }
  }
  fclose(f);
  return 1;
}

/* The history's material from its property names (interlock_material_from_names). */
static interlock_material *history_material(const history_t *h) {
  const char *names[32];
  interlock_material *m = NULL;
  char message[512];
  int i;
  for (i = 0; i < h->n_material; ++i) names[i] = h->names[i];
  if (interlock_material_from_names(h->dim, h->n_material, names, h->values, &m, message,
                                    sizeof message) != INTERLOCK_OK) {
    fprintf(stderr, "material refused: %s\n", message);
    return NULL;
  }
  return m;
}

/* Replay the history on n_points identical points in one batched update per step (in place:
   state_new = state_old). Every point must be bitwise point 0, point 0 the file to
   HISTORY_TOL; *worst is the largest |got - expected| / scale met. Returns the number of
   failed checks. */
static long history_replay(const interlock_material *m, const history_t *h, size_t n_points,
                           int in_place, double *worst) {
  const int d = h->dim, nsv = h->nstatv, width = 2 * d + nsv;
  const int ns = interlock_state_size(m);
  double *sep, *old_state, *new_state, *traction, *tangent, *fraction, *scale;
  int *status;
  long failures = 0;
  int r, j;
  size_t p;
  *worst = 0.0;
  if (interlock_dim(m) != d || interlock_statev_size(m) != nsv || ns != nsv + 2 * d) {
    fprintf(stderr, "sizes: dim %d statev %d state %d, the file: dim %d statev %d\n",
            interlock_dim(m), interlock_statev_size(m), ns, d, nsv);
    return 1;
  }
  sep = (double *)malloc(sizeof(double) * n_points * d);
  old_state = (double *)malloc(sizeof(double) * n_points * ns);
  new_state = in_place ? old_state : (double *)malloc(sizeof(double) * n_points * ns);
  traction = (double *)malloc(sizeof(double) * n_points * d);
  tangent = (double *)malloc(sizeof(double) * n_points * d * d);
  fraction = (double *)malloc(sizeof(double) * n_points);
  status = (int *)malloc(sizeof(int) * n_points);
  scale = (double *)calloc((size_t)width, sizeof(double));
  for (r = 0; r < h->rows; ++r)
    for (j = 0; j < width; ++j)
      if (fabs(h->data[(long)r * width + j]) > scale[j]) scale[j] = fabs(h->data[(long)r * width + j]);
  if (interlock_state_init(m, 0, n_points, old_state) != INTERLOCK_OK) {
    fprintf(stderr, "state_init failed\n");
    return 1;
  }
  for (r = 0; r < h->rows; ++r) {
    const double *row = h->data + (long)r * width;
    size_t failed;
    for (p = 0; p < n_points; ++p) memcpy(sep + p * d, row, sizeof(double) * d);
    failed = interlock_update(m, n_points, sep, old_state, new_state, traction, tangent, status,
                              fraction);
    if (failed != 0) {
      char message[512];
      interlock_update_message(m, sep, old_state, message, sizeof message);
      fprintf(stderr, "step %d: %zu points failed, status %d: %s\n", r, failed, status[0], message);
      ++failures;
      break;
    }
    for (j = 0; j < width; ++j) {
      /* separation and traction (in the state too), then STATEV */
      double got = j < d ? new_state[nsv + j] : j < 2 * d ? traction[j - d] : new_state[j - 2 * d];
      double expected = row[j];
      double err = fabs(got - expected);
      if (scale[j] > 0.0) {
        if (err / scale[j] > *worst) *worst = err / scale[j];
        if (err > HISTORY_TOL * scale[j]) {
          if (failures < 10)
            fprintf(stderr, "step %d, column %d: %.17g, expected %.17g\n", r, j, got, expected);
          ++failures;
        }
      } else if (got != 0.0) {
        if (failures < 10) fprintf(stderr, "step %d, column %d: %.17g, expected 0\n", r, j, got);
        ++failures;
      }
    }
    for (j = 0; j < d; ++j) {
      if (memcmp(&traction[j], &new_state[nsv + d + j], sizeof(double)) != 0) {
        fprintf(stderr, "step %d: the state's traction is not the traction\n", r);
        ++failures;
      }
    }
    for (p = 1; p < n_points; ++p) {
      if (memcmp(new_state + p * ns, new_state, sizeof(double) * ns) != 0 ||
          memcmp(traction + p * d, traction, sizeof(double) * d) != 0 ||
          memcmp(tangent + p * d * d, tangent, sizeof(double) * d * d) != 0 ||
          memcmp(&fraction[p], &fraction[0], sizeof(double)) != 0 || status[p] != status[0]) {
        fprintf(stderr, "step %d: point %zu differs from point 0\n", r, p);
        ++failures;
        break;
      }
    }
    if (!in_place) {
      double *swap = old_state;
      old_state = new_state;
      new_state = swap;
    }
  }
  free(sep);
  free(old_state);
  if (!in_place) free(new_state);
  free(traction);
  free(tangent);
  free(fraction);
  free(status);
  free(scale);
  return failures;
}

#endif
