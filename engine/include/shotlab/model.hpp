// The constant side of a simulation (MuJoCo's mjModel): bodies, colliders, materials, options. Nothing here changes
// while the engine runs; the changing side is State (state.hpp).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "shotlab/colliders.hpp"
#include "shotlab/material.hpp"
#include "shotlab/vec.hpp"

namespace shotlab {

struct BallSpec {
  std::string id;
  double mass;    // kg
  double radius;  // m
  double inertia() const { return 0.4 * mass * radius * radius; }  // solid sphere, 2/5 m R^2, kg m^2
};

// Rod actor (thesis, Newton's cradle): keeps a ball's centre at `length` from a fixed anchor, by a force through
// the centre (no torque): a pendulum rod.
struct Rod {
  int ball;
  Vec3 anchor;
  double length;  // m
};

// A pocket: the hole in the bed plus where a falling ball counts as pocketed.
struct Pocket {
  std::string name;
  Vec3 center;    // on the bed
  double radius;  // m
};

enum class Method { Euler, RK4, CashKarp54, DormandPrince5, BulirschStoer, Rosenbrock4 };

const char* method_name(Method m);
bool parse_method(const std::string& name, Method& out);
bool is_adaptive(Method m);

struct IntegratorOptions {
  Method method = Method::CashKarp54;    // default chosen by docs/bench (fastest at the accuracy the presets need)
  double abs_tol = 1e-7;          // absolute error per step: m for positions, m/s for velocities and, with Cash-Karp
                                  // and Dormand-Prince, for a spin's surface speed R |w| (stepper.hpp)
  double rel_tol = 1e-7;          // relative error per step
  double fixed_step = 1e-5;       // s, for Euler and RK4
  double initial_step = 1e-4;     // s, first trial step of the adaptive methods
  int max_steps_per_call = 20000; // steps one advance() call may take before it stops and reports
};

inline constexpr double kDefaultSleepTime = 0.2;  // s

// Which contact model moves the balls (docs/model.md#rigid-model). Soft: the thesis's compliant contacts, integrated;
// the reference. Rigid: balls kept on a table's bed, in closed form between instant impulses: event-driven, far
// faster, a different model with its own accuracy (docs/bench/speed.md).
enum class ContactModel { Soft, Rigid };
const char* contact_model_name(ContactModel m);  // "soft", "rigid"
bool parse_contact_model(const std::string& name, ContactModel& out);

struct Options {
  ContactModel contact = ContactModel::Soft;
  Vec3 gravity{0.0, -9.81, 0.0};  // m/s^2
  double friction_sharpness = 1000.0;  // k of fricstep(k s), s/m: friction reaches full strength at 1/k m/s of slip
  double friction_rate_limit = 2e5;    // 1/s: the fastest a smoothed friction term may relax a slip; under heavy
                                       // load the band widens instead (contact_force.hpp). 0: no limit
  double rest_speed = 1e-3;            // m/s: below this a ball (and R|w|) counts as stopped / rolling without slip
  double contact_margin = 1e-6;        // m: a step may bring a still separated pair this far into contact
  // The solver switches: SolverPath sets them all (use_path); a scene may then override each.
  double sleep_time = kDefaultSleepTime;  // s a group of touching balls must rest before it sleeps; 0: never
  bool rolling_regime = true;  // a ball alone on the bed rolls in closed form (regimes.hpp)
  bool sliding_regime = true;  // a ball alone on the bed, settled onto it, slides at its static sink (regimes.hpp)
  bool swing_regime = true;    // a ball alone on its rod swings in the pendulum's closed form (swing.hpp)
  bool flight_regime = true;   // a ball touching nothing, held by no rod, flies in closed form (regimes.hpp)
  bool bounce_regime = true;   // a ball sliding on the bed alone bounces and settles in reduced form (bounce.hpp)
  bool islands = true;         // balls that cannot touch for a while integrate apart (partition.hpp)
};

// How much of a scene the engine moves in closed form, puts to sleep or integrates apart (docs/model.md#regimes).
// Fast: all of it, the default. Plain: every ball in one ODE system with the full model, none asleep: the thesis's
// path, the reference the bench and the tests measure the fast one against.
enum class SolverPath { Fast, Plain };
void use_path(Options& options, SolverPath path);

// Names of the three standard material pairs.
inline const std::string kBallBall = "ball_ball";
inline const std::string kBallCloth = "ball_cloth";
inline const std::string kBallCushion = "ball_cushion";
inline const std::string kBallPocket = "ball_pocket";  // not standard: tables with pockets add it (table.hpp)

struct Model {
  std::vector<BallSpec> balls;
  std::vector<Collider> colliders;
  std::vector<Rod> rods;
  std::vector<Pocket> pockets;
  // Set by add_table: a ball whose centre falls a radius below the bed (y = 0) has gone through a pocket or off
  // the table and leaves play. Scenes without a table (a pendulum, a cradle) keep every ball.
  bool balls_leave_below_bed = false;
  std::map<std::string, ContactMaterial> materials;  // always holds the three standard pairs
  Options options;
  IntegratorOptions integrator;

  const ContactMaterial& material(const std::string& name) const;
  int ball_index(const std::string& id) const;  // -1 when absent
  // The pocket a ball of radius r (m) that left play at centre p went through: its centre within a radius of the
  // hole's edge, in the bed's plane; nullptr for a ball that went off the table.
  const Pocket* pocket_under(const Vec3& p, double r) const;
};

// A model with the standard materials and no bodies.
Model empty_model();

}  // namespace shotlab
