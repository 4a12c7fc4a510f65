/*
 * The C API from C (include/interlock.h, the shared library interlock::interlock_c), built
 * against the installed prefix:
 *   - a 3D deck's history and a 2D deck's history (interlock-history's HDF5 files, exported by
 *     export_history.py) reproduced step by step through the batched update, to 1e-13 of each
 *     value's scale, out of place and in place, 3 points per call;
 *   - garbage refused: bad PROPS and names (each with its message), NULL pointers, n = 0,
 *     NaN/Inf/huge separations, out-of-range state values, each with its status and step
 *     fraction and the point's outputs untouched, the good points of the same batch updated;
 *   - the material description (the table's names, units, ranges).
 * usage: test_c_api HISTORY_3D.txt HISTORY_2D.txt
 * With INTERLOCK_TEST_TRAPS (Debug) the floating-point traps are on, as in the Fortran suites.
 */
#define _GNU_SOURCE
#include <fenv.h>

#include "c_api_history.h"

static long failures = 0;

static void check(int ok, const char *what) {
  if (!ok) {
    ++failures;
    fprintf(stderr, "FAILED: %s\n", what);
  }
}

/* A refusal: status BAD_INPUT, *m NULL, the message contains `needle`. */
static void check_refused(int status, const interlock_material *m, const char *message,
                          const char *needle, const char *what) {
  printf("%s: %s\n", what, message);
  check(status == INTERLOCK_BAD_INPUT, what);
  check(m == NULL, "a refused material is NULL");
  check(strstr(message, needle) != NULL, needle);
}

static const double granite[11] = {0.025, 0.025, 0.0005, 0.99, 0.6898538, 4.0, 30.0, 9.0, 6.666,
                                   0.0,   3.0};

static void materials_refused(void) {
  double props[22];
  char message[512];
  char small[10];
  interlock_material *m = (interlock_material *)&failures; /* must come back NULL */
  int status;
  const char *names[3] = {"sigma0_n", "no_such_property", "eta"};
  const char *required[2] = {"sigma0_n", "eta"};
  const char *twice[10] = {"sigma0_n", "sigma0_t", "gc", "eta", "mu", "h_n", "theta0_deg",
                           "thetaf_deg", "zeta0", "eta"};
  const char *nine[9] = {"sigma0_n", "sigma0_t", "gc", "eta", "mu", "h_n", "theta0_deg",
                         "thetaf_deg", "zeta0"};
  double values[10];
  memcpy(props, granite, sizeof granite);
  memcpy(values, granite, 9 * sizeof(double));
  values[9] = 0.5;

  props[3] = 2.0;
  status = interlock_material_from_props(3, 11, props, &m, message, sizeof message);
  check_refused(status, m, message, "PROPS(4): property 'eta' = 2 is inadmissible", "eta = 2");
  props[3] = NAN;
  m = (interlock_material *)&failures;
  status = interlock_material_from_props(3, 11, props, &m, message, sizeof message);
  check_refused(status, m, message, "'eta' = NaN", "eta = NaN");
  props[3] = 0.99;
  props[5] = -INFINITY;
  status = interlock_material_from_props(2, 11, props, &m, message, sizeof message);
  check_refused(status, m, message, "'h_n'", "h_n = -Inf");
  props[5] = 4.0;
  status = interlock_material_from_props(3, 5, props, &m, message, sizeof message);
  check_refused(status, m, message, "NPROPS = 5", "NPROPS = 5");
  status = interlock_material_from_props(3, 23, props, &m, message, sizeof message);
  check_refused(status, m, message, "NPROPS = 23", "NPROPS = 23");
  status = interlock_material_from_props(3, 11, NULL, &m, message, sizeof message);
  check_refused(status, m, message, "NULL", "props NULL");
  status = interlock_material_from_props(4, 11, props, &m, message, sizeof message);
  check_refused(status, m, message, "dim = 4", "dim = 4");
  status = interlock_material_from_props(3, 11, props, NULL, message, sizeof message);
  check(status == INTERLOCK_BAD_INPUT, "a NULL handle address is refused");
  /* the azimuthal RIA needs a 3D interface */
  memcpy(props, granite, sizeof granite);
  props[11] = 0.0; props[12] = 0.25; props[13] = 1.0; props[14] = 1.0; props[15] = 1.0;
  props[16] = 1.0; props[17] = 1.0; props[18] = 1.0; props[19] = 1.0; props[20] = 1.0;
  status = interlock_material_from_props(2, 21, props, &m, message, sizeof message);
  check_refused(status, m, message, "ria", "ria = 1 in 2D");
  /* a message truncated to the buffer, NUL-terminated; a NULL buffer */
  props[3] = 2.0;
  memset(small, 'x', sizeof small);
  status = interlock_material_from_props(3, 11, props, &m, small, sizeof small);
  check(status == INTERLOCK_BAD_INPUT && small[9] == '\0' && strlen(small) == 9 &&
            strncmp(small, "PROPS(4):", 9) == 0,
        "a message truncated to the buffer");
  status = interlock_material_from_props(3, 11, props, &m, NULL, 0);
  check(status == INTERLOCK_BAD_INPUT, "a NULL message buffer");

  status = interlock_material_from_names(3, 3, names, values, &m, message, sizeof message);
  check_refused(status, m, message, "unknown property 'no_such_property'", "unknown name");
  status = interlock_material_from_names(3, 2, required, values, &m, message, sizeof message);
  check_refused(status, m, message, "'sigma0_t' is required", "a required property missing");
  status = interlock_material_from_names(3, 10, twice, values, &m, message, sizeof message);
  check_refused(status, m, message, "'eta' is given twice", "a property given twice");
  values[3] = 1.0;
  status = interlock_material_from_names(3, 9, nine, values, &m, message, sizeof message);
  check_refused(status, m, message, "property 'eta' = 1 is inadmissible: admissible 0 < eta < 1",
                "eta = 1 by name");
  values[3] = 0.99;
  values[7] = 31.0; /* theta_f > theta_0 */
  status = interlock_material_from_names(3, 9, nine, values, &m, message, sizeof message);
  check_refused(status, m, message, "thetaf_deg", "theta_f > theta_0 by name");
  status = interlock_material_from_names(3, -1, nine, values, &m, message, sizeof message);
  check_refused(status, m, message, "n = -1", "n = -1");
}

