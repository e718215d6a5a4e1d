#include "solver/simple/anderson_mixing.hpp"

#include <algorithm>
#include <cmath>
#include <span>

namespace bagnold::solver {

namespace {
constexpr std::size_t field_count = 9;  // u_g (3), u_s (3), P_g, ε_s, ε_g
constexpr std::size_t pressure_field = 6, solids_fraction_field = 7;
// A change of 0.01 in a volume fraction weighs as much as a change of the velocity scale: the
// weighting that converged the 10 mm bin's steps in the fewest iterations of those tried
// (fractions weighted 1, 10⁴, 10⁶ against the velocity scale; docs/solver.md).
constexpr double fraction_scale = 0.01;

// The fields mixed, in packing order.
template <class State>
auto mixed_fields(State& state) {
  return std::array{&state.gas_velocity[0],    &state.gas_velocity[1],    &state.gas_velocity[2],
                    &state.solids_velocity[0], &state.solids_velocity[1], &state.solids_velocity[2],
                    &state.gas_pressure,       &state.solids_fraction,    &state.gas_fraction};
}

// Solves the small symmetric system A γ = b (row-major m × m) by Gaussian elimination with
// partial pivoting; false if a pivot vanishes against the matrix's size.
bool solve_small(std::vector<double> a, std::vector<double> b, std::size_t m, std::vector<double>& x) {
  double size = 0.0;
  for (const double v : a) size = std::max(size, std::abs(v));
  if (!(size > 0.0) || !std::isfinite(size)) return false;
  for (std::size_t c = 0; c < m; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < m; ++r)
      if (std::abs(a[r * m + c]) > std::abs(a[pivot * m + c])) pivot = r;
    if (std::abs(a[pivot * m + c]) <= 1e-13 * size) return false;
    if (pivot != c) {
      for (std::size_t k = 0; k < m; ++k) std::swap(a[c * m + k], a[pivot * m + k]);
      std::swap(b[c], b[pivot]);
    }
    for (std::size_t r = c + 1; r < m; ++r) {
      const double factor = a[r * m + c] / a[c * m + c];
      for (std::size_t k = c; k < m; ++k) a[r * m + k] -= factor * a[c * m + k];
      b[r] -= factor * b[c];
    }
  }
  x.assign(m, 0.0);
  for (std::size_t c = m; c-- > 0;) {
    double sum = b[c];
    for (std::size_t k = c + 1; k < m; ++k) sum -= a[c * m + k] * x[k];
    x[c] = sum / a[c * m + c];
  }
  return true;
}
}  // namespace

AndersonMixing::AndersonMixing(const parallel::Layout& layout, int depth)
    : m_layout(layout),
      m_depth(static_cast<std::size_t>(std::max(depth, 1))),
      m_owned(static_cast<std::size_t>(layout.owned_count())) {}

void AndersonMixing::start_step(const run::FlowState& old) {
  m_delta_f.clear();
  m_delta_g.clear();
  m_has_last = false;
  double low = INFINITY, high = -INFINITY;
  for (std::size_t l = 0; l < static_cast<std::size_t>(m_layout.owned_fluid_count()); ++l) {
    low = std::min(low, old.gas_pressure[l]);
    high = std::max(high, old.gas_pressure[l]);
  }
  const auto& comm = m_layout.comm();
  const double range = comm.max(high) + comm.max(-low);
  const double scale = std::isfinite(range) ? std::max(range, 1.0) : 1.0;
  m_pressure_weight = 1.0 / (scale * scale);
}

void AndersonMixing::pack(const run::FlowState& state, std::vector<double>& into) const {
  into.resize(field_count * m_owned);
  const auto fields = mixed_fields(state);
  for (std::size_t f = 0; f < field_count; ++f)
    std::copy_n(fields[f]->begin(), m_owned, into.begin() + static_cast<std::ptrdiff_t>(f * m_owned));
}

void AndersonMixing::unpack(const std::vector<double>& from, run::FlowState& state) const {
  const auto fields = mixed_fields(state);
  for (std::size_t f = 0; f < field_count; ++f) {
    std::copy_n(from.begin() + static_cast<std::ptrdiff_t>(f * m_owned), m_owned, fields[f]->begin());
    parallel::exchange_halo(m_layout, std::span<double>(*fields[f]));
  }
}

