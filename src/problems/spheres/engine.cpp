#include "problems/spheres/engine.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dlpverify/errors.hpp"
#include "problems/spheres/event_times.hpp"
#include "problems/spheres/invariants.hpp"
#include "io/format.hpp"

namespace dlpverify::events {

void Spheres::add(std::array<double, 3> position, std::array<double, 3> velocity, double r, double m) {
  x.push_back(position[0]), y.push_back(position[1]), z.push_back(position[2]);
  vx.push_back(velocity[0]), vy.push_back(velocity[1]), vz.push_back(velocity[2]);
  wx.push_back(0.0), wy.push_back(0.0), wz.push_back(0.0);
  radius.push_back(r), mass.push_back(m);
}

EventEngine::EventEngine(Spheres spheres, Box box, CollisionModel model)
    : s_(std::move(spheres)), t_(s_.size(), 0.0), n_(s_.size(), 0), scratch_(s_.size()), box_(box), model_(model) {
  const double overlap = worst_overlap();
  if (overlap > 0.0) throw InputError("sphere placement", value_text(overlap), "spheres overlap each other or a wall");
  predict_all();
  start_rate_window();
}

void EventEngine::move_to_now(std::size_t i) {
  const double dt = now_ - t_[i];
  s_.x[i] += s_.vx[i] * dt, s_.y[i] += s_.vy[i] * dt, s_.z[i] += s_.vz[i] * dt;
  t_[i] = now_;
}

void EventEngine::move_all_to_now() {
  for (std::size_t i = 0; i < s_.size(); ++i) move_to_now(i);
}

double EventEngine::wall_position(int wall) const {
  const int k = wall / 2;
  const double dt = now_ - box_time_;
  return wall % 2 == 0 ? box_.lower[k] + box_.lower_speed[k] * dt : box_.upper[k] + box_.upper_speed[k] * dt;
}

// Sphere i's earliest event against every other sphere and the six walls, queued. Sphere i must
// be at the current time; the others are moved there on the fly, r_j(now) = r_j + v_j (now − t_j).
void EventEngine::predict(std::size_t i) {
  const std::size_t n = s_.size();
  const double xi = s_.x[i], yi = s_.y[i], zi = s_.z[i], ui = s_.vx[i], vi = s_.vy[i], wi = s_.vz[i];
  const double ri = s_.radius[i], now = now_;
  const double *x = s_.x.data(), *y = s_.y.data(), *z = s_.z.data(), *vx = s_.vx.data(), *vy = s_.vy.data(),
               *vz = s_.vz.data(), *r = s_.radius.data(), *t = t_.data();
  double* out = scratch_.data();
  // event_times.hpp's pair_time written without branches, so the loop vectorises.
  for (std::size_t j = 0; j < n; ++j) {
    const double dt = now - t[j];
    const double rx = xi - (x[j] + vx[j] * dt), ry = yi - (y[j] + vy[j] * dt), rz = zi - (z[j] + vz[j] * dt);
    const double ux = ui - vx[j], uy = vi - vy[j], uz = wi - vz[j];
    const double sigma = ri + r[j];
    const double b = rx * ux + ry * uy + rz * uz;
    const double v2 = ux * ux + uy * uy + uz * uz;
    const double c = rx * rx + ry * ry + rz * rz - sigma * sigma;
    const double disc = b * b - v2 * c;
    const double root = c / (-b + std::sqrt(disc > 0.0 ? disc : 0.0));
    const double when = root > 0.0 ? root : 0.0;
    out[j] = ((b < 0.0) & (disc >= 0.0)) ? when : kNever;
  }
  out[i] = kNever;
  std::size_t best = i;
  double best_t = kNever;
  for (std::size_t j = 0; j < n; ++j)
    if (out[j] < best_t) best_t = out[j], best = j;
  int best_wall = -1;
  const double position[3] = {xi, yi, zi}, velocity[3] = {ui, vi, wi};
  for (int k = 0; k < 3; ++k) {
    const double dt_box = now - box_time_;
    const double lower = box_.lower[k] + box_.lower_speed[k] * dt_box, upper = box_.upper[k] + box_.upper_speed[k] * dt_box;
    const double t_lower = wall_time(position[k] - ri - lower, box_.lower_speed[k] - velocity[k]);
    const double t_upper = wall_time(upper - position[k] - ri, velocity[k] - box_.upper_speed[k]);
    if (t_lower < best_t) best_t = t_lower, best_wall = 2 * k;
    if (t_upper < best_t) best_t = t_upper, best_wall = 2 * k + 1;
  }
  if (best_t == kNever) return;  // at rest between walls at rest: only another sphere can change that
  const auto a = static_cast<std::int32_t>(i);
  if (best_wall >= 0)
    queue_.push({now + best_t, a, wall_partner(best_wall), n_[i], 0});
  else
    queue_.push({now + best_t, a, static_cast<std::int32_t>(best), n_[i], n_[best]});
}

void EventEngine::predict_all() {
  queue_.clear();
  move_all_to_now();
  for (std::size_t i = 0; i < s_.size(); ++i) predict(i);
}

bool EventEngine::process(const Event& e) {
  const auto a = static_cast<std::size_t>(e.a);
  if (n_[a] != e.count_a) {  // sphere a collided since: a newer prediction of a is queued
    ++counts_.stale;
    return false;
  }
  now_ = std::max(now_, e.t);  // every earlier event is done: time may advance to e.t
  if (e.partner >= 0 && n_[static_cast<std::size_t>(e.partner)] != e.count_partner) {
    ++counts_.stale;  // the partner collided since: predict a afresh from here
    move_to_now(a);
    predict(a);
    return false;
  }
  if (e.partner >= 0)
    process_pair(a, static_cast<std::size_t>(e.partner));
  else
    process_wall(a, wall_of(e.partner));
  check_work();
  if (check_overlaps_) {
    const double overlap = worst_overlap();
    if (overlap > 1e-9) fail(printf_string("overlap %.3e of a sphere radius sum", overlap));
  }
  return true;
}

void EventEngine::fail(const std::string& what) const {
  throw SolverError(printf_string("hard spheres at t = %s s (simulated), after %lld events: ", shortest_text(now_).c_str(),
                                  static_cast<long long>(counts_.pair + counts_.wall)) +
                    what);
}

std::int64_t EventEngine::rate_window() const { return std::max<std::int64_t>(1000, 10 * static_cast<std::int64_t>(s_.size())); }

void EventEngine::start_rate_window() {
  window_events_ = 0;
  window_time_ = now_;
  window_rate_ = kinetic_theory_rate();
}

void EventEngine::check_work() {
  const std::int64_t done = counts_.pair + counts_.wall;
  if (bound_.events > 0 && done > bound_.events)
    fail(printf_string("past the bound of %lld events in all (its work bound): inelastic collapse, a jammed gas, or "
                       "events that do not advance the gas",
                       static_cast<long long>(bound_.events)));
  if (bound_.rate_factor <= 0.0 || ++window_events_ < rate_window()) return;
  // The window's events must have taken at least window / (rate_factor Γ) of simulated time.
  const double elapsed = now_ - window_time_;
  const double rate = std::max(window_rate_, kinetic_theory_rate());
  if (static_cast<double>(window_events_) > bound_.rate_factor * rate * elapsed)
    fail(printf_string("%lld events in the last %.3g s of simulated time (from t = %.9g s), past the work bound of "
                       "%g x the kinetic-theory rate %.4g events/s: events that repeat without time passing (a "
                       "collision that leaves its spheres approaching), inelastic collapse or a jammed gas",
                       static_cast<long long>(window_events_), elapsed, window_time_, bound_.rate_factor, rate));
  start_rate_window();
}

double EventEngine::kinetic_theory_rate() const {
  const std::size_t n = s_.size();
  if (n == 0) return 0.0;
  const Box b = box();
  const double volume = (b.upper[0] - b.lower[0]) * (b.upper[1] - b.lower[1]) * (b.upper[2] - b.lower[2]);
  double walls = 0.0, speed2 = 0.0, r_max = 0.0, sphere_volume = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double v[3] = {s_.vx[i], s_.vy[i], s_.vz[i]}, r = s_.radius[i];
    for (int k = 0; k < 3; ++k) {
      const double edge = b.upper[k] - b.lower[k];
      const double reach = std::max(edge - 2.0 * r, 1e-12 * edge);
      walls += (std::fabs(v[k]) + std::fabs(b.lower_speed[k]) + std::fabs(b.upper_speed[k])) / reach;
    }
    speed2 += v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    r_max = std::max(r_max, r);
    sphere_volume += 4.0 / 3.0 * std::numbers::pi * r * r * r;
  }
  const double eta = std::min(sphere_volume / volume, 0.9);
  const double contact = (1.0 - 0.5 * eta) / ((1.0 - eta) * (1.0 - eta) * (1.0 - eta));
  const double sigma = 2.0 * r_max, count = static_cast<double>(n);
  const double pairs = 0.5 * count * (count - 1.0) / volume * std::numbers::pi * sigma * sigma *
                       std::sqrt(2.0 * speed2 / count) * contact;
  return walls + pairs;
}

