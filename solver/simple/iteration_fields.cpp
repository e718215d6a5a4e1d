// Storage of the values the steps of an outer iteration hand each other (iteration_fields.hpp).
#include "solver/simple/iteration_fields.hpp"

namespace bagnold::solver {

ClosureFields::ClosureFields(std::size_t local_count)
    : drag(local_count, 0.0),
      viscosity{std::vector<double>(local_count, 0.0), std::vector<double>(local_count, 0.0)},
      bulk_viscosity(local_count, 0.0),
      pressure_derivative(local_count, 0.0),
      strain_rate(local_count, 0.0),
      divergence{std::vector<double>(local_count, 0.0), std::vector<double>(local_count, 0.0)} {}

CarriedFractions::CarriedFractions(std::size_t local_count) {
  for (auto& phase : value)
    for (auto& d : phase) d.assign(local_count, 0.0);
}

CorrectionResponse::CorrectionResponse(std::size_t local_count) {
  for (auto& phase : pressure)
    for (auto& d : phase) d.assign(local_count, 0.0);
  for (auto& d : fraction) d.assign(local_count, 0.0);
  for (auto& d : friction) d.assign(local_count, 0.0);
}

}  // namespace bagnold::solver
