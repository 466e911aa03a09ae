/*
 * stancf.h: the C library of stancf's coupling API (libstancf_c).
 *
 * A system of cable lines (a TOML system scenario or a MoorDyn v2 deck)
 * stepped by a code that moves its coupled points (fairleads) and takes
 * back the lines' forces on them, in memory. The calls mirror MoorDyn's C
 * API argument for argument (MoorDyn_Create, MoorDyn_NCoupledDOF,
 * MoorDyn_Init, MoorDyn_Step, MoorDyn_Close). See docs/interface.md
 * ("C library") and docs/method.md section 13.
 *
 * Units: m, s, N. The coupling arrays hold first 6 values per coupled
 * body (stancf_coupled_body_ids, in body order): in x its reference
 * point's x, y, z and MoorDyn's roll, pitch, yaw in radians; in xd the
 * reference point's velocity and the angular velocity (rad/s, global); in
 * f the lines' force on the body and their moment about the reference
 * point (global). Then 3 values per coupled point not on a body (x, y, z),
 * the points in the order of their ids (stancf_coupled_ids).
 * Every call returns STANCF_SUCCESS (0) or an error code, and keeps its
 * message for stancf_error_message() (per thread); none aborts or unwinds
 * into the caller. The handles (StancfSystem *, StancfState *) are tokens
 * the library looks up, never reads: a handle closed or freed already, or
 * not from stancf_create / stancf_save, is refused with
 * STANCF_INVALID_INPUT. A handle is meant for one thread at a time; calls
 * on one handle from several threads wait for each other. Separate
 * handles may step in separate threads.
 *
 * Build: cargo build --release --workspace  (target/release/libstancf_c.so)
 * Link:  cc prog.c -I crates/stancf-capi/include -L target/release -lstancf_c
 */
#ifndef STANCF_H
#define STANCF_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Return codes (MoorDyn's values where they mean the same). */
#define STANCF_SUCCESS 0
/* The scenario or deck cannot be read or is not valid. */
#define STANCF_INVALID_INPUT_FILE -1
/* A call that cannot be made: a NULL pointer; a handle that is closed,
   freed or not from stancf_create / stancf_save (or a state given for a
   system); no such line, node or point; a step before stancf_init; *t not
   the time reached. Nothing is written. */
#define STANCF_INVALID_INPUT -3
/* The solver did not converge (the message gives time, step and
   residual); the system stays at its last converged step. */
#define STANCF_NUMERICAL_ERROR -4
/* A refused value, the system untouched: a wrong number of coupled DOFs,
   a value not finite, a state saved from another system, an interval of
   more internal steps than the handle's bound. */
#define STANCF_INVALID_VALUE -6
/* An internal error caught at the boundary (please report it); the handle
   is unusable from then on: close it. */
#define STANCF_UNHANDLED_ERROR -255

/* A coupled system and a saved state of one (opaque). */
typedef struct StancfSystem StancfSystem;
typedef struct StancfState StancfState;

/* Opens the system scenario or MoorDyn v2 deck at path; NULL on error
   (the message names the file and the key or line). Writes no file. */
StancfSystem *stancf_create(const char *path);

/* stancf_create with flags: STANCF_ALLOW_LARGE opens a system of more
   elements than `stancf run` takes without --allow-large (2000), up to the
   hard bound (1000000); 0 is stancf_create. Beyond the bounds, and for an
   unknown flag: NULL, the message saying which. */
#define STANCF_ALLOW_LARGE 1u
StancfSystem *stancf_create_with(const char *path, unsigned int flags);

/* stancf_create_with in the host's sea, as OpenFAST gives MoorDyn-F its
   WtrDepth, rhoW and g before init: water_depth (m), water_density
   (kg/m^3) and gravity (m/s^2) fill what a MoorDyn deck leaves out (a
   glue code's deck has no WtrDpth), the deck's own values winning; 0 for
   a value the host does not give. A negative or non-finite value: NULL,
   the message naming it. */
StancfSystem *stancf_create_in(const char *path, unsigned int flags, double water_depth,
                               double water_density, double gravity);

/* stancf_create_with for a FAST.Farm farm-level deck whose turbines the
   host places, as FAST.Farm gives MoorDyn-F its turbines' positions:
   positions holds n_turbines triples x, y, z (m), turbine n's at index
   3 (n - 1); each turbine's platform is then 6 coupled degrees of freedom
   (docs/interface.md, "FAST.Farm's farm-level decks"). NULL positions
   with n_turbines > 0, more than 100000 turbines, or a position not
   finite: NULL, the message naming it. */
