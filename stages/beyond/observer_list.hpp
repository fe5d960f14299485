// Several observers on stage 7's one hook (beyond the article).
//
// What this file does: stage 7 tells one CollisionObserver of each collision
// and of the key B; a run that keeps kinetic theory's sums and follows the
// Lyapunov exponent too hangs this list there, which tells each of its
// observers in turn.
// Article: none (stage 7's hook is beyond the article too).
// Lesson: lessons/15-chaos.md
#pragma once

#include <utility>
#include <vector>

#include "stage7_control.hpp"

namespace gas {

class ObserverList final : public CollisionObserver {
 public:
  // The observers, told in this order; each must outlive the list.
  explicit ObserverList(std::vector<CollisionObserver*> observers)
      : observers_(std::move(observers)) {}

  void before_collision(const Gas& gas, const Collision& collision) override {
    for (CollisionObserver* o : observers_) o->before_collision(gas, collision);
  }
  void after_collision(const Gas& gas, const Collision& collision) override {
    for (CollisionObserver* o : observers_) o->after_collision(gas, collision);
  }
  void before_rows_rewritten(const Gas& gas) override {
    for (CollisionObserver* o : observers_) o->before_rows_rewritten(gas);
  }

 private:
  std::vector<CollisionObserver*> observers_;
};

}  // namespace gas
