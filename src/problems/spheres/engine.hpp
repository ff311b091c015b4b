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
//
// Every event is checked against what the physics keeps (invariants.hpp), and every run against a
// bound on its work (WorkBound): a fault stops the run with SolverError and its reason, never a hang.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "problems/spheres/collision_rule.hpp"
#include "problems/spheres/event_queue.hpp"

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

// The engine's bound on its own work: a run that reaches it throws SolverError saying how many
// events it did, the simulated time it reached and the bound, instead of running on. Events that
// repeat without time passing (a collision that leaves its spheres approaching), inelastic collapse
// and a jammed gas all have ever more events in ever less simulated time.
struct WorkBound {
  std::int64_t events = 0;   // pair and wall events in all; 0: no limit
  // Events per second of simulated time, as a multiple of the gas's kinetic-theory rate Γ
  // (EventEngine::kinetic_theory_rate): every window of rate_window() events must last at least
  // window / (rate_factor · Γ), Γ the larger of its values at the window's start and end. 0: unchecked.
  double rate_factor = 100.0;
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

  // The bound on this engine's work (WorkBound; by default only the rate is bounded).
  void bound_work(const WorkBound& bound) { bound_ = bound; }
  const WorkBound& work_bound() const { return bound_; }
  // Events in one window of the rate bound: 1000, or 10 per sphere when there are more than 100.
  std::int64_t rate_window() const;
  // The events per second kinetic theory expects of the present state (docs/model.md §7.2.1):
  //   walls  Σ_i Σ_k (|v_ik| + |u_k,lower| + |u_k,upper|) / (L_k − 2R_i): a free sphere crosses the
  //          length its centre can reach once per wall hit, a moving wall meets it sooner;
  //   pairs  ½ N (N − 1)/V · π σ² √(2⟨v²⟩) g(η): Enskog's rate, σ = 2 R_max, √(2⟨v²⟩) bounding the
  //          mean relative speed, g(η) = (1 − η/2)/(1 − η)³ (Carnahan–Starling's contact value).
  double kinetic_theory_rate() const;

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
  void check_work();             // after each event: the WorkBound
  void start_rate_window();
  [[noreturn]] void fail(const std::string& what) const;
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
  WorkBound bound_;
  std::int64_t window_events_ = 0;  // events since the rate window started
  double window_time_ = 0.0;        // when it started
  double window_rate_ = 0.0;        // Γ then
};

}  // namespace dlpverify::events
