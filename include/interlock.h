/*
 * interlock.h: the C API of the interlock cohesive-zone law for rough interfaces (Serpieri,
 * Alfano, Sacco), 2D and 3D. C99, usable from C++. docs/c-api.md describes every function.
 *
 * A material is an opaque handle made from the UMAT's PROPS or from named properties (the
 * material table's names, as `interlock-query --props` prints them). A point's state is an
 * array of interlock_state_size() doubles: the UMAT's STATEV for that material (same layout,
 * same meaning, same checks; `interlock-query --statev`), then the separation and the traction
 * at the end of the last accepted update (dim values each: what a UMAT host keeps in STRAN and
 * STRESS). interlock_update() advances n points at once; it allocates nothing, writes no file,
 * never stops the host and keeps no global state: call it from many threads on disjoint points.
 *
 * Conventions. Separations in mm (s_N, s_T) in 2D, (s_N, s_T1, s_T2) in 3D (Abaqus' cohesive
 * element convention: t1 the element's first local shear direction, t2 = n x t1); tractions in
 * MPa in the same order; the tangent row-major, tangent[a * dim + b] = d traction_a / d s_b
 * [MPa/mm]. Indices of properties and state variables are 0-based. Every message is copied
 * NUL-terminated into the caller's buffer, truncated to message_len - 1 characters; a NULL
 * buffer or message_len 0 is allowed (no message).
 */
#ifndef INTERLOCK_H
#define INTERLOCK_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Status of a call or of a point. */
#define INTERLOCK_OK 0
/* The input is refused (a bad property, state value or argument): outputs untouched; no
   increment cut helps (step_fraction 0; the UMAT's PNEWDT = -1). */
#define INTERLOCK_BAD_INPUT 1
/* The local integration failed: outputs untouched; retry with a smaller increment
   (step_fraction 0.5, the UMAT's PNEWDT). */
#define INTERLOCK_LOCAL_FAILURE 2
/* The end separation is not finite or beyond 1e6 mm while the start is sound (the host's
   Newton iterate went astray): outputs untouched; cut the increment (step_fraction 0.25). */
#define INTERLOCK_DIVERGED 3

/* Bits of interlock_property_info's flags. */
#define INTERLOCK_PROPERTY_REQUIRED 1     /* no default: must be given                      */
#define INTERLOCK_PROPERTY_LOWER_OPEN 2   /* lo itself is not admissible                    */
#define INTERLOCK_PROPERTY_UPPER_OPEN 4   /* hi itself is not admissible                    */
#define INTERLOCK_PROPERTY_INFINITE_OK 8  /* >= 1e30 or +Inf admissible: the effect is off  */
#define INTERLOCK_PROPERTY_INTEGER 16     /* a whole number (a flag 0/1 or a choice)        */

/* The opaque material: created by interlock_material_from_*, freed by interlock_material_free.
   Read-only after creation: one material may serve many threads at once. */
typedef struct interlock_material interlock_material;

/* A material from the UMAT's PROPS(1:nprops) (same meaning, defaults and checks as the UMAT:
   9 <= nprops <= 22; dim = 2: the paper's RIA only; dim = 3: PROPS(21) ria, PROPS(22)
   n_azimuths). On success *material is a new handle and INTERLOCK_OK is returned; on refusal
   *material is NULL, INTERLOCK_BAD_INPUT is returned and the message names the value and its
   admissible range ("PROPS(4): property 'eta' = 2 is inadmissible: admissible 0 < eta < 1"). */
int interlock_material_from_props(int dim, int nprops, const double *props,
                                  interlock_material **material, char *message,
                                  size_t message_len);

/* A material from n named properties (names of the material table: "sigma0_n", "eta", "ria",
   "n_azimuths", ...; interlock_property_info lists them). The required properties must be
   given, the others take their defaults; an unknown or repeated name is refused. */
int interlock_material_from_names(int dim, int n, const char *const *names,
                                  const double *values, interlock_material **material,
                                  char *message, size_t message_len);

/* Free a material (NULL is allowed). */
void interlock_material_free(interlock_material *material);