/* Fill n doubles with a pattern that no update writes (a NaN payload). */
static void poison(double *x, size_t n) {
  size_t i;
  const unsigned long long bits = 0x7ff8dead0000beefULL;
  for (i = 0; i < n; ++i) memcpy(&x[i], &bits, sizeof bits);
}

static int poisoned(const double *x, size_t n) {
  double p;
  size_t i;
  poison(&p, 1);
  for (i = 0; i < n; ++i)
    if (memcmp(&x[i], &p, sizeof p) != 0) return 0;
  return 1;
}

enum { N_CASES = 10 };

static void updates_refused(void) {
  double props[11];
  interlock_material *m = NULL;
  char message[512];
  int ns, nsv, i;
  size_t failed;
  double *state, *old_state, *new_state, sep[3 * N_CASES], traction[3 * N_CASES],
      tangent[9 * N_CASES], fraction[N_CASES];
  double one_new[200], one_traction[3], one_tangent[9], one_fraction;
  int status[N_CASES], one_status, s;
  /* point k: what is wrong with it, the status and fraction it must get */
  const char *what[N_CASES] = {"good", "separation NaN", "separation +Inf", "separation 2e6 mm",
                               "damage 1.5", "damage NaN", "flag 0.5",
                               "start separation -Inf", "start traction NaN", "good, far"};
  const int expected_status[N_CASES] = {INTERLOCK_OK, INTERLOCK_DIVERGED, INTERLOCK_DIVERGED,
                                        INTERLOCK_DIVERGED, INTERLOCK_BAD_INPUT,
                                        INTERLOCK_BAD_INPUT, INTERLOCK_BAD_INPUT,
                                        INTERLOCK_BAD_INPUT, INTERLOCK_BAD_INPUT, INTERLOCK_OK};
  const char *expected_message[N_CASES] = {"", "diverged", "diverged", "diverged",
                                           "(damage of plane 1) is inadmissible",
                                           "(damage of plane 1) is inadmissible",
                                           "(initialized) is inadmissible",
                                           "the separation at the start", "the traction at the start",
                                           ""};
  memcpy(props, granite, sizeof props);
  s = interlock_material_from_props(3, 11, props, &m, message, sizeof message);
  check(s == INTERLOCK_OK, "the granite material");
  if (s != INTERLOCK_OK) return;
  ns = interlock_state_size(m);
  nsv = interlock_statev_size(m);
  check(ns == 34 && nsv == 28 && interlock_dim(m) == 3 && interlock_plane_count(m) == 3,
        "3D paper RIA: 28 STATEV + 6");
  state = (double *)malloc(sizeof(double) * ns * N_CASES);
  old_state = (double *)malloc(sizeof(double) * ns * N_CASES);
  new_state = (double *)malloc(sizeof(double) * ns * N_CASES);
  check(interlock_state_init(m, 0, N_CASES, state) == INTERLOCK_OK, "state_init");
  /* a sound start: one elastic step under compression and slip */
  for (i = 0; i < N_CASES; ++i) {
    sep[3 * i] = -0.01; sep[3 * i + 1] = 0.002; sep[3 * i + 2] = 0.001;
  }
  failed = interlock_update(m, N_CASES, sep, state, old_state, traction, tangent, status, fraction);
  check(failed == 0, "the start");
  for (i = 0; i < N_CASES; ++i) {
    sep[3 * i] = -0.011; sep[3 * i + 1] = 0.004; sep[3 * i + 2] = 0.0015;
  }
  sep[3 * 1 + 0] = NAN;
  sep[3 * 2 + 1] = INFINITY;
  sep[3 * 3 + 2] = 2.0e6;
  old_state[4 * ns + 0] = 1.5;
  old_state[5 * ns + 0] = NAN;
  old_state[6 * ns + 21] = 0.5;                /* STATEV(22), the flag of 3 planes in 3D */
  old_state[7 * ns + nsv + 0] = -INFINITY;     /* start separation s_N */
  old_state[8 * ns + nsv + 3 + 1] = NAN;       /* start traction sigma_T1 */
  sep[3 * 9 + 1] = 0.5;                        /* a long slip: a step fraction < 1 */
  poison(new_state, (size_t)ns * N_CASES);
  poison(traction, 3 * N_CASES);
  poison(tangent, 9 * N_CASES);
  failed = interlock_update(m, N_CASES, sep, old_state, new_state, traction, tangent, status,
                            fraction);
  check(failed == 8, "8 of 10 points refused");
  for (i = 0; i < N_CASES; ++i) {
    char label[200];
    int ms;
    ms = interlock_update_message(m, sep + 3 * i, old_state + (size_t)i * ns, message, sizeof message);
    printf("point %d (%s): status %d, step fraction %g: %s\n", i, what[i], status[i], fraction[i],
           message);
    snprintf(label, sizeof label, "point %d (%s): status", i, what[i]);
    check(status[i] == expected_status[i] && ms == status[i], label);
    snprintf(label, sizeof label, "point %d (%s): message", i, what[i]);
    check(strstr(message, expected_message[i]) != NULL, label);
    snprintf(label, sizeof label, "point %d (%s): outputs", i, what[i]);
    if (status[i] == INTERLOCK_OK) {
      /* = the same point alone */
      one_status = -1;
      check(interlock_update(m, 1, sep + 3 * i, old_state + (size_t)i * ns, one_new, one_traction,
                             one_tangent, &one_status, &one_fraction) == 0, label);
      check(memcmp(one_new, new_state + (size_t)i * ns, sizeof(double) * ns) == 0 &&
                memcmp(one_traction, traction + 3 * i, sizeof one_traction) == 0 &&
                memcmp(one_tangent, tangent + 9 * i, sizeof one_tangent) == 0 &&
                memcmp(&one_fraction, &fraction[i], sizeof one_fraction) == 0,
            label);
    } else {
      check(poisoned(new_state + (size_t)i * ns, ns) && poisoned(traction + 3 * i, 3) &&
                poisoned(tangent + 9 * i, 9),
            label);
    }
  }
  check(fraction[0] == 1.0, "a small step: fraction 1");
  check(fraction[9] > 0.0 && fraction[9] < 0.8, "a long slip: a suggested cut");
  check(fraction[1] == 0.25 && fraction[4] == 0.0 && fraction[7] == 0.0, "the fractions");
  /* n = 0 and NULL pointers (each argument in turn): nothing written */
  status[0] = 99;
  check(interlock_update(m, 0, sep, old_state, new_state, traction, tangent, status, fraction) == 0 &&
            status[0] == 99,
        "n = 0");
  for (i = 0; i < 7; ++i) {
    char label[64];
    snprintf(label, sizeof label, "argument %d NULL", i);
    check(interlock_update(i == 0 ? NULL : m, 2, i == 1 ? NULL : sep, i == 2 ? NULL : old_state,
                           i == 3 ? NULL : new_state, i == 4 ? NULL : traction, tangent,
                           i == 5 ? NULL : status, i == 6 ? NULL : fraction) == 2 &&
              status[0] == 99,
          label);
  }
  /* tangent NULL: the same update without it */
  check(interlock_update(m, 1, sep, old_state, one_new, one_traction, NULL, &one_status,
                         &one_fraction) == 0 &&
            memcmp(one_new, new_state, sizeof(double) * ns) == 0,
        "tangent NULL");
  /* state_init refusals */
  check(interlock_state_init(m, 2, 1, state) == INTERLOCK_BAD_INPUT, "prefractured = 2");
  check(interlock_state_init(m, 0, 1, NULL) == INTERLOCK_BAD_INPUT, "state NULL");
  check(interlock_state_init(NULL, 0, 1, state) == INTERLOCK_BAD_INPUT, "state_init material NULL");
  check(interlock_state_init(m, 0, 0, NULL) == INTERLOCK_OK, "state_init n = 0");
  /* a pre-fractured state: damage 1 on every plane */
  check(interlock_state_init(m, 1, 1, state) == INTERLOCK_OK && state[0] == 1.0 && state[1] == 1.0 &&
            state[2] == 1.0 && state[3] == 1.0 / (1.0 - 0.99),
        "a pre-fractured state");
  check(interlock_update_message(NULL, sep, state, message, sizeof message) == INTERLOCK_BAD_INPUT,
        "update_message material NULL");
  free(state);
  free(old_state);
  free(new_state);
  interlock_material_free(m);
  interlock_material_free(NULL);
}

