// Where pictures are taken (stages/beyond/display_steps.hpp, lesson 7): at
// every collision for the small scenes, as in the article; only at the
// display steps for the large ones. The rule changes when pictures are
// taken, never what happens: the collisions (suite end-to-end, "T0 never
// changes the physics ... under either picture rule") and the statistics
// are the same, bit for bit.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "beyond/display_steps.hpp"
#include "beyond/random_placement.hpp"
#include "beyond/strategy.hpp"
#include "support.hpp"

using gas::PictureRule;
using gas::testing::lines_of;
using gas::testing::read_file;
using gas::testing::run_program;
using gas::testing::Scratch;
using gas::testing::source_path;

namespace {

// The first column (T) of each row of a --csv file, its header left out.
std::vector<std::string> times_of(const std::string& csv_path) {
  std::vector<std::string> times;
  const std::vector<std::string> lines = lines_of(read_file(csv_path));
  for (std::size_t i = 1; i < lines.size(); ++i)
    times.push_back(lines[i].substr(0, lines[i].find(',')));
  return times;
}

// What `gas` writes for SCENE --until UNTIL --mode none with `more`
// arguments: its --csv, --events and --dump files.
struct Written {
  std::string csv, events, dump;
};
Written batch_run(const std::string& scene, const std::string& until,
                  const std::vector<std::string>& more) {
  const Scratch scratch;
  std::vector<std::string> arguments = {scene,
                                        "--until",
                                        until,
                                        "--mode",
                                        "none",
                                        "--csv",
                                        scratch.file("c.csv"),
                                        "--events",
                                        scratch.file("e.csv"),
                                        "--dump",
                                        scratch.file("d.scene")};
  arguments.insert(arguments.end(), more.begin(), more.end());
  const auto run = run_program(arguments);
  REQUIRE(run.status == 0);
  CHECK(run.out.empty());  // --mode none: nothing drawn
  CHECK(run.err.empty());
  return {read_file(scratch.file("c.csv")), read_file(scratch.file("e.csv")),
          read_file(scratch.file("d.scene"))};
}

}  // namespace

