#pragma once
// The nonzero pattern of one rank's rows of a sparse matrix: the columns of each owned row
// (global indices, each once), rows in order. Built once from the discretization's stencils
// (Discretization::momentum_pattern, cell_pattern) and given to a LinearSystem, which then
// accepts no entry outside it.

#include <algorithm>
#include <cstdint>
#include <vector>

namespace bagnold::solver {

struct SparsityPattern {
  std::vector<std::int64_t> offsets{0};  // row r's columns are columns[offsets[r], offsets[r + 1])
  std::vector<std::int64_t> columns;

  // Appends a row; a column given twice is kept once.
  void add_row(const std::int64_t* row_columns, int count) {
    const auto begin = static_cast<std::ptrdiff_t>(columns.size());
    for (int i = 0; i < count; ++i)
      if (std::find(columns.begin() + begin, columns.end(), row_columns[i]) == columns.end())
        columns.push_back(row_columns[i]);
    offsets.push_back(static_cast<std::int64_t>(columns.size()));
  }
  std::int64_t rows() const { return static_cast<std::int64_t>(offsets.size()) - 1; }
};

}  // namespace bagnold::solver
