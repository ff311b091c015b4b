// An event-driven simulation of hard spheres in a box whose six walls move at constant speeds
// (docs/model.md §7.2). No time step: spheres fly freely between events, each event (a pair
// collision, a wall hit) is found exactly (event_times.hpp) and kept in a priority queue with
// lazy invalidation (event_queue.hpp).
//
// Each sphere keeps its position at its own last-update time ("delayed states"), so an event
// touches only the spheres it involves: O(N) work per event (its spheres against all others),
// no cell lists — enough for the hundreds of spheres this suite simulates. Only each sphere's
// earliest predicted event is queued; when a queued event's partner has collided meanwhile, the
// sphere's next event is predicted afresh.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "events/collision_rule.hpp"
#include "events/event_queue.hpp"

namespace dlpverify::events {

// Spheres as arrays (one array per coordinate: the prediction loop runs over them).
struct Spheres {
  std::vector<double> x, y, z, vx, vy, vz, wx, wy, wz;  // position, velocity, angular velocity
  std::vector<double> radius, mass;
  std::size_t size() const { return x.size(); }
  void add(std::array<double, 3> position, std::array<double, 3> velocity, double r, double m);
};

// The box: along each axis k a lower and an upper wall, at lower[k] + lower_speed[k] (t − t0)
// and upper[k] + upper_speed[k] (t − t0), t0 the time the speeds were last set.
struct Box {
  std::array<double, 3> lower{}, upper{}, lower_speed{}, upper_speed{};
};

struct EventCounts {
  std::int64_t pair = 0, wall = 0, stale = 0;
};

class EventEngine {
 public:
  // Throws InputError if a sphere overlaps another or a wall.
  EventEngine(Spheres spheres, Box box, CollisionModel model = {});

  double time() const { return now_; }
  const EventCounts& counts() const { return counts_; }
  // After every event, check that no pair overlaps and no sphere crosses a wall (O(N²) per
  // event: a debug mode). A violation beyond round-off throws SolverError.
  void check_overlaps(bool on) { check_overlaps_ = on; }

  // A run past this many pair and wall events in all throws SolverError: inelastic collapse
  // (e < 1) or a jammed gas have ever more events in ever less time. 0: no limit.
  void limit_events(std::int64_t limit) { event_limit_ = limit; }

  // Processes every event up to time t_end, then moves all spheres to t_end.
  void run_until(double t_end);
  // Processes `events` more pair and wall events (stale ones not counted).
  void run_events(std::int64_t events);
  // From now on the walls move at these speeds (m/s, along +axis): every prediction is redone.
  void set_wall_speeds(const std::array<double, 3>& lower_speed, const std::array<double, 3>& upper_speed);

  // The spheres and walls at the current time.
  const Spheres& spheres();
  Box box() const;
  double kinetic_energy();            // translational, Σ ½ m v²
  double rotational_energy();         // Σ ½ I ω², I = (2/5) m R²
  // The largest overlap of a pair, 1 − |r_ab| / (R_a + R_b), or of a wall (as a fraction of R); ≤ 0: none.
  double worst_overlap();

 private:
  void move_to_now(std::size_t i);
  void move_all_to_now();
  double wall_position(int wall) const;
  void predict(std::size_t i);
  void predict_all();
  bool process(const Event& e);  // false: the event was stale
  void process_pair(std::size_t a, std::size_t b);
  void process_wall(std::size_t a, int wall);

  Spheres s_;
  std::vector<double> t_;        // each sphere's last-update time
  std::vector<std::uint32_t> n_; // each sphere's collision count (invalidates its old events)
  std::vector<double> scratch_;  // pair times of one prediction
  Box box_;
  double box_time_ = 0.0;        // t0 of box_
  CollisionModel model_;
  EventQueue queue_;
  EventCounts counts_;
  double now_ = 0.0;
  bool check_overlaps_ = false;
  std::int64_t event_limit_ = 0;
};

}  // namespace dlpverify::events
