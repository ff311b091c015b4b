// The future event list: a binary min-heap of candidate events, invalidated lazily (the design of
// event-driven MD codes such as DynamO): every event records the collision counts its particles
// had when it was predicted; a popped event whose counts no longer match is stale.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace dlpverify::events {

struct Event {
  double t;              // absolute time
  std::int32_t a;        // the particle whose prediction this is
  std::int32_t partner;  // ≥ 0: a particle; < 0: wall −1 − w (w = 2·axis + side)
  std::uint32_t count_a, count_partner;
};

inline constexpr std::int32_t wall_partner(int wall) { return -1 - wall; }
inline constexpr int wall_of(std::int32_t partner) { return -1 - partner; }

class EventQueue {
 public:
  void clear() { heap_.clear(); }
  bool empty() const { return heap_.empty(); }
  std::size_t size() const { return heap_.size(); }
  const Event& top() const { return heap_.front(); }
  void push(const Event& e) {
    heap_.push_back(e);
    std::push_heap(heap_.begin(), heap_.end(), later);
  }
  Event pop() {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const Event e = heap_.back();
    heap_.pop_back();
    return e;
  }

 private:
  // Earliest first; ties broken by the particle indices so the order never depends on the heap's
  // history beyond what was pushed (deterministic runs).
  static bool later(const Event& x, const Event& y) {
    if (x.t != y.t) return x.t > y.t;
    if (x.a != y.a) return x.a > y.a;
    return x.partner > y.partner;
  }
  std::vector<Event> heap_;
};

}  // namespace dlpverify::events