StancfSystem *stancf_create_farm(const char *path, unsigned int flags, unsigned int n_turbines,
                                 const double *positions);

/* Frees the system; s is refused from then on (a second close too). */
int stancf_close(StancfSystem *s);

/* *n = the number of coupled degrees of freedom, 6 per coupled body (3 per
   body pinned to the host, MoorDyn's CoupledPinned: its reference point's
   position, velocity and pull), then 6 per coupled rod (a coupled body of
   its own, its reference point at end A; 3 per CoupledPinned rod), and 3
   per coupled point. A coupled body's force holds its rods' weight,
   water and inertia with its lines' (docs/method.md §15.18). */
int stancf_ncoupled_dof(StancfSystem *s, unsigned int *n);

/* ids[k] = the id of coupled point k, after the bodies in the arrays
   ((ncoupled_dof - 6 nb) / 3 values, nb the coupled bodies, when none is
   pinned to the host; such a body takes 3 numbers, not 6). */
int stancf_coupled_ids(StancfSystem *s, int64_t *ids);

/* *n = nb, the number of coupled bodies (6 values each, 3 for a body
   pinned to the host, first in the arrays; coupled rods are coupled
   bodies, their ids after the deck's bodies'); ids[k] = the id of coupled
   body k (nb values). */
int stancf_coupled_body_count(StancfSystem *s, unsigned int *n);
int stancf_coupled_body_ids(StancfSystem *s, int64_t *ids);

/* x = the coupled bodies' poses and the coupled points' positions as the
   scenario or deck places them (ncoupled_dof values): a start for
   stancf_init. */
int stancf_coupled_positions(StancfSystem *s, double *x);

/* Solves the static equilibrium with the coupled points at x (their
   velocities xd, or NULL) and starts at t = 0. Reads ncoupled_dof values
   from each array; writes nothing. May be called again to start over. */
int stancf_init(StancfSystem *s, const double *x, const double *xd);

/* stancf_init with the arrays' length n: STANCF_INVALID_VALUE unless n is
   ncoupled_dof. */
int stancf_init_n(StancfSystem *s, unsigned int n, const double *x, const double *xd);

/* f = the forces on the coupled bodies and points at the equilibrium the
   last stancf_init solved (ncoupled_dof values, as stancf_step gives
   them); STANCF_INVALID_INPUT before stancf_init. */
int stancf_init_force(StancfSystem *s, double *f);

/* Advances from *t (the time reached) to *t + *dt with the coupled points
   moving to x (cubically, with the velocities xd or, where xd is NULL,
   velocities estimated from this call's and the two last calls'
   positions, docs/method.md (K2a)); f = the lines' force on each coupled
   point, and on each coupled body their force and moment with its rods'
   push (the mean over the last internal step); then *t += *dt. The
   interval is split into the fewest equal steps no longer than the
   scenario's time step; an interval of more steps than the handle's bound
   (100000 unless stancf_set_max_interval_steps raised it) is refused with
   STANCF_INVALID_VALUE before anything moves. */
int stancf_step(StancfSystem *s, const double *x, const double *xd, double *f, double *t,
                double *dt);

/* stancf_step with the arrays' length n: STANCF_INVALID_VALUE unless n is
   ncoupled_dof. */
int stancf_step_n(StancfSystem *s, unsigned int n, const double *x, const double *xd, double *f,
                  double *t, double *dt);

/* f = the mean force over the last stancf_step's whole interval (its
   impulse over its length; ncoupled_dof values). */
int stancf_interval_mean_force(StancfSystem *s, double *f);

/* *n = the internal steps the last stancf_step took: its interval's equal
   steps, or the kept half steps where the scenario's
   analysis.force_tolerance chooses them. */
int stancf_last_steps(StancfSystem *s, unsigned int *n);

/* *t = the time reached (0 before stancf_init). */
int stancf_time(StancfSystem *s, double *t);

/* Lets one stancf_step take up to n internal steps (n >= 1; 100000 by
   default): for a host that steps over long intervals on purpose. */
int stancf_set_max_interval_steps(StancfSystem *s, uint64_t n);

/* The whole state (NULL on error): stancf_restore brings it back and
   stepping on gives the same bits. Free it with stancf_free_state. A
   state restores into its own system or one opened from the same file (a
   restart); a state of another system is refused with
   STANCF_INVALID_VALUE, the system untouched. */
StancfState *stancf_save(StancfSystem *s);
int stancf_restore(StancfSystem *s, const StancfState *state);
int stancf_free_state(StancfState *state);

