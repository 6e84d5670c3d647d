#include "shotlab/model.hpp"

#include <array>
#include <stdexcept>

namespace shotlab {
namespace {
constexpr std::array<std::pair<Method, const char*>, 6> kMethods{{
    {Method::Euler, "euler"},
    {Method::RK4, "rk4"},
    {Method::CashKarp54, "cash_karp54"},
    {Method::DormandPrince5, "dopri5"},
    {Method::BulirschStoer, "bulirsch_stoer"},
    {Method::Rosenbrock4, "rosenbrock4"},
}};
}  // namespace

const char* method_name(Method m) {
  for (const auto& [method, name] : kMethods)
    if (method == m) return name;
  return "?";
}

bool parse_method(const std::string& name, Method& out) {
  for (const auto& [method, n] : kMethods)
    if (name == n) {
      out = method;
      return true;
    }
  return false;
}

const char* contact_model_name(ContactModel m) { return m == ContactModel::Rigid ? "rigid" : "soft"; }

bool parse_contact_model(const std::string& name, ContactModel& out) {
  if (name != "soft" && name != "rigid") return false;
  out = name == "rigid" ? ContactModel::Rigid : ContactModel::Soft;
  return true;
}

bool is_adaptive(Method m) { return m != Method::Euler && m != Method::RK4; }

const ContactMaterial& Model::material(const std::string& name) const {
  const auto it = materials.find(name);
  if (it == materials.end()) throw std::out_of_range("unknown material '" + name + "'");
  return it->second;
}

int Model::ball_index(const std::string& id) const {
  for (size_t i = 0; i < balls.size(); ++i)
    if (balls[i].id == id) return static_cast<int>(i);
  return -1;
}

Model empty_model() {
  Model m;
  m.materials[kBallBall] = default_ball_ball();
  m.materials[kBallCloth] = default_ball_cloth();
  m.materials[kBallCushion] = default_ball_cushion();
  return m;
}

void use_path(Options& options, SolverPath path) {
  const bool fast = path == SolverPath::Fast;
  options.rolling_regime = options.sliding_regime = options.swing_regime = options.flight_regime =
      options.bounce_regime = options.islands = fast;
  options.sleep_time = fast ? kDefaultSleepTime : 0.0;
}

const Pocket* Model::pocket_under(const Vec3& p, double r) const {
  for (const Pocket& pk : pockets) {
    const Vec3 d = p - pk.center;
    if (d.x * d.x + d.z * d.z < (pk.radius + r) * (pk.radius + r)) return &pk;
  }
  return nullptr;
}

}  // namespace shotlab