TEST_SUITE("pictures") {
  TEST_CASE(
      "the picture rule: the article's for the small scenes and display steps for "
      "the large ones") {
    for (const std::string scene :
         {"data/default.scene", "data/crowd.scene", "data/head-on.scene",
          "data/one-ball.scene", "data/trajectories.scene"}) {
      CAPTURE(scene);
      CHECK(
          gas::picture_rule_for(gas::read_scene_file(source_path(scene)).balls.size()) ==
          PictureRule::every_collision);
    }
    for (const std::string scene :
         {"data/kinetic.scene", "data/large-1000.scene", "data/large-10000.scene"}) {
      CAPTURE(scene);
      CHECK(
          gas::picture_rule_for(gas::read_scene_file(source_path(scene)).balls.size()) ==
          PictureRule::display_steps);
    }
    // The names of --pictures, both ways.
    for (const PictureRule rule :
         {PictureRule::every_collision, PictureRule::display_steps})
      CHECK(gas::picture_rule_named(gas::picture_rule_name(rule)) == rule);
    CHECK_FALSE(gas::picture_rule_named("never"));
  }

  TEST_CASE(
      "--csv has one row per picture: at every T0 for a large scene and at the "
      "collisions too for a small one") {
    const Scratch scratch;
    const std::string csv = scratch.file("c.csv");
    // A large scene: a row at each display step, and only there.
    REQUIRE(run_program(
                {"data/large-1000.scene", "--until", "5", "--mode", "none", "--csv", csv})
                .status == 0);
    CHECK(times_of(csv) == std::vector<std::string>{"1", "2", "3", "4", "5"});
    // The same with --pictures collisions: five pictures, each at one of the
    // first collisions (the first at 0.0067), long before T0 = 1.
    REQUIRE(run_program({"data/large-1000.scene", "--frames", "5", "--mode", "none",
                         "--pictures", "collisions", "--csv", csv})
                .status == 0);
    const std::vector<std::string> at_collisions = times_of(csv);
    REQUIRE(at_collisions.size() == 5);
    for (const std::string& t : at_collisions) CHECK(std::stod(t) < 0.1);

    // The default scene: its first collision, TC = 34.5454..., ends a step
    // and gets a row of its own; with --pictures steps it does not.
    REQUIRE(run_program({"--until", "40", "--mode", "none", "--csv", csv}).status == 0);
    const std::vector<std::string> small = times_of(csv);
    CHECK(small.size() > 40);
    CHECK(std::count(small.begin(), small.end(), "34.54545454545454") == 1);
    REQUIRE(run_program(
                {"--until", "40", "--mode", "none", "--pictures", "steps", "--csv", csv})
                .status == 0);
    const std::vector<std::string> steps = times_of(csv);
    REQUIRE(steps.size() == 40);
    for (std::size_t i = 0; i < steps.size(); ++i)
      CHECK(steps[i] == std::to_string(i + 1));
  }

  TEST_CASE(
      "the statistics and the events and the dump are the same whether pictures are "
      "taken or not") {
    // Every figure of the last --csv row (the averages, their errors, the
    // histogram behind them) is kept collision by collision: at T = 7 it is
    // the same to the last digit under both rules. The 1000 balls collide
    // about 3000 times by then, the 200 of the kinetic scene some 550.
    for (const std::string scene : {"data/large-1000.scene", "data/kinetic.scene"}) {
      CAPTURE(scene);
      const Written steps = batch_run(scene, "7", {"--pictures", "steps"});
      const Written collisions = batch_run(scene, "7", {"--pictures", "collisions"});
      const std::vector<std::string> a = lines_of(steps.csv),
                                     b = lines_of(collisions.csv);
      REQUIRE(a.size() == 8);  // the header, and T = 1 ... 7
      REQUIRE(b.size() > 100);
      CHECK(a.back().rfind("7,", 0) == 0);
      CHECK(a.back() == b.back());
      CHECK(lines_of(steps.events).size() > 500);
      CHECK(steps.events == collisions.events);
      CHECK(steps.dump == collisions.dump);
    }
  }

  TEST_CASE(
      "a display step that keeps no picture and no list of collisions carries out the "
      "same collisions, bit for bit, and holds neither") {
    // What --mode none without --events asks of a step (StepKeeps): the same
    // gas after 5 steps of 1000 balls (some 2000 collisions) as steps that
    // keep both, to the bit; no centres, no list; the same count.
    const gas::Gas start = gas::read_scene_file(source_path("data/large-1000.scene"));
    gas::Control kept = gas::start_control_for(start);
    gas::Control bare = gas::start_control_for(start);
    bare.picture = gas::Picture{};
    std::size_t listed = 0;
    for (int k = 0; k < 5; ++k) {
      listed += gas::take_display_step(kept, gas::never, nullptr).collisions.size();
      const gas::Step step =
          gas::take_display_step(bare, gas::never, nullptr, {false, false});
      CHECK(step.collisions.empty());
      CHECK(step.length == 1);
    }
    CHECK(listed > 1500);
    CHECK(bare.picture.centres.empty());
    CHECK(bare.picture.old_centres.empty());
    CHECK(kept.picture.centres.size() == start.balls.size());
    CHECK(bare.gas.time == kept.gas.time);
    CHECK(bare.wall_collisions + bare.ball_collisions == static_cast<long long>(listed));
    CHECK(bare.wall_collisions == kept.wall_collisions);
    for (std::size_t i = 0; i < start.balls.size(); ++i) {
      const gas::Ball &a = bare.gas.balls[i], &b = kept.gas.balls[i];
      REQUIRE(a.x == b.x);
      REQUIRE(a.y == b.y);
      REQUIRE(a.vx == b.vx);
      REQUIRE(a.vy == b.vy);
      REQUIRE(a.since == b.since);
    }
  }

  TEST_CASE(
      "B on a large gas drawn at display steps: reverse then as long again then "
      "reverse and it is back at its start") {
    // 1000 balls at area fraction 0.3, 3 time units each way: about 2.7
    // collisions per ball, some 1400 collisions each way.
    const gas::Gas start = gas::read_scene_file(source_path("data/large-1000.scene"));
    gas::Control control = gas::start_control_for(start);
    long long collisions = 0;
    auto run_to = [&](double end) {
      while (control.gas.time < end) {
        collisions += static_cast<long long>(
            gas::take_display_step(control, end, nullptr).collisions.size());
      }
    };
    run_to(3);
    gas::press_key(control, 'B');
    run_to(6);
    gas::press_key(control, 'B');
    CHECK(collisions > 2000);
    // Each collision amplifies an error by a factor of a few in the
    // directions it mixes (lesson 9); with under three collisions per ball
    // each way, rounding errors of 1e-16 relative grow to about 1e-12 at
    // most. 1e-8 radii is far above that, and a reversal that missed or
    // misordered one collision would be off by a radius or more.
    double farthest = 0;
    for (std::size_t i = 0; i < start.balls.size(); ++i) {
      const gas::Point now = gas::centre_at(control.gas.balls[i], 6);
      farthest = std::max(farthest,
                          std::hypot(now.x - start.balls[i].x, now.y - start.balls[i].y));
    }
    CAPTURE(farthest);
    CHECK(farthest < 1e-8);
  }
}