void EventEngine::process_pair(std::size_t a, std::size_t b) {
  move_to_now(a);
  move_to_now(b);
  double normal[3] = {s_.x[a] - s_.x[b], s_.y[a] - s_.y[b], s_.z[a] - s_.z[b]};
  const double distance = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  for (double& c : normal) c /= distance;
  SphereKinematics ka{{s_.vx[a], s_.vy[a], s_.vz[a]}, {s_.wx[a], s_.wy[a], s_.wz[a]}, s_.mass[a], s_.radius[a]};
  SphereKinematics kb{{s_.vx[b], s_.vy[b], s_.vz[b]}, {s_.wx[b], s_.wy[b], s_.wz[b]}, s_.mass[b], s_.radius[b]};
  const SphereKinematics before_a = ka, before_b = kb;
  collide(model_, normal, ka, kb);
  s_.vx[a] = ka.v[0], s_.vy[a] = ka.v[1], s_.vz[a] = ka.v[2], s_.wx[a] = ka.w[0], s_.wy[a] = ka.w[1], s_.wz[a] = ka.w[2];
  s_.vx[b] = kb.v[0], s_.vy[b] = kb.v[1], s_.vz[b] = kb.v[2], s_.wx[b] = kb.w[0], s_.wy[b] = kb.w[1], s_.wz[b] = kb.w[2];
  ++n_[a], ++n_[b], ++counts_.pair;
  const double centres[3] = {s_.x[a] - s_.x[b], s_.y[a] - s_.y[b], s_.z[a] - s_.z[b]};  // not `normal`: checked apart
  const std::string broken = pair_violation(model_, centres, before_a, before_b, ka, kb);
  if (!broken.empty()) fail(printf_string("the collision of spheres %zu and %zu: ", a, b) + broken);
  predict(a);
  predict(b);
}

