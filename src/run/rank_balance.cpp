// Per-rank counters of cells and seconds, gathered and shown (rank_balance.hpp).
#include "src/run/rank_balance.hpp"

#include "src/run/work_weights.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

namespace bagnold::run {

namespace {

constexpr std::size_t counter_count = 6;  // before the busy segments

// The counters, then the busy segments and the work units, each padded with zeros to `segments`.
std::vector<double> pack(const RankCounters& c, std::size_t segments) {
  std::vector<double> v = {c.owned_cells, c.fluid_cells, c.solids_cells, c.seconds.assembly,
                           c.seconds.solves, c.seconds.waits};
  for (const auto* series : {&c.busy_segments, &c.work_units}) {
    const std::size_t start = v.size();
    v.insert(v.end(), series->begin(), series->end());
    v.resize(start + segments, 0.0);
  }
  return v;
}

RankCounters unpack(const double* v, std::size_t segments) {
  RankCounters c{v[0], v[1], v[2], RankSeconds{v[3], v[4], v[5]}, {}, {}};
  c.busy_segments.assign(v + counter_count, v + counter_count + segments);
  c.work_units.assign(v + counter_count + segments, v + counter_count + 2 * segments);
  return c;
}

double at(const std::vector<double>& series, std::size_t k) { return k < series.size() ? series[k] : 0.0; }

// max/min of values over the ranks, as text: "inf" when the smallest is 0 and the largest not.
std::string ratio(const std::vector<double>& values) {
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  const double smallest = *low, largest = *high;
  if (largest == 0.0) return "1.00";
  if (smallest == 0.0) return "inf";
  return fmt::format("{:.2f}", largest / smallest);
}
template <class Value>
std::string ratio(const std::vector<RankCounters>& ranks, Value value) {
  std::vector<double> values;
  for (const auto& r : ranks) values.push_back(value(r));
  return ratio(values);
}

double owned(const RankCounters& r) { return r.owned_cells; }
double fluid(const RankCounters& r) { return r.fluid_cells; }
double solids(const RankCounters& r) { return r.solids_cells; }
double assembly(const RankCounters& r) { return r.seconds.assembly; }
double solves(const RankCounters& r) { return r.seconds.solves; }
double waits(const RankCounters& r) { return r.seconds.waits; }
double busy(const RankCounters& r) { return std::accumulate(r.busy_segments.begin(), r.busy_segments.end(), 0.0); }

}  // namespace

double work_imbalance(const std::vector<RankCounters>& ranks) {
  double largest = 0.0, total = 0.0;
  for (const auto& r : ranks) {
    const double work = gas_cell_work * (r.fluid_cells - r.solids_cells) + solids_cell_work * r.solids_cells;
    largest = std::max(largest, work);
    total += work;
  }
  return total > 0.0 ? largest / (total / static_cast<double>(ranks.size())) - 1.0 : 0.0;
}

double RankCounters::wait_share() const {
  const double busy = seconds.assembly + seconds.solves;
  return busy > 0.0 ? seconds.waits / busy : 0.0;
}

std::vector<std::vector<double>> counted_work(const std::vector<RankCounters>& ranks) {
  std::size_t segments = 0;
  for (const auto& r : ranks) segments = std::max(segments, r.busy_segments.size());
  std::vector<std::vector<double>> work(ranks.size(), std::vector<double>(segments, 0.0));
  for (std::size_t k = 0; k < segments; ++k) {
    double seconds = 0.0, units = 0.0;
    for (const auto& r : ranks) {
      seconds += at(r.busy_segments, k);
      units += at(r.work_units, k);
    }
    for (std::size_t r = 0; r < ranks.size(); ++r)
      work[r][k] = units > 0.0 ? at(ranks[r].work_units, k) * seconds / units : at(ranks[r].busy_segments, k);
  }
  return work;
}

std::vector<double> imbalance_wait_shares(const std::vector<RankCounters>& ranks) {
  const auto work = counted_work(ranks);
  const std::size_t segments = work.empty() ? 0 : work.front().size();
  double largest_total = 0.0;
  std::vector<double> waits(ranks.size(), 0.0);
  for (std::size_t k = 0; k < segments; ++k) {
    double largest = 0.0;
    for (const auto& w : work) largest = std::max(largest, w[k]);
    largest_total += largest;
    for (std::size_t r = 0; r < ranks.size(); ++r) waits[r] += largest - work[r][k];
  }
  for (auto& w : waits) w = largest_total > 0.0 ? w / largest_total : 0.0;
  return waits;
}

RankCounters count_rank(const parallel::Layout& layout, const FlowState& state,
                        double solids_threshold, const RankSeconds& seconds,
                        std::vector<double> busy_segments, std::vector<double> work_units) {
  RankCounters c;
  c.owned_cells = layout.owned_count();
  c.fluid_cells = layout.owned_fluid_count();
  for (int l = 0; l < layout.owned_fluid_count(); ++l)
    if (state.solids_fraction[static_cast<std::size_t>(l)] > solids_threshold) c.solids_cells += 1.0;
  c.seconds = seconds;
  c.busy_segments = std::move(busy_segments);
  c.work_units = std::move(work_units);
  return c;
}

std::vector<RankCounters> gather_rank_counters(const parallel::Communicator& comm,
                                               const RankCounters& mine) {
  unsigned long segments = std::max(mine.busy_segments.size(), mine.work_units.size());
  MPI_Allreduce(MPI_IN_PLACE, &segments, 1, MPI_UNSIGNED_LONG, MPI_MAX, comm.get());
  const auto packed = pack(mine, segments);
  const int count = static_cast<int>(packed.size());
  std::vector<double> all(static_cast<std::size_t>(comm.size()) * packed.size());
  MPI_Allgather(packed.data(), count, MPI_DOUBLE, all.data(), count, MPI_DOUBLE, comm.get());
  std::vector<RankCounters> ranks;
  for (int r = 0; r < comm.size(); ++r)
    ranks.push_back(unpack(all.data() + static_cast<std::size_t>(r) * packed.size(), segments));
  return ranks;
}

std::string rank_balance_table(const std::vector<RankCounters>& ranks) {
  const auto imbalance = imbalance_wait_shares(ranks);
  const auto work = counted_work(ranks);
  std::vector<double> work_totals;
  for (const auto& w : work) work_totals.push_back(std::accumulate(w.begin(), w.end(), 0.0));
  std::string text = fmt::format("{:>8} {:>10} {:>10} {:>10} {:>12} {:>10} {:>10} {:>6} {:>8} {:>8} {:>11}\n",
                                 "rank", "cells", "fluid", "solids", "assembly/s", "solves/s",
                                 "wait/s", "wait%", "busy/s", "work/s", "imbalance%");
  for (std::size_t r = 0; r < ranks.size(); ++r) {
    const auto& c = ranks[r];
    text += fmt::format("{:>8} {:>10.0f} {:>10.0f} {:>10.0f} {:>12.2f} {:>10.2f} {:>10.2f} {:>6.1f} {:>8.2f} {:>8.2f} {:>11.1f}\n",
                        r, c.owned_cells, c.fluid_cells, c.solids_cells, c.seconds.assembly,
                        c.seconds.solves, c.seconds.waits, 100.0 * c.wait_share(), busy(c),
                        work_totals[r], 100.0 * imbalance[r]);
  }
  text += fmt::format("{:>8} {:>10} {:>10} {:>10} {:>12} {:>10} {:>10} {:>6} {:>8} {:>8}\n", "max/min",
                      ratio(ranks, owned), ratio(ranks, fluid), ratio(ranks, solids),
                      ratio(ranks, assembly), ratio(ranks, solves), ratio(ranks, waits), "",
                      ratio(ranks, busy), ratio(work_totals));
  text.pop_back();  // the caller ends the line
  return text;
}

std::string busy_segment_table(const std::vector<RankCounters>& ranks,
                               const std::vector<std::string>& names) {
  const auto work = counted_work(ranks);
  struct Row {
    std::size_t key;
    double lead;  // the largest counted work less the smallest
  };
  std::vector<Row> rows;
  for (std::size_t k = 0; k < names.size(); ++k) {
    double low = INFINITY, high = 0.0, busiest = 0.0;
    for (std::size_t r = 0; r < ranks.size(); ++r) {
      const double w = k < work[r].size() ? work[r][k] : 0.0;
      low = std::min(low, w);
      high = std::max(high, w);
      busiest = std::max(busiest, at(ranks[r].busy_segments, k));
    }
    if (busiest > 0.0) rows.push_back({k, high - low});
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.lead > b.lead; });
  std::string text = fmt::format("{:>26}", "segment");
  for (std::size_t r = 0; r < ranks.size(); ++r)
    text += fmt::format(" {:>12} {:>12}", fmt::format("{} busy/s", r), fmt::format("{} work/s", r));
  text += fmt::format(" {:>10}\n", "lead/s");
  for (const auto& row : rows) {
    text += fmt::format("{:>26}", names[row.key]);
    for (std::size_t r = 0; r < ranks.size(); ++r)
      text += fmt::format(" {:>12.2f} {:>12.2f}", at(ranks[r].busy_segments, row.key), work[r][row.key]);
    text += fmt::format(" {:>10.2f}\n", row.lead);
  }
  text.pop_back();
  return text;
}

std::string rank_balance_line(const std::vector<RankCounters>& ranks) {
  double least = 1.0, most = 0.0;
  for (const auto& r : ranks) {
    least = std::min(least, r.wait_share());
    most = std::max(most, r.wait_share());
  }
  const auto imbalance = imbalance_wait_shares(ranks);
  double fewest = 0.0, most_imbalance = 0.0;
  if (!imbalance.empty()) {
    fewest = *std::min_element(imbalance.begin(), imbalance.end());
    most_imbalance = *std::max_element(imbalance.begin(), imbalance.end());
  }
  return fmt::format("ranks: fluid cells max/min {}, solids cells {}, assembly {}, solves {}; "
                     "wait {:.1f}–{:.1f} %, from the imbalance {:.1f}–{:.1f} %; work max {:.1f} % "
                     "above the mean",
                     ratio(ranks, fluid), ratio(ranks, solids), ratio(ranks, assembly),
                     ratio(ranks, solves), 100.0 * least, 100.0 * most, 100.0 * fewest,
                     100.0 * most_imbalance, 100.0 * work_imbalance(ranks));
}

}  // namespace bagnold::run
