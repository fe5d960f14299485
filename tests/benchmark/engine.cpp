// The engine's event loop and its speed. See engine.hpp.
#include "engine.hpp"

#include "time_stepped.hpp"  // cpu_seconds

namespace gas::benchmark {

EventLoop::EventLoop(const Gas& start, Strategy strategy)
    : gas(start), limits(centre_limits(start)), finder(make_finder(strategy)) {
  finder->rebuild(gas, limits);
}

Collision EventLoop::step() {
  const Collision c = finder->first(gas);
  if (c.kind == CollisionKind::none) return c;
  gas.time = c.time;
  apply_collision(gas, limits, c);
  finder->update(gas, c);
  return c;
}

long long EventLoop::run_to(double end) {
  long long count = 0;
  for (Collision c = finder->first(gas); c.kind != CollisionKind::none && c.time <= end;
       c = finder->first(gas)) {
    gas.time = c.time;
    apply_collision(gas, limits, c);
    finder->update(gas, c);
    ++count;
  }
  gas.time = end;
  return count;
}

std::pair<long long, double> run_for(EventLoop& loop, double budget, long long most) {
  long long done = 0, batch = 1;
  const double start = cpu_seconds();
  double elapsed = 0;
  while (elapsed < budget && done < most) {
    const double batch_start = cpu_seconds();
    for (long long i = 0; i < batch; ++i) loop.step();
    done += batch;
    elapsed = cpu_seconds() - start;
    if (batch < 4096 && cpu_seconds() - batch_start < 0.005) batch *= 2;
  }
  return {done, elapsed};
}

Throughput measure_throughput(const Gas& gas, Strategy strategy, double budget) {
  const double start = cpu_seconds();
  EventLoop loop(gas, strategy);
  Throughput result{strategy, 0, gas.balls.size(), cpu_seconds() - start, 0, 0};
  // Warm up: a collision per ball (the grid's lists reach their working
  // sizes), or a quarter of the budget.
  run_for(loop, budget / 4, static_cast<long long>(gas.balls.size()));
  // Three rounds, the best kept: the machine's noise (another program's use
  // of the shared cache, say) only ever slows a round down.
  for (int round = 0; round < 3; ++round) {
    const auto [collisions, seconds] = run_for(loop, budget / 3, 1LL << 40);
    if (result.collisions == 0 || collisions / seconds > result.per_second()) {
      result.collisions = collisions;
      result.seconds = seconds;
    }
  }
  return result;
}

}  // namespace gas::benchmark
