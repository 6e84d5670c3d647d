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

/* R1's ball on an endless cloth: friction 0.2, no rolling resistance or spin friction while it slides, friction
 * smoothing 1e4 s/m (its effect on the switch time is 15 us, 0.005 % of it). */
static const char* kStun =
    "{\"colliders\": [{\"type\": \"plane\", \"point\": [0, 0, 0], \"normal\": [0, 1, 0], \"material\": \"ball_cloth\"}],"
    " \"materials\": {\"ball_cloth\": {\"friction\": 0.2, \"rolling_resistance\": 0, \"spin_friction\": 0}},"
    " \"model\": {\"friction_sharpness\": 1e4},"
    " \"integrator\": {\"method\": \"dopri5\", \"abs_tol\": 1e-10, \"rel_tol\": 1e-10, \"max_steps_per_call\": 1000000},"
    " \"balls\": [{\"id\": \"cue\", \"position\": [0, 0.028575, 0], \"velocity\": [2, 0, 0]}]}";

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
  if (!version || !last_error || !create || !destroy || !advance || !within || !now || !reset || !balls || !events ||
      !material || !from_balls || !strike)
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
  CHECK(from_balls(1, nan_position, NULL, NULL, radius, mass, "pool", &none) == SHOTLAB_ERROR_ARGUMENT && none == NULL,
        "a non-finite position");
  CHECK(from_balls(1, pos, NULL, NULL, radius, mass, "billiards", &none) == SHOTLAB_ERROR_INPUT &&
            strstr(last_error(NULL), "table"),
        "an unknown table type, named");
  destroy(table);

  /* Errors: codes, never an abort. */
  CHECK(advance(NULL, 0.1) == SHOTLAB_ERROR_HANDLE, "NULL handle");
  CHECK(advance(sim, NAN) == SHOTLAB_ERROR_ARGUMENT && strstr(last_error(sim), "dt"), "non-finite dt named");
  CHECK(advance(sim, -1) == SHOTLAB_ERROR_ARGUMENT, "negative dt");
  CHECK(balls(sim, p, v, NULL, NULL, 0) == SHOTLAB_ERROR_BUFFER, "buffer too small");
  CHECK(material(sim, "ball_cloth", "frction", 0.3) == SHOTLAB_ERROR_INPUT && strstr(last_error(sim), "frction"),
        "an unknown field is named");
  CHECK(material(sim, "ball_cloth", "friction", -1) == SHOTLAB_ERROR_INPUT && strstr(last_error(sim), "friction"),
        "a negative friction is refused");
  CHECK(material(sim, "ball_cloth", "friction", 0.3) == SHOTLAB_OK, "a material is set");
  CHECK(material(sim, "nothing", "friction", 0.3) == SHOTLAB_ERROR_ARGUMENT, "an unknown pair");
  destroy(sim);
  CHECK(advance(sim, 0.1) == SHOTLAB_ERROR_HANDLE, "a destroyed handle");
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
