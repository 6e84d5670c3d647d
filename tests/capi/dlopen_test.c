/* libshotlab loaded at run time and its functions looked up by name, as the thesis's C# wrapper does with its native
 * plugin; then VALIDATION.md R1 (a stun shot slides, then rolls at t = 2 v0 / (7 mu g) = 0.29125 s, x = 0.49928 m,
 * v = 5 v0 / 7 = 1.42857 m/s; 0.5 %) and every error path the header promises.
 * usage: dlopen_test PATH_TO_LIBSHOTLAB */
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "shotlab.h"

static int failures = 0;
#define CHECK(cond, what)                                  \
  do {                                                     \
    if (!(cond)) {                                         \
      fprintf(stderr, "FAIL %s (line %d)\n", what, __LINE__); \
      ++failures;                                          \
    }                                                      \
  } while (0)

typedef int (*version_fn)(void);
typedef const char* (*error_fn)(const shotlab_sim*);
typedef shotlab_status (*json_fn)(const char*, shotlab_sim**);
typedef void (*destroy_fn)(shotlab_sim*);
typedef shotlab_status (*advance_fn)(shotlab_sim*, double);
typedef shotlab_status (*within_fn)(shotlab_sim*, double, double, int);
typedef shotlab_status (*time_fn)(const shotlab_sim*, double*);
typedef shotlab_status (*reset_fn)(shotlab_sim*);
typedef shotlab_status (*balls_fn)(const shotlab_sim*, double*, double*, double*, int*, int);
typedef shotlab_status (*events_fn)(shotlab_sim*, shotlab_event*, int, int*);
typedef shotlab_status (*material_fn)(shotlab_sim*, const char*, const char*, double);
typedef shotlab_status (*from_balls_fn)(int, const double*, const double*, const double*, const double*, const double*,
                                        const char*, shotlab_sim**);
typedef shotlab_status (*strike_fn)(shotlab_sim*, const char*, double, double, double, double, double);
typedef shotlab_status (*id_fn)(const shotlab_sim*, int, char*, int);

/* R1's ball on an endless cloth: friction 0.2, no rolling resistance or spin friction while it slides, friction
 * smoothing 1e4 s/m (its effect on the switch time is 15 us, 0.005 % of it). */
static const char* kStun =
    "{\"colliders\": [{\"type\": \"plane\", \"point\": [0, 0, 0], \"normal\": [0, 1, 0], \"material\": \"ball_cloth\"}],"
    " \"materials\": {\"ball_cloth\": {\"friction\": 0.2, \"rolling_resistance\": 0, \"spin_friction\": 0}},"
    " \"model\": {\"friction_sharpness\": 1e4},"
    " \"integrator\": {\"method\": \"dopri5\", \"abs_tol\": 1e-10, \"rel_tol\": 1e-10, \"max_steps_per_call\": 1000000},"
    " \"balls\": [{\"id\": \"cue\", \"position\": [0, 0.028575, 0], \"velocity\": [2, 0, 0]}]}";

/* presets/cut.json (it pockets ball "1" at 0.69 s), and with its tip 0.6 radii right of centre. */
#define CUT_SCENE(more)                                                                                               \
  "{\"table\": {\"type\": \"pool\"}, \"balls\": [{\"id\": \"cue\", \"position\": [0.6801793249039285, 0.028575,"      \
  " -0.30837406568934533]}, {\"id\": \"1\", \"position\": [0.85, 0.028575, 0.215]}],"                                 \
  " \"cue\": {\"ball\": \"cue\", \"speed\": 2.0, \"aim_deg\": -75.00000000000001" more "}}"
static const char* kCut = CUT_SCENE("");
static const char* kCutMiscue = CUT_SCENE(", \"side\": 0.6");
static const char* kCutHeld = CUT_SCENE("}, \"integrator\": {\"max_steps_per_call\": 3");

