// bagnold rheometer: a solids-stress model under steady homogeneous simple shear, as CSV
// (models/stress/rheometer.hpp). Material from --set (deck keys) or --deck.
#include <cmath>
#include <iostream>

#include "models/stress/rheometer.hpp"
#include "src/app/commands.hpp"
#include "src/app/exit_codes.hpp"
#include "src/deck/load.hpp"

namespace bagnold::app {

int rheometer_command(const RheometerArguments& args) {
  std::vector<std::string> overrides = args.overrides;
  overrides.push_back("models.solids_stress.model=" + args.model);
  deck::Deck deck;
  try {
    deck = deck::load_material_and_models(args.deck, overrides);
  } catch (const deck::DeckError& e) {
    say(std::string(e.what()) + "bagnold rheometer: invalid material or model", true);
    return bad_input;
  }
  for (double phi : args.phis)
    if (!(phi >= 0.0 && phi < 1.0)) {
      say("bagnold rheometer: --phi " + std::to_string(phi) + " is outside [0, 1)", true);
      return bad_input;
    }
  for (double rate : args.shear_rates)
    if (!(rate >= 0.0) || !std::isfinite(rate)) {
      say("bagnold rheometer: --shear-rate " + std::to_string(rate) + " must be >= 0", true);
      return bad_input;
    }
  const auto& choice = deck.models.solids_stress;
  const auto model = models::stress_registry().create(choice.name, choice.coefficients);
  const auto rows = models::shear_rheometer(*model, deck.solids.material, args.phis, args.shear_rates);
  models::write_rheometer_csv(std::cout, rows, true);
  return success;
}

}  // namespace bagnold::app
