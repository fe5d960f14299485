// A coverage-guided fuzzer (clang's libFuzzer) for stage 2, the scene reader:
// any bytes at all must either give a Gas that the later stages can run, or
// a SceneError — never a crash, a hang, undefined behaviour or a leak (the
// fuzzer runs with AddressSanitizer and UndefinedBehaviorSanitizer) — and
// the same message with either search for overlaps.
//
// Built with -DGAS_FUZZ=ON and clang; run by .ci/fuzz with a corpus seeded
// from the scenes in data/.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "beyond/overlap_cells.hpp"
#include "beyond/random_placement.hpp"
#include "stage2_input.hpp"
#include "stage7_control.hpp"

namespace {

// What stage 2 alone says about `text` with `search`: "" if it accepts it.
std::string refusal(std::string_view text, const gas::OverlapSearch& search) {
  try {
    gas::parse_scene_description(text, "fuzz.scene", search);
  } catch (const gas::SceneError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // The search for overlaps through cells says what the search of every pair
  // says, to the character.
  if (refusal(text, gas::first_overlap_of_all_pairs) !=
      refusal(text, gas::first_overlap_by_cells)) {
    std::abort();
  }
  gas::Gas gas;
  try {
    gas = gas::parse_scene(text, "fuzz.scene");
  } catch (const gas::SceneError&) {
    return 0;  // refused with a message: fine
  }
  // What stage 2 accepts must be a gas the loop can run: a few steps, every
  // centre finite and within its limits (up to the contact slack).
  if (gas.balls.size() > 64) return 0;  // keep each input fast
  gas::Control control = gas::start_control(gas);
  for (int i = 0; i < 20; ++i) gas::take_step(control, gas::never, nullptr);
  const double slack = 2 * gas::contact_tolerance * 2 * gas.radius;
  for (const gas::Ball& ball : control.gas.balls) {
    const gas::Point p = gas::centre_at(ball, control.gas.time);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) ||
        p.x < control.limits.x_min - slack || p.x > control.limits.x_max + slack ||
        p.y < control.limits.y_min - slack || p.y > control.limits.y_max + slack) {
      std::abort();
    }
  }
  return 0;
}
