/* libshotlab: the shotlab engine behind a C ABI (C99), for programs that load it at run time (a game engine's native
 * plugin, a tool, a binding). docs/c-api.md says how to build against it.
 *
 * A simulation is an opaque handle. Every function returns a status; on an error, shotlab_last_error() says what
 * happened in the words of the command line (file, field, problem). No function aborts or throws, and none reads
 * a handle it did not create: a NULL or destroyed handle is SHOTLAB_ERROR_HANDLE.
 *
 * Threads: one simulation is used by one thread at a time; separate simulations may run in parallel.
 * Units: SI (m, s, kg, m/s, rad/s); y is up, the table's bed is y = 0. */
#ifndef SHOTLAB_H
#define SHOTLAB_H

#include <stddef.h>

#if defined(_WIN32)
#define SHOTLAB_API __declspec(dllexport)
#else
#define SHOTLAB_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

#define SHOTLAB_API_VERSION 2

typedef enum shotlab_status {
  SHOTLAB_OK = 0,
  SHOTLAB_ERROR_HANDLE = 1,    /* NULL or destroyed simulation */
  SHOTLAB_ERROR_ARGUMENT = 2,  /* a NULL pointer, a non-finite or out-of-range number, an unknown name */
  SHOTLAB_ERROR_INPUT = 3,     /* a scene that cannot be read or is not valid */
  SHOTLAB_ERROR_BUFFER = 4,    /* a caller's buffer is too small: the count needed is written where asked */
  SHOTLAB_ERROR_STOPPED = 5,   /* the simulation stopped (step limit, unstable, non-finite): see the message; it
                                * stays stopped (every advance says so again) until shotlab_reset */
  SHOTLAB_ERROR_INTERNAL = 6   /* anything else the engine reported; the handle stays usable for reading */
} shotlab_status;

typedef struct shotlab_sim shotlab_sim;

/* An event since the last shotlab_events() call: kind (contact_begin, contact_end, rolling, sliding, pocketed, miscue,
 * ...), the bodies it names (a ball's id, a collider's name; body_b empty when it names one; a name is cut to its
 * first 47 bytes), and its time (s). */
typedef struct shotlab_event {
  double time;
  char kind[24];
  char body_a[48];
  char body_b[48];
} shotlab_event;

/* SHOTLAB_API_VERSION of the library that is loaded. */
SHOTLAB_API int shotlab_api_version(void);

/* The message of the last failed call on `sim`; when sim is NULL, of this thread's last failed shotlab_create_* or
 * call on a NULL or destroyed handle. Valid until the next call on the same handle (or thread); never NULL. */
SHOTLAB_API const char* shotlab_last_error(const shotlab_sim* sim);

/* Create a simulation from a scene file, a scene as JSON text (docs/scene-format.md), or arrays of n balls: position,
 * velocity, spin (3 n numbers each, x y z per ball; velocity and spin may be NULL for at rest), radius and mass (n
 * each), on a table of type "pool", "carom" or "snooker" (NULL: no table; gravity stays on, so then nothing holds
 * the balls up). Balls are named b0, b1, ... On success *out is the new handle. */
SHOTLAB_API shotlab_status shotlab_create_from_file(const char* path, shotlab_sim** out);
SHOTLAB_API shotlab_status shotlab_create_from_json(const char* json, shotlab_sim** out);
SHOTLAB_API shotlab_status shotlab_create_from_balls(int n, const double* position, const double* velocity,
                                                     const double* spin, const double* radius, const double* mass,
                                                     const char* table, shotlab_sim** out);
/* Releases the simulation; NULL is allowed. The handle must not be used again (it is then SHOTLAB_ERROR_HANDLE). */
SHOTLAB_API void shotlab_destroy(shotlab_sim* sim);

/* Moves the clock by dt >= 0 s. */
SHOTLAB_API shotlab_status shotlab_advance(shotlab_sim* sim, double dt);
/* As shotlab_advance, but for a frame loop that must keep its frame rate (API version 2): it may stop short of t + dt
 * once wall_seconds >= 0 of wall time have passed (one step at least), at the latest time every ball can be read at;
 * shotlab_time says where (it may stay put while parts of the table catch up: call again). Results do not depend on
 * where calls stop. The step limit (integrator.max_steps_per_call) counts from this call, or with go_on nonzero on
 * from the last, for a caller finishing a stretch it was stopped short in. */
SHOTLAB_API shotlab_status shotlab_advance_within(shotlab_sim* sim, double dt, double wall_seconds, int go_on);
/* Back to the scene's start (as created, its own cue struck again), with the materials set since then; strikes
 * made since are not repeated (they act on the state of their moment). */
SHOTLAB_API shotlab_status shotlab_reset(shotlab_sim* sim);

SHOTLAB_API shotlab_status shotlab_time(const shotlab_sim* sim, double* seconds);
SHOTLAB_API shotlab_status shotlab_ball_count(const shotlab_sim* sim, int* count);
/* The id of ball `index` (0 to count - 1, the order of shotlab_balls), as events and shotlab_strike name it, into
 * `id` (capacity bytes, with its terminating NUL; SHOTLAB_ERROR_BUFFER when it does not fit, and the message says
 * how many bytes it needs; a scene's ids are short, 64 bytes hold any of the presets'). API version 2. */
SHOTLAB_API shotlab_status shotlab_ball_id(const shotlab_sim* sim, int index, char* id, int capacity);
/* Every ball's state into caller buffers of `capacity` balls (3 numbers each; any may be NULL); in_play (may be
 * NULL) gets 1 or 0 per ball. SHOTLAB_ERROR_BUFFER when capacity is below the ball count. */
SHOTLAB_API shotlab_status shotlab_balls(const shotlab_sim* sim, double* position, double* velocity, double* spin,
                                         int* in_play, int capacity);
/* The events since the last call, into `events` (capacity entries). *count gets how many there are; when more than
 * the capacity, nothing is taken (call again with room for *count). */
SHOTLAB_API shotlab_status shotlab_events(shotlab_sim* sim, shotlab_event* events, int capacity, int* count);

/* Sets a field of a material pair ("ball_ball", "ball_cloth", "ball_cushion", a pocketed table's "ball_pocket" or a
 * scene's own) as the scene file names it: stiffness, damping, exponent, friction, rolling_resistance, spin_friction,
 * restitution, ... The simulation goes on from its current state with the new model. */
SHOTLAB_API shotlab_status shotlab_set_material(shotlab_sim* sim, const char* pair, const char* field, double value);
/* Strikes the ball `ball` (its id, in play) with the cue: speed (above 0, at most 30 m/s of the cue), aim (rad,
 * 0 = +x, pi/2 = -z), tip offsets side and height (ball radii, inside the ball), elevation (0 to pi/2 rad); the
 * rigid-cue model with squirt (docs/model.md#cue), as a scene's cue. A tip offset beyond the cue's miscue limit (half
 * a radius) is struck as if the tip held, and a miscue event says so. A stopped simulation stays stopped: this and
 * shotlab_set_material return SHOTLAB_ERROR_STOPPED until shotlab_reset. */
SHOTLAB_API shotlab_status shotlab_strike(shotlab_sim* sim, const char* ball, double speed, double aim, double side,
                                          double height, double elevation);

#ifdef __cplusplus
}
#endif

#endif /* SHOTLAB_H */