static void description(void) {
  char name[64], unit[16], message[512];
  double lo, hi, def;
  int flags, plane, i;
  double props[11];
  interlock_material *m = NULL;
  check(interlock_property_count() == 22, "22 properties");
  check(interlock_property_info(0, name, sizeof name, unit, sizeof unit, &lo, &hi, &def, &flags) ==
                INTERLOCK_OK &&
            strcmp(name, "sigma0_n") == 0 && strcmp(unit, "MPa") == 0 && lo == 0.0 &&
            (flags & INTERLOCK_PROPERTY_REQUIRED) && (flags & INTERLOCK_PROPERTY_LOWER_OPEN),
        "property 0: sigma0_n [MPa], required, > 0");
  check(interlock_property_info(3, name, sizeof name, NULL, 0, &lo, &hi, NULL, &flags) ==
                INTERLOCK_OK &&
            strcmp(name, "eta") == 0 && lo == 0.0 && hi == 1.0 &&
            (flags & INTERLOCK_PROPERTY_UPPER_OPEN),
        "property 3: 0 < eta < 1");
  check(interlock_property_info(21, name, sizeof name, unit, sizeof unit, &lo, &hi, &def, &flags) ==
                INTERLOCK_OK &&
            strcmp(name, "n_azimuths") == 0 && def == 3.0 && (flags & INTERLOCK_PROPERTY_INTEGER) &&
            !(flags & INTERLOCK_PROPERTY_REQUIRED),
        "property 21: n_azimuths, default 3");
  check(interlock_property_info(5, NULL, 0, NULL, 0, NULL, NULL, NULL, &flags) == INTERLOCK_OK &&
            (flags & INTERLOCK_PROPERTY_INFINITE_OK),
        "h_n admits infinity");
  check(interlock_property_info(22, name, sizeof name, NULL, 0, NULL, NULL, NULL, NULL) ==
            INTERLOCK_BAD_INPUT,
        "property 22 does not exist");
  check(interlock_property_info(-1, name, sizeof name, NULL, 0, NULL, NULL, NULL, NULL) ==
            INTERLOCK_BAD_INPUT,
        "property -1 does not exist");
  check(interlock_property_check(3, 1.5, message, sizeof message) == INTERLOCK_BAD_INPUT &&
            strstr(message, "'eta' = 1.5 is inadmissible") != NULL,
        "property_check eta = 1.5");
  check(interlock_property_check(3, 0.5, message, sizeof message) == INTERLOCK_OK &&
            message[0] == '\0',
        "property_check eta = 0.5");
  memcpy(props, granite, sizeof props);
  check(interlock_material_from_props(2, 11, props, &m, message, sizeof message) == INTERLOCK_OK,
        "a 2D material");
  check(interlock_state_size(m) == 26 && interlock_state_variable_count(m) == 26, "2D: 22 + 4");
  check(interlock_state_variable_info(m, 12, name, sizeof name, unit, sizeof unit, &plane, &lo,
                                      &hi) == INTERLOCK_OK &&
            strcmp(name, "theta") == 0 && strcmp(unit, "rad") == 0 && plane == 1,
        "2D slot 12: theta of plane 1");
  check(interlock_state_variable_info(m, 23, name, sizeof name, unit, sizeof unit, &plane, &lo,
                                      &hi) == INTERLOCK_OK &&
            strcmp(name, "separation_t") == 0 && strcmp(unit, "mm") == 0 && plane == 0,
        "2D slot 23: separation_t");
  interlock_material_free(m);
  m = NULL;
  props[9] = 0.0;
  {
    double p22[22];
    memcpy(p22, granite, sizeof granite);
    p22[11] = 0.0; p22[12] = 0.25; p22[13] = 1.0; p22[14] = 1.0; p22[15] = 1.0; p22[16] = 1.0;
    p22[17] = 1.0; p22[18] = 1.0; p22[19] = 1.0; p22[20] = 1.0; p22[21] = 3.0;
    check(interlock_material_from_props(3, 22, p22, &m, message, sizeof message) == INTERLOCK_OK,
          "the azimuthal RIA, N_a = 3");
  }
  check(interlock_plane_count(m) == 7 && interlock_statev_size(m) == 60 &&
            interlock_state_size(m) == 66,
        "N_a = 3: 7 planes, 60 STATEV");
  for (i = 0; i < interlock_state_size(m); ++i) {
    check(interlock_state_variable_info(m, i, name, sizeof name, unit, sizeof unit, &plane, &lo,
                                        &hi) == INTERLOCK_OK,
          "every slot described");
    printf("  state[%d] %s plane %d [%s] %g .. %g\n", i, name, plane, unit, lo, hi);
  }
  check(interlock_state_variable_info(m, 0, name, sizeof name, unit, sizeof unit, &plane, &lo,
                                      &hi) == INTERLOCK_OK &&
            strcmp(name, "damage") == 0 && plane == 1 && lo == 0.0 && hi == 1.0,
        "3D slot 0: damage of plane 1 in [0, 1]");
  check(interlock_state_variable_info(m, 59, name, sizeof name, unit, sizeof unit, &plane, &lo,
                                      &hi) == INTERLOCK_OK &&
            strcmp(name, "friction_traction_strike") == 0 && plane == 7,
        "3D slot 59: friction_traction_strike of plane 7");
  check(interlock_state_variable_info(m, 65, name, sizeof name, unit, sizeof unit, &plane, &lo,
                                      &hi) == INTERLOCK_OK &&
            strcmp(name, "traction_t2") == 0 && strcmp(unit, "MPa") == 0,
        "3D slot 65: traction_t2");
  check(interlock_state_variable_info(m, 66, name, sizeof name, unit, sizeof unit, &plane, &lo,
                                      &hi) == INTERLOCK_BAD_INPUT,
        "3D slot 66 does not exist");
  check(strlen(interlock_version()) > 0, "a version");
  interlock_material_free(m);
}