int main(int argc, char** argv) {
  if (argc < 2) return fprintf(stderr, "usage: dlopen_test LIBRARY\n"), 2;
  void* lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
  if (!lib) return fprintf(stderr, "dlopen: %s\n", dlerror()), 1;
  version_fn version = (version_fn)dlsym(lib, "shotlab_api_version");
  error_fn last_error = (error_fn)dlsym(lib, "shotlab_last_error");
  json_fn create = (json_fn)dlsym(lib, "shotlab_create_from_json");
  destroy_fn destroy = (destroy_fn)dlsym(lib, "shotlab_destroy");
  advance_fn advance = (advance_fn)dlsym(lib, "shotlab_advance");
  within_fn within = (within_fn)dlsym(lib, "shotlab_advance_within");
  time_fn now = (time_fn)dlsym(lib, "shotlab_time");
  reset_fn reset = (reset_fn)dlsym(lib, "shotlab_reset");
  balls_fn balls = (balls_fn)dlsym(lib, "shotlab_balls");
  events_fn events = (events_fn)dlsym(lib, "shotlab_events");
  material_fn material = (material_fn)dlsym(lib, "shotlab_set_material");
  from_balls_fn from_balls = (from_balls_fn)dlsym(lib, "shotlab_create_from_balls");
  strike_fn strike = (strike_fn)dlsym(lib, "shotlab_strike");
  id_fn ball_id = (id_fn)dlsym(lib, "shotlab_ball_id");
  if (!version || !last_error || !create || !destroy || !advance || !within || !now || !reset || !balls || !events ||
      !material || !from_balls || !strike || !ball_id)
    return fprintf(stderr, "a function is missing from the library\n"), 1;
  CHECK(version() == SHOTLAB_API_VERSION, "the library's API version is the header's");
  CHECK(dlsym(lib, "_ZN7shotlab10SimulationC1ENS_5ModelENS_5StateE") == NULL, "the engine's C++ symbols are hidden");

  shotlab_sim* sim = NULL;
  CHECK(create(kStun, &sim) == SHOTLAB_OK && sim, "the stun scene is created");
  /* Advance in frames until the rolling event, then reset and advance exactly to it (runs do not depend on slicing). */
  double tau = -1;
  shotlab_event ev[64];
  int count = 0;
  for (int frame = 0; frame < 60 && tau < 0; ++frame) {
    CHECK(advance(sim, 1.0 / 60) == SHOTLAB_OK, "advance");
    CHECK(events(sim, ev, 64, &count) == SHOTLAB_OK, "events");
    for (int k = 0; k < count; ++k)
      if (strcmp(ev[k].kind, "rolling") == 0 && strcmp(ev[k].body_a, "cue") == 0) tau = ev[k].time;
  }
  CHECK(reset(sim) == SHOTLAB_OK && advance(sim, tau) == SHOTLAB_OK, "reset and advance to the switch");
  double p[3], v[3];
  int in_play[1];
  CHECK(balls(sim, p, v, NULL, in_play, 1) == SHOTLAB_OK, "balls");
  printf("R1 through the C ABI: t %.6f s, x %.6f m, v %.6f m/s\n", tau, p[0], v[0]);
  CHECK(fabs(tau / 0.29125 - 1) < 0.005, "R1 time");
  CHECK(fabs(p[0] / 0.49928 - 1) < 0.005, "R1 distance");
  CHECK(fabs(v[0] / 1.42857 - 1) < 0.005, "R1 speed");
  CHECK(in_play[0] == 1, "in play");

  /* A frame loop with no wall time to spare: each call takes one step and the clock reaches the switch in many calls,
   * where the ball is as one call put it. */
  double q[3], w[3], t = 0;
  int calls = 0;
  CHECK(reset(sim) == SHOTLAB_OK, "reset");
  for (; calls < 100000 && t < tau; ++calls) {
    CHECK(within(sim, tau - t, 0.0, calls > 0) == SHOTLAB_OK, "advance within no wall time");
    CHECK(now(sim, &t) == SHOTLAB_OK, "time");
  }
  CHECK(balls(sim, q, w, NULL, NULL, 1) == SHOTLAB_OK, "balls after the budgeted calls");
  printf("to the switch in %d calls of no wall time: x off by %.1e m, v by %.1e m/s\n", calls, fabs(q[0] - p[0]),
         fabs(w[0] - v[0]));
  CHECK(calls > 5 && t == tau, "many calls, to the switch exactly");
  CHECK(fabs(q[0] - p[0]) < 1e-9 && fabs(w[0] - v[0]) < 1e-9, "the state one call gives");
  CHECK(within(sim, 0.1, -1, 0) == SHOTLAB_ERROR_ARGUMENT && strstr(last_error(sim), "wall_seconds"),
        "a negative budget named");
  CHECK(within(sim, 0.1, NAN, 0) == SHOTLAB_ERROR_ARGUMENT, "a NaN budget");

  /* From arrays: a pool ball at rest on the pool table, struck along +x at the cue's 2 m/s (centre hit: the rigid-cue
   * model gives (1 + e) M V0 / (M + m) = 2.66 m/s), rolls on. */
  const double pos[3] = {-0.9, 0.028575, 0}, radius[1] = {0.028575}, mass[1] = {0.17};
  shotlab_sim* table = NULL;
  CHECK(from_balls(1, pos, NULL, NULL, radius, mass, "pool", &table) == SHOTLAB_OK, "created from arrays");
  CHECK(strike(table, "b0", 2.0, 0.0, 0.0, 0.0, 0.0) == SHOTLAB_OK, "struck");
  CHECK(advance(table, 1e-4) == SHOTLAB_OK && balls(table, p, v, NULL, NULL, 1) == SHOTLAB_OK, "advance after it");
  CHECK(fabs(v[0] - 1.75 * 0.54 * 2.0 / (0.54 + 0.17)) < 0.01 && fabs(v[2]) < 1e-9, "the strike's speed and heading");
  CHECK(strike(table, "nobody", 2, 0, 0, 0, 0) == SHOTLAB_ERROR_ARGUMENT, "an unknown ball");
  CHECK(strike(table, "b0", 2, 0, 0.9, 0.9, 0) == SHOTLAB_ERROR_ARGUMENT, "a tip offset outside the ball");
  const double nan_position[3] = {0, NAN, 0};
  shotlab_sim* none = NULL;
  CHECK(from_balls(1, nan_position, NULL, NULL, radius, mass, "pool", &none) == SHOTLAB_ERROR_ARGUMENT &&
            none == NULL && strstr(last_error(NULL), "position[1]"),
        "a non-finite position, named");
  CHECK(from_balls(1, pos, NULL, NULL, radius, NULL, "pool", &none) == SHOTLAB_ERROR_ARGUMENT &&
            strstr(last_error(NULL), "mass: NULL"),
        "a NULL mass array, named");
  CHECK(from_balls(1, pos, NULL, NULL, radius, mass, "billiards", &none) == SHOTLAB_ERROR_INPUT &&
            strstr(last_error(NULL), "table"),
        "an unknown table type, named");
  destroy(table);

  /* presets/cut.json, its tip offset beyond the miscue limit: the miscue is the first event, again after a reset; the
   * object ball "1" is pocketed by 1 s and can be struck no more; ids by index. */
  shotlab_sim* cut = NULL;
  CHECK(create(kCutMiscue, &cut) == SHOTLAB_OK, "the miscued cut is created");
  for (int round = 0; round < 2; ++round) {
    CHECK(events(cut, ev, 64, &count) == SHOTLAB_OK && count >= 1 && strcmp(ev[0].kind, "miscue") == 0 &&
              strcmp(ev[0].body_a, "cue") == 0 && ev[0].time == 0,
          "the scene's miscue is its first event");
    CHECK(reset(cut) == SHOTLAB_OK, "reset the cut");
  }
  destroy(cut);
  CHECK(create(kCut, &cut) == SHOTLAB_OK, "the cut is created");
  CHECK(events(cut, ev, 64, &count) == SHOTLAB_OK && count == 0, "no miscue there");
  CHECK(advance(cut, 1.0) == SHOTLAB_OK && balls(cut, NULL, NULL, NULL, in_play, 0) == SHOTLAB_ERROR_BUFFER,
        "a zero capacity is too small");
  int cut_in_play[2] = {1, 1};
  CHECK(balls(cut, NULL, NULL, NULL, cut_in_play, 2) == SHOTLAB_OK && cut_in_play[0] == 1 && cut_in_play[1] == 0,
        "the object ball is pocketed");
  CHECK(strike(cut, "1", 1.0, 0, 0, 0, 0) == SHOTLAB_ERROR_ARGUMENT && strstr(last_error(cut), "out of play"),
        "a pocketed ball cannot be struck");
  CHECK(events(cut, ev, 64, &count) == SHOTLAB_OK, "events taken");
  CHECK(strike(cut, "cue", 1.0, 0, 0.6, 0, 0) == SHOTLAB_OK && events(cut, ev, 64, &count) == SHOTLAB_OK &&
            count == 1 && strcmp(ev[0].kind, "miscue") == 0 && fabs(ev[0].time - 1.0) < 1e-12,
        "a strike beyond the miscue limit reports a miscue at its moment");
  char id[4];
  CHECK(ball_id(cut, 0, id, 4) == SHOTLAB_OK && strcmp(id, "cue") == 0, "ball 0 is the cue ball");
  CHECK(ball_id(cut, 1, id, 4) == SHOTLAB_OK && strcmp(id, "1") == 0, "ball 1 is '1'");
  CHECK(ball_id(cut, 0, id, 3) == SHOTLAB_ERROR_BUFFER && strstr(last_error(cut), "needs 4"),
        "an id that does not fit");
  CHECK(ball_id(cut, 2, id, 4) == SHOTLAB_ERROR_ARGUMENT && strstr(last_error(cut), "index"), "no ball 2");
  CHECK(strike(cut, "cue", 40, 0, 0, 0, 0) == SHOTLAB_ERROR_ARGUMENT && strstr(last_error(cut), "speed"),
        "a cue speed over 30 m/s, named");
  CHECK(strike(cut, "cue", 2, 0, 0, 0, 2.0) == SHOTLAB_ERROR_ARGUMENT && strstr(last_error(cut), "elevation"),
        "an elevation past a vertical cue, named");
  CHECK(strike(cut, NULL, 2, 0, 0, 0, 0) == SHOTLAB_ERROR_ARGUMENT && strstr(last_error(cut), "ball: NULL"),
        "a NULL ball, named");
  CHECK(strike(cut, "cue", 0, 0, 0, 0, 0) == SHOTLAB_ERROR_ARGUMENT && strstr(last_error(cut), "speed"),
        "no cue speed, as a scene's cue may not have");
  CHECK(material(cut, "ball_cloth", "friction", -1) == SHOTLAB_ERROR_INPUT &&
            strstr(last_error(cut), "materials.ball_cloth.friction") &&
            strstr(strstr(last_error(cut), "materials.ball_cloth.friction") + 1, "materials.ball_cloth") == NULL,
        "a refused value names its field once");
  destroy(cut);

  /* A run stopped by its step limit stays stopped: a material or a strike does not start it again; reset does. */
  shotlab_sim* held = NULL;
  CHECK(create(kCutHeld, &held) == SHOTLAB_OK, "the held cut is created");
  CHECK(advance(held, 0.5) == SHOTLAB_ERROR_STOPPED && strstr(last_error(held), "step limit"), "the step limit stops");
  CHECK(material(held, "ball_cloth", "friction", 0.3) == SHOTLAB_ERROR_STOPPED, "no material on a stopped run");
  CHECK(strike(held, "cue", 1, 0, 0, 0, 0) == SHOTLAB_ERROR_STOPPED, "no strike on a stopped run");
  CHECK(advance(held, 0.1) == SHOTLAB_ERROR_STOPPED, "still stopped");
  double held_t = -1;
  CHECK(reset(held) == SHOTLAB_OK && now(held, &held_t) == SHOTLAB_OK && held_t == 0, "reset starts it again");
  destroy(held);

  /* Errors: codes, never an abort. */
  CHECK(advance(NULL, 0.1) == SHOTLAB_ERROR_HANDLE && strstr(last_error(NULL), "sim: NULL"),
        "NULL handle, said where a NULL handle's message is read");
  CHECK(advance(sim, NAN) == SHOTLAB_ERROR_ARGUMENT && strstr(last_error(sim), "dt"), "non-finite dt named");
  CHECK(advance(sim, -1) == SHOTLAB_ERROR_ARGUMENT, "negative dt");
  CHECK(balls(sim, p, v, NULL, NULL, 0) == SHOTLAB_ERROR_BUFFER, "buffer too small");
  CHECK(balls(sim, p, v, NULL, NULL, -1) == SHOTLAB_ERROR_ARGUMENT &&
            events(sim, ev, -1, &count) == SHOTLAB_ERROR_ARGUMENT,
        "a negative capacity");
  CHECK(material(sim, "ball_cloth", "frction", 0.3) == SHOTLAB_ERROR_ARGUMENT && strstr(last_error(sim), "frction") &&
            strstr(last_error(sim), "friction"),
        "an unknown field is named, with the fields there are");
  CHECK(material(sim, "ball_cloth", "friction", -1) == SHOTLAB_ERROR_INPUT && strstr(last_error(sim), "friction"),
        "a negative friction is refused");
  CHECK(material(sim, "ball_cloth", "friction", 0.3) == SHOTLAB_OK, "a material is set");
  CHECK(material(sim, "nothing", "friction", 0.3) == SHOTLAB_ERROR_ARGUMENT, "an unknown pair");
  destroy(sim);
  CHECK(advance(sim, 0.1) == SHOTLAB_ERROR_HANDLE && strstr(last_error(NULL), "not a valid handle"),
        "a destroyed handle");
  CHECK(strstr(last_error(sim), "not valid") != NULL, "its message");
  destroy(sim); /* twice: ignored */
  shotlab_sim* bad = NULL;
  CHECK(create("{\"balls\": [{\"id\": \"a\", \"position\": [0, 0, 0], \"mass\": -1}]}", &bad) == SHOTLAB_ERROR_INPUT &&
            bad == NULL,
        "a bad scene is refused");
  CHECK(strstr(last_error(NULL), "balls[0].mass") != NULL, "and the field is named");
  CHECK(create("{", &bad) == SHOTLAB_ERROR_INPUT, "malformed JSON");
  CHECK(create(kStun, NULL) == SHOTLAB_ERROR_ARGUMENT, "NULL out");
  dlclose(lib);
  printf("%s\n", failures ? "FAILED" : "all checks passed");
  return failures ? 1 : 0;
}
