/* A program a user writes against libshotlab: load a scene file, run it for up to 20 s and print what was pocketed
 * and where every ball ended, by its id. Built after `cmake --install` with
 *     cc example.c $(pkg-config --cflags --libs shotlab)
 * usage: example SCENE.json */
#include <stdio.h>
#include <string.h>

#include <shotlab.h>

static int check(shotlab_status status, const shotlab_sim* sim, const char* what) {
  if (status != SHOTLAB_OK) fprintf(stderr, "%s: %s\n", what, shotlab_last_error(sim));
  return status == SHOTLAB_OK;
}

int main(int argc, char** argv) {
  if (argc < 2) return fprintf(stderr, "usage: example SCENE.json\n"), 2;
  shotlab_sim* sim = NULL;
  if (!check(shotlab_create_from_file(argv[1], &sim), NULL, "load")) return 1;
  int n = 0, pocketed = 0;
  shotlab_ball_count(sim, &n);
  shotlab_event events[256];
  for (int second = 0; second < 20; ++second) {
    if (!check(shotlab_advance(sim, 1.0), sim, "advance")) break;
    int count = 0;
    if (!check(shotlab_events(sim, events, 256, &count), sim, "events")) break;
    for (int k = 0; k < count; ++k)
      if (strcmp(events[k].kind, "pocketed") == 0) printf("pocketed: %s at %.3f s\n", events[k].body_a, events[k].time), ++pocketed;
  }
  double position[3 * 64];
  int in_play[64];
  char id[64];
  if (n <= 64 && check(shotlab_balls(sim, position, NULL, NULL, in_play, 64), sim, "balls"))
    for (int i = 0; i < n; ++i)
      if (check(shotlab_ball_id(sim, i, id, sizeof id), sim, "ball id"))
        printf("ball %s: %s at (%.3f, %.3f)\n", id, in_play[i] ? "on the table" : "off", position[3 * i],
               position[3 * i + 2]);
  printf("%d pocketed, API version %d\n", pocketed, shotlab_api_version());
  shotlab_destroy(sim);
  return 0;
}