// A wall moving at u reflects the normal velocity component: v' = 2u − v (the seed's eq. 24).
void EventEngine::process_wall(std::size_t a, int wall) {
  move_to_now(a);
  const int k = wall / 2;
  const double u = wall % 2 == 0 ? box_.lower_speed[k] : box_.upper_speed[k];
  double& v = k == 0 ? s_.vx[a] : k == 1 ? s_.vy[a] : s_.vz[a];
  const double v_before = v;
  v = 2.0 * u - v;
  ++n_[a], ++counts_.wall;
  const std::string broken = wall_violation(v_before, v, u, wall % 2 == 0);
  if (!broken.empty()) fail(printf_string("sphere %zu at the %s%c wall: ", a, wall % 2 == 0 ? "-" : "+", "xyz"[k]) + broken);
  predict(a);
}

void EventEngine::run_until(double t_end) {
  while (!queue_.empty() && queue_.top().t <= t_end) process(queue_.pop());
  now_ = std::max(now_, t_end);
  move_all_to_now();
}

void EventEngine::run_events(std::int64_t events) {
  const std::int64_t target = counts_.pair + counts_.wall + events;
  while (!queue_.empty() && counts_.pair + counts_.wall < target) process(queue_.pop());
  move_all_to_now();
}

void EventEngine::set_wall_speeds(const std::array<double, 3>& lower_speed, const std::array<double, 3>& upper_speed) {
  box_ = box();
  box_time_ = now_;
  box_.lower_speed = lower_speed;
  box_.upper_speed = upper_speed;
  predict_all();
  start_rate_window();  // the walls change the gas's rate
}

const Spheres& EventEngine::spheres() {
  move_all_to_now();
  return s_;
}

Box EventEngine::box() const {
  Box b = box_;
  for (int k = 0; k < 3; ++k) b.lower[k] = wall_position(2 * k), b.upper[k] = wall_position(2 * k + 1);
  return b;
}

double EventEngine::kinetic_energy() {
  double sum = 0.0;
  for (std::size_t i = 0; i < s_.size(); ++i)
    sum += 0.5 * s_.mass[i] * (s_.vx[i] * s_.vx[i] + s_.vy[i] * s_.vy[i] + s_.vz[i] * s_.vz[i]);
  return sum;
}

double EventEngine::rotational_energy() {
  double sum = 0.0;
  for (std::size_t i = 0; i < s_.size(); ++i)
    sum += 0.2 * s_.mass[i] * s_.radius[i] * s_.radius[i] *
           (s_.wx[i] * s_.wx[i] + s_.wy[i] * s_.wy[i] + s_.wz[i] * s_.wz[i]);
  return sum;
}

double EventEngine::worst_overlap() {
  move_all_to_now();
  double worst = -kNever;
  const Box b = box();
  for (std::size_t i = 0; i < s_.size(); ++i) {
    const double p[3] = {s_.x[i], s_.y[i], s_.z[i]};
    for (int k = 0; k < 3; ++k) {
      worst = std::max(worst, (b.lower[k] - (p[k] - s_.radius[i])) / s_.radius[i]);
      worst = std::max(worst, ((p[k] + s_.radius[i]) - b.upper[k]) / s_.radius[i]);
    }
    for (std::size_t j = i + 1; j < s_.size(); ++j) {
      const double dx = p[0] - s_.x[j], dy = p[1] - s_.y[j], dz = p[2] - s_.z[j];
      worst = std::max(worst, 1.0 - std::sqrt(dx * dx + dy * dy + dz * dz) / (s_.radius[i] + s_.radius[j]));
    }
  }
  return worst;
}

}  // namespace dlpverify::events