/* The material's dimension (2 or 3), number of microplanes, and the doubles of state per point
   (STATEV slots + 2 dim). */
int interlock_dim(const interlock_material *material);
int interlock_plane_count(const interlock_material *material);
int interlock_state_size(const interlock_material *material);
/* The UMAT's STATEV slots of the material (NSTATV, *DEPVAR): the first values of a state. */
int interlock_statev_size(const interlock_material *material);

/* Initialise n states, state[n * interlock_state_size()]: virgin (prefractured = 0) or
   pre-fractured (prefractured = 1: every plane's damage 1), separation and traction 0. A
   material with property prefractured = 1 admits pre-fractured states only (a virgin request
   is refused). Returns INTERLOCK_OK or INTERLOCK_BAD_INPUT (state untouched). */
int interlock_state_init(const interlock_material *material, int prefractured, size_t n,
                         double *state);

/* The batched update of n points. For point i:
     separation    + i * dim          the separation at the end of the increment [mm]
     state_old     + i * state_size   the state at its start (STATEV, separation, traction)
     state_new     + i * state_size   the state at its end (may be state_old itself: in place)
     traction      + i * dim          the traction at its end [MPa]
     tangent       + i * dim * dim    the consistent tangent, row-major [MPa/mm]
     status[i]                        INTERLOCK_OK, _BAD_INPUT, _LOCAL_FAILURE or _DIVERGED
     step_fraction[i]                 the UMAT's PNEWDT for the point: 1 when the increment
                                      meets the accuracy bounds (max_damage_increment,
                                      max_angle_increment_deg); in (0, 1) a suggested increment
                                      cut (status OK: the results are returned all the same, as
                                      the UMAT does); 0.5 a local failure, 0.25 a diverged
                                      separation, 0 bad input.
   A point whose status is not INTERLOCK_OK leaves its state_new, traction and tangent untouched.
   tangent may be NULL (not computed for the host: no tangent written). Property tangent = 2
   gives the symmetric tangent as the UMAT does. No allocation, no I/O, no global state.
   Returns the number of points whose status is not INTERLOCK_OK (n when material, separation,
   state_old, state_new, traction, status or step_fraction is NULL: nothing is written then). */
size_t interlock_update(const interlock_material *material, size_t n, const double *separation,
                        const double *state_old, double *state_new, double *traction,
                        double *tangent, int *status, double *step_fraction);

/* The status of one point as interlock_update gives it, and its message (why it was refused or
   failed; empty for INTERLOCK_OK). Reruns the point: for logs, not for the hot loop. */
int interlock_update_message(const interlock_material *material, const double *separation,
                             const double *state_old, char *message, size_t message_len);

/* The material table: n properties (the UMAT's PROPS order), each with its name, unit,
   admissible range [lo, hi] (open ends and integers in flags), default (0 for the required
   ones) and flags (INTERLOCK_PROPERTY_*). NULL outputs are skipped. i out of range:
   INTERLOCK_BAD_INPUT. */
int interlock_property_count(void);
int interlock_property_info(int i, char *name, size_t name_len, char *unit, size_t unit_len,
                            double *lo, double *hi, double *default_value, int *flags);
/* Whether value is admissible for property i, with the table's message when it is not. */
int interlock_property_check(int i, double value, char *message, size_t message_len);

/* The state of a point, slot by slot (i from 0 to interlock_state_size() - 1): the variable's
   name ("damage", ..., "separation_n", "traction_t1"), unit, microplane (1-based; 0 for a
   variable of the point) and admissible range for this material (lo = -hi for unbounded
   values; an uninitialised STATEV, flag 0, is admissible whatever its other slots). */
int interlock_state_variable_count(const interlock_material *material);
int interlock_state_variable_info(const interlock_material *material, int i, char *name,
                                  size_t name_len, char *unit, size_t unit_len, int *plane,
                                  double *lo, double *hi);

/* The library's version, e.g. "0.1.0" (a static string). */
const char *interlock_version(void);

#ifdef __cplusplus
}
#endif

#endif /* INTERLOCK_H */