static void replay(const char *path, const char *what) {
  history_t h;
  interlock_material *m;
  double worst, worst_in_place;
  long bad;
  if (!history_read(path, &h)) {
    check(0, path);
    return;
  }
  m = history_material(&h);
  check(m != NULL, "the history's material");
  if (!m) return;
  bad = history_replay(m, &h, 3, 0, &worst);
  check(bad == 0, what);
  bad = history_replay(m, &h, 3, 1, &worst_in_place);
  check(bad == 0, what);
  printf("%s: %d steps, dim %d, %d STATEV: largest difference %.3g of the scale (in place %.3g)\n",
         what, h.rows, h.dim, h.nstatv, worst, worst_in_place);
  interlock_material_free(m);
  free(h.data);
}

int main(int argc, char **argv) {
#ifdef INTERLOCK_TEST_TRAPS
  feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
#endif
  if (argc != 3) {
    fprintf(stderr, "usage: test_c_api HISTORY_3D.txt HISTORY_2D.txt\n");
    return 2;
  }
  printf("interlock %s\n", interlock_version());
  replay(argv[1], "3D history");
  replay(argv[2], "2D history");
  materials_refused();
  updates_refused();
  description();
  if (failures) {
    printf("%ld checks FAILED\n", failures);
    return 1;
  }
  printf("all checks passed\n");
  return 0;
}
