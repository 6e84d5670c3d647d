#include "dynamics.hpp"

#include "band_tail.hpp"

namespace shotlab {

Dynamics::Dynamics(const Model& model, const ModelIndex& index, const State& state)
    : model_(model), index_(index), state_(state), force_(model.balls.size()), torque_(model.balls.size()) {}

template <bool Record>
void Dynamics::add_contacts(const StateVector& x) {
  // Only an evaluation that records sees a contact the step's plan did not foresee (StepContacts::colliders).
  for_each_contact(model_, index_, state_, x.data(), broad_, &plan_, [&](const Contact& c) {
    const ContactForce& f = c.force;
    if constexpr (Record) {
      // A contact between two balls is recorded from the lower-numbered one: the other sees the friction and rolling
      // forces turned around and the same spin torque about its own normal (-n).
      ContactRecord& r = recorded_.emplace_back(ContactRecord{{c.ball, -1 - c.collider}, c.depth, f.normal, FrictionState(f)});
      if (c.other_ball > c.ball) {
        r.key.second = c.other_ball;
      } else if (c.other_ball >= 0) {
        r.key = {c.other_ball, c.ball};
        r.friction.friction = -r.friction.friction;
        r.friction.rolling = -r.friction.rolling;
      }
    }
    const double r = model_.balls[c.ball].radius;
    const Vec3 lever = tangential_torque(f, c.normal, r);
    force_[c.ball] += f.force;
    torque_[c.ball] += lever + f.spin_torque * c.normal;
    if (c.other_ball >= 0) {
      // Newton's third law. B sees the normal -n and the opposite friction and rolling forces, so its tangential
      // torque, r_B (-n) x (-F_fric) + (2/5) r_B (-n) x (-F_roll), is A's when the radii are equal (every contact of a
      // rack), and its spin torque about -n keeps the same scalar.
      const double rb = model_.balls[c.other_ball].radius;
      force_[c.other_ball] -= f.force;
      torque_[c.other_ball] += (rb == r ? lever : tangential_torque(f, c.normal, rb)) - f.spin_torque * c.normal;
    }
  }, false, !Record);
}

void Dynamics::operator()(const StateVector& x, StateVector& dxdt, double /*t*/) {
  ++evaluations_;
  const int n = state_.ball_count();
  dxdt.assign(x.size(), 0.0);
  for (int i = 0; i < n; ++i) {
    force_[i] = state_.active(i) ? model_.balls[i].mass * model_.options.gravity : Vec3{0.0};
    torque_[i] = Vec3{0.0};
  }
  // Two instances of the contact pass, so that the stages that do not record pay nothing for it.
  if (recording_) {
    recorded_.clear();
    add_contacts<true>(x);
  } else {
    add_contacts<false>(x);
  }
  for (int i = 0; i < n; ++i) {
    if (!state_.active(i)) continue;  // pocketed or asleep: frozen, zero derivative
    if (state_.rolling(i)) {
      rolling_derivative(model_, index_, state_, x.data(), i, &dxdt[9 * i]);
      continue;
    }
    if (state_.sliding(i)) {
      sliding_derivative(model_, index_, state_, x.data(), i, &dxdt[9 * i]);
      continue;
    }
    set_position(dxdt, i, velocity(x, i));
    set_velocity(dxdt, i, force_[i] * index_.inv_mass[i]);
    set_spin(dxdt, i, torque_[i] * index_.inv_inertia[i]);
  }
  apply_rods(x, dxdt);
}

// A rod holds |p - anchor| = L. Its force acts along d^ = (p - anchor)/|p - anchor| and sets the radial
// acceleration to what circular motion needs: a.d^ = -|v_perp|^2/|d|. With a_free the acceleration from all other
// forces, the rod adds (lambda) d^ with lambda = -|v_perp|^2/|d| - a_free.d^, plus a Baumgarte term
// -2 beta (v.d^) - beta^2 (|d| - L), beta = kRodDriftRate, that pulls the numerical drift of length and radial speed
// back to zero.
void Dynamics::apply_rods(const StateVector& x, StateVector& dxdt) const {
  constexpr double beta = kRodDriftRate;
  for (const Rod& rod : model_.rods) {
    if (!state_.active(rod.ball)) continue;
    const Vec3 d = position(x, rod.ball) - rod.anchor;
    const double len = glm::length(d);
    if (len <= 0) continue;
    const Vec3 dh = d / len;
    const Vec3 v = velocity(x, rod.ball);
    const double vr = glm::dot(v, dh);
    const double vperp2 = glm::dot(v, v) - vr * vr;
    const Vec3 a_free = velocity(dxdt, rod.ball);  // the v-slot of dxdt holds the acceleration
    const double lambda = -vperp2 / len - glm::dot(a_free, dh) - 2.0 * beta * vr - beta * beta * (len - rod.length);
    set_velocity(dxdt, rod.ball, a_free + lambda * dh);
  }
}

// Sliding on a flat bed with normal n, settled at the static sink: the normal force is the weight m g and stays so
// (nothing changes the depth), so the contact law's tangential terms act at N = m g and the normal components of
// the motion stay zero:
//   dp/dt = v,  dv/dt = F_t / m,  dw/dt = T / I    (F_t, T: friction, rolling resistance and spin friction of the
//                                                   bed at N = m g, contact_force.hpp, exactly as in the full model)
void sliding_derivative(const Model& model, const ModelIndex& index, const State& state, const double* x, int i,
                        double* dxdt) {
  const int bed = state.sliding_on[i];
  const Vec3& n = index.plane_normal[bed];
  const BallSpec& b = model.balls[i];
  const Vec3 v = velocity(x, i), w = spin(x, i);
  ContactForce f;
  f.normal = b.mass * index.gravity;
  // The depth is the static sink; the friction terms do not read it.
  add_friction(index.collider_material(bed), collider_kinematics(index, i, b.radius, v, w, n, 0.0),
               {model.options.friction_sharpness, model.options.friction_rate_limit}, f);
  Vec3 a = f.force * index.inv_mass[i];
  a -= glm::dot(a, n) * n;  // round-off of the projections in add_friction
  const Vec3 alpha = contact_torque(f, n, b.radius) * index.inv_inertia[i];
  for (int c = 0; c < 3; ++c) {
    dxdt[c] = v[c];
    dxdt[3 + c] = a[c];
    dxdt[6 + c] = alpha[c];
  }
}

// Rolling on a flat bed with normal n under gravity g (magnitude), static normal force m g:
//   dp/dt = v (tangential; the height stays at the sink depth)
//   dv/dt = a = -mu_r g fricstep(k |v|) v^                                  (docs/model.md#rolling-regime)
//   dw/dt = (1/R) n x a  +  n (-(5 mu_sp g / (2 R)) fricstep(k R w.n))      (eq. 3.7; spin torque mu_sp R m g over
//                                                                            I = 2/5 m R^2, eq. 3.8)
// The slip v + R n x w stays exactly zero: d/dt of it is a + R n x ((1/R) n x a) = a - a = 0 for a along the bed.
void rolling_derivative(const Model& model, const ModelIndex& index, const State& state, const double* x, int i,
                        double* dxdt) {
  const ContactMaterial& m = index.collider_material(state.rolling_on[i]);
  const Vec3& n = index.plane_normal[state.rolling_on[i]];
  const double g = index.gravity, r = model.balls[i].radius, weight = model.balls[i].mass * g;
  const Smoothing smooth{model.options.friction_sharpness, model.options.friction_rate_limit};
  // The sharpness each term would get in contact_force (the static normal force is m g).
  const double k_roll = sharpness_for(smooth, m.rolling_resistance * weight, index.inv_mass[i]);
  const double k_spin = sharpness_for(smooth, m.spin_friction * weight, index.inv_inertia_r2[i]);
  const Vec3 v = velocity(x, i), w = spin(x, i);
  const double speed = glm::length(v);
  const Vec3 a = speed > 0 ? -(m.rolling_resistance * g * fricstep(k_roll * speed) / speed) * v : Vec3{0.0};
  const double wn = glm::dot(w, n);
  const Vec3 alpha = glm::cross(n, a) / r - (2.5 * m.spin_friction * g / r * fricstep(k_spin * r * wn)) * n;
  for (int c = 0; c < 3; ++c) {
    dxdt[c] = v[c];
    dxdt[3 + c] = a[c];
    dxdt[6 + c] = alpha[c];
  }
}

}  // namespace shotlab
