// Stage 4 — first collision, by a table of next events. See
// beyond/event_table.hpp.
#include "beyond/event_table.hpp"

#include "beyond/event_order.hpp"

namespace gas {

namespace {

int ball_count(const Gas& gas) {
  return static_cast<int>(gas.balls.size());
}

}  // namespace

// Keeps the event in ball's entry if it comes before what is there.
void EventTable::offer(int ball, double time, CollisionKind kind, int partner) {
  if (!(time < never)) return;  // the scan ignores what never happens
  const std::uint64_t place =
      kind == CollisionKind::balls
          ? scan_place(kind, std::min(ball, partner), std::max(ball, partner))
          : scan_place(kind, ball, 0);
  Entry& entry = next_[static_cast<std::size_t>(ball - 1)];
  if (comes_before(time, place, entry.time, entry.place))
    entry = {time, place, kind, partner};
}

void EventTable::predict_walls(const Gas& gas, int ball) {
  next_[static_cast<std::size_t>(ball - 1)] = Entry{};
  for (const CollisionKind wall :
       {CollisionKind::horizontal_wall, CollisionKind::vertical_wall}) {
    offer(ball, wall_time(gas, limits_, ball, wall), wall, 0);
  }
}

void EventTable::rebuild(const Gas& gas, const CentreLimits& limits) {
  limits_ = limits;
  const int n = ball_count(gas);
  next_.assign(static_cast<std::size_t>(n), Entry{});
  for (int i = 1; i <= n; ++i) predict_walls(gas, i);
  for (int n3 = 1; n3 < n; ++n3) {
    for (int n4 = n3 + 1; n4 <= n; ++n4) {
      const double time = pair_time(gas, n3, n4);
      offer(n3, time, CollisionKind::balls, n4);
      offer(n4, time, CollisionKind::balls, n3);
    }
  }
}

// [anchor: table-first]
Collision EventTable::first(const Gas& gas) {
  const Entry* earliest = nullptr;
  for (const Entry& entry : next_) {
    if (entry.kind == CollisionKind::none) continue;
    if (earliest == nullptr ||
        comes_before(entry.time, entry.place, earliest->time, earliest->place))
      earliest = &entry;
  }
  if (earliest == nullptr) return Collision{};  // K = 0: nothing will ever collide
  const int ball = static_cast<int>(earliest - next_.data()) + 1;
  Collision first{earliest->time, earliest->kind, ball, 0};
  if (earliest->kind == CollisionKind::balls) {
    first.first = std::min(ball, earliest->partner);
    first.second = std::max(ball, earliest->partner);
  }
  return due_from(first, gas.time);
}
// [/anchor: table-first]

// [anchor: table-update]
void EventTable::update(const Gas& gas, const Collision& done) {
  if (done.kind == CollisionKind::none) return;
  const int n = ball_count(gas);
  const int n1 = done.first;
  const int n2 = done.kind == CollisionKind::balls ? done.second : 0;
  auto collided = [&](int ball) { return ball == n1 || ball == n2; };
  // A ball whose earliest event was a meeting with N1 or N2 has lost it.
  std::vector<int> lost;
  for (int k = 1; k <= n; ++k) {
    const Entry& entry = next_[static_cast<std::size_t>(k - 1)];
    if (!collided(k) && entry.kind == CollisionKind::balls && collided(entry.partner))
      lost.push_back(k);
  }
  // N1 and N2 against the walls and every other ball; the others' entries
  // take the new meetings if they come first.
  for (const int m : {n1, n2}) {
    if (m == 0) continue;
    predict_walls(gas, m);
    for (int k = 1; k <= n; ++k) {
      if (k == m) continue;
      const double time = pair_time(gas, std::min(m, k), std::max(m, k));
      offer(m, time, CollisionKind::balls, k);
      if (!collided(k)) offer(k, time, CollisionKind::balls, m);
    }
  }
  // The balls that lost their event: predicted again in full.
  for (const int k : lost) {
    predict_walls(gas, k);
    for (int j = 1; j <= n; ++j) {
      if (j != k)
        offer(k, pair_time(gas, std::min(j, k), std::max(j, k)), CollisionKind::balls, j);
    }
  }
}
// [/anchor: table-update]

}  // namespace gas