/* Lines, numbered from 0 in the scenario's order; their ids. */
int stancf_nlines(StancfSystem *s, unsigned int *n);
int stancf_line_id(StancfSystem *s, unsigned int line, int64_t *id);
int stancf_line_nnodes(StancfSystem *s, unsigned int line, unsigned int *n);

/* Node values at the time reached (after stancf_init): position (m, 3),
   velocity (m/s, 3), axial force EA eps (N, a scalar, where MoorDyn's
   MoorDyn_GetLineNodeTen gives a vector) and curvature (1/m). */
int stancf_line_node_pos(StancfSystem *s, unsigned int line, unsigned int node, double *pos);
int stancf_line_node_vel(StancfSystem *s, unsigned int line, unsigned int node, double *vel);
int stancf_line_node_ten(StancfSystem *s, unsigned int line, unsigned int node, double *ten);
int stancf_line_node_curv(StancfSystem *s, unsigned int line, unsigned int node, double *curv);

/* A whole line at once: 3 positions per node, or one axial force per
   node. */
int stancf_line_positions(StancfSystem *s, unsigned int line, double *pos);
int stancf_line_tensions(StancfSystem *s, unsigned int line, double *ten);

/* Points (fixed, coupled and free), numbered from 0 in the scenario's
   order; their ids; position (m), velocity (m/s) and the net force of
   their lines (N), 3 values each, any of the three NULL to skip it. */
int stancf_npoints(StancfSystem *s, unsigned int *n);
int stancf_point_id(StancfSystem *s, unsigned int point, int64_t *id);
int stancf_point_state(StancfSystem *s, unsigned int point, double *pos, double *vel,
                       double *force);

/* A host that sets the water's kinematics (a deck's WaveKin 1, a
   scenario's water.host_waves; MoorDyn's MoorDyn_ExternalWaveKin*):
   after stancf_init, n = the points where it is asked (every line's nodes,
   every rod's nodes, every point, then 1 for MoorDyn's ground body and 1
   for each body, in MoorDyn's order), r =
   their positions now (3 n values), and stancf_wave_kin_set gives the
   water's velocity u (m/s) and local acceleration ud (m/s^2) there (3 n
   values each), added to the sea's current and held for the steps from
   then until set again (t, the time they are for, must be finite; as in
   MoorDyn it does not move them in time). Still water until set.
   STANCF_INVALID_INPUT before stancf_init or for a system whose waves are
   not a host's; STANCF_INVALID_VALUE for a value that is not finite. */
int stancf_wave_kin_init(StancfSystem *s, unsigned int *n);
int stancf_wave_kin_n(StancfSystem *s, unsigned int *n);
int stancf_wave_kin_coordinates(StancfSystem *s, double *r);
int stancf_wave_kin_set(StancfSystem *s, const double *u, const double *ud, double t);

/* Free or coupled body body_id's (the scenario's or deck's id) 6 x 6 mooring stiffness
   at the static equilibrium of the last stancf_init, docs/method.md
   section 15.9; row-major in out (36 values): rows the lines' force
   F_x, F_y, F_z and moment M_x, M_y, M_z about the body's reference point
   (global axes), columns the reference point's displacement dx, dy, dz and
   a small rotation about global x, y, z through it (N/m, N/rad, N m/m,
   N m/rad); K = -d[F; M]/d[dr; dphi], a positive diagonal restoring. The
   lines' stiffness only (not the body's own hydrostatics); not symmetric in
   general. STANCF_INVALID_INPUT for an unknown id, a fixed body, a call
   before stancf_init or a NULL out; STANCF_NUMERICAL_ERROR where the rest
   of the system is singular with the body held. Nothing is written on an
   error. */
int stancf_body_stiffness(StancfSystem *s, int64_t body_id, double *out);

/* Coupled point point_id's (the scenario's or deck's id; a coupled point
   not on a body) 3 x 3 mooring stiffness at the static equilibrium of the
   last stancf_init, row-major in out (9 values): K = -df/dx of the lines'
   force on it (N/m, global axes), the rest of the system in equilibrium.
   STANCF_INVALID_INPUT for an unknown id, a point that is not coupled, a
   call before stancf_init or a NULL out; STANCF_NUMERICAL_ERROR where the
   rest is singular with the point held. Nothing is written on an error. */
int stancf_point_stiffness(StancfSystem *s, int64_t point_id, double *out);

/* The message of this thread's last failed call ("" before any). */
const char *stancf_error_message(void);

#ifdef __cplusplus
}
#endif

#endif /* STANCF_H */