double AndersonMixing::dot(const std::vector<double>& a, const std::vector<double>& b) const {
  double result = 0.0;
  for (std::size_t f = 0; f < field_count; ++f) {
    const double weight = f < pressure_field    ? m_velocity_weight
                          : f == pressure_field ? m_pressure_weight
                                                : 1.0 / (fraction_scale * fraction_scale);
    double sum = 0.0;
    for (std::size_t i = f * m_owned; i < (f + 1) * m_owned; ++i) sum += a[i] * b[i];
    result += weight * sum;
  }
  return result;
}

void AndersonMixing::remember_input(const run::FlowState& state) { pack(state, m_input); }

long AndersonMixing::mix(run::FlowState& state, double velocity_scale) {
  m_velocity_weight = 1.0 / (velocity_scale * velocity_scale);
  pack(state, m_image);
  m_residual.resize(m_image.size());
  for (std::size_t i = 0; i < m_image.size(); ++i) m_residual[i] = m_image[i] - m_input[i];
  if (m_has_last) {
    // The newest difference goes last; when the history is full it reuses the oldest's storage.
    if (m_delta_f.size() == m_depth) {
      std::rotate(m_delta_f.begin(), m_delta_f.begin() + 1, m_delta_f.end());
      std::rotate(m_delta_g.begin(), m_delta_g.begin() + 1, m_delta_g.end());
    } else {
      m_delta_f.emplace_back();
      m_delta_g.emplace_back();
    }
    auto& df = m_delta_f.back();
    auto& dg = m_delta_g.back();
    df.resize(m_image.size());
    dg.resize(m_image.size());
    for (std::size_t i = 0; i < m_image.size(); ++i) {
      df[i] = m_residual[i] - m_last_residual[i];
      dg[i] = m_image[i] - m_last_image[i];
    }
  }
  m_last_residual = m_residual;
  m_last_image = m_image;
  m_has_last = true;
  const std::size_t m = m_delta_f.size();
  if (m == 0) return 0;

  // The normal equations of the weighted least-squares fit, summed over the ranks at once.
  std::vector<double> sums(m * m + m);
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j <= i; ++j) sums[i * m + j] = sums[j * m + i] = dot(m_delta_f[i], m_delta_f[j]);
    sums[m * m + i] = dot(m_delta_f[i], m_residual);
  }
  m_layout.comm().sum_in_place(sums);
  std::vector<double> gram(sums.begin(), sums.begin() + static_cast<std::ptrdiff_t>(m * m));
  std::vector<double> rhs(sums.begin() + static_cast<std::ptrdiff_t>(m * m), sums.end());
  std::vector<double> gamma;
  const bool solved = solve_small(gram, rhs, m, gamma);

  // The mixture G(x_k) − ΔG γ; where it would take ε_s outside [0, the images' largest ε_s],
  // ε_s is clipped into that range (and ε_g = 1 − ε_s). A fit that fails restarts the history
  // and keeps Picard's image.
  const auto& comm = m_layout.comm();
  std::vector<double>& mixed = m_input;  // x_k is not needed any more
  mixed = m_image;
  bool finite = solved;
  if (solved)
    for (std::size_t j = 0; j < m; ++j)
      for (std::size_t i = 0; i < mixed.size(); ++i) mixed[i] -= gamma[j] * m_delta_g[j][i];
  for (std::size_t i = 0; finite && i < mixed.size(); ++i) finite = std::isfinite(mixed[i]);
  if (comm.max(std::int64_t{finite ? 0 : 1}) != 0) {
    m_delta_f.clear();
    m_delta_g.clear();
    return 0;
  }
  const std::size_t solids = solids_fraction_field * m_owned, gas = solids + m_owned;
  double solids_high = 0.0;
  for (std::size_t i = 0; i < m_owned; ++i) solids_high = std::max(solids_high, m_image[solids + i]);
  solids_high = comm.max(solids_high);
  long clipped = 0;
  for (std::size_t i = 0; i < m_owned; ++i) {
    const double e = std::clamp(mixed[solids + i], 0.0, solids_high);
    if (e != mixed[solids + i]) {
      ++clipped;
      mixed[solids + i] = e;
      mixed[gas + i] = 1.0 - e;
    }
  }
  unpack(mixed, state);
  return clipped;
}

}  // namespace bagnold::solver
