#include "Distance/GridRegions.h"

#include <algorithm>
#include <array>
#include <numeric>

namespace shrinkwrap
{

namespace
{
// The runs of free nodes of each row (j + k ny) along x, and the regions they form: two runs of
// neighbouring rows (in y or z) that share an x are face neighbours (union-find over runs).
class FreeRuns
{
public:
  FreeRuns(const GridLattice& lattice, const NodeFlags& blocked)
    : Dims(lattice.dims)
  {
    const int rows = this->Dims[1] * this->Dims[2];
    this->RowStart.reserve(rows + 1);
    for (int row = 0; row < rows; ++row)
    {
      this->RowStart.push_back(static_cast<int>(this->Runs.size()));
      const std::int64_t first = static_cast<std::int64_t>(row) * this->Dims[0];
      for (int i = 0; i < this->Dims[0]; ++i)
      {
        if (blocked[first + i])
          continue;
        const int begin = i;
        while (i + 1 < this->Dims[0] && !blocked[first + i + 1])
          ++i;
        this->Runs.push_back({ begin, i });
      }
    }
    this->RowStart.push_back(static_cast<int>(this->Runs.size()));
    this->Parent.resize(this->Runs.size());
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
    for (int k = 0; k < this->Dims[2]; ++k)
      for (int j = 0; j < this->Dims[1]; ++j)
      {
        const int row = j + k * this->Dims[1];
        if (j > 0)
          this->joinRows(row, row - 1);
        if (k > 0)
          this->joinRows(row, row - this->Dims[1]);
      }
  }

  NodeFlags reachingBorder()
  {
    std::vector<char> regionReached(this->Runs.size(), 0);
    for (int k = 0; k < this->Dims[2]; ++k)
      for (int j = 0; j < this->Dims[1]; ++j)
      {
        const int row = j + k * this->Dims[1];
        const bool borderRow = j == 0 || k == 0 || j == this->Dims[1] - 1 || k == this->Dims[2] - 1;
        for (int r = this->RowStart[row]; r < this->RowStart[row + 1]; ++r)
        {
          if (borderRow || this->Runs[r].first == 0 || this->Runs[r].last == this->Dims[0] - 1)
            regionReached[this->root(r)] = 1;
        }
      }
    NodeFlags nodes(static_cast<std::size_t>(this->Dims[0]) * this->Dims[1] * this->Dims[2], 0);
    for (int row = 0; row + 1 < static_cast<int>(this->RowStart.size()); ++row)
    {
      const auto first = nodes.begin() + static_cast<std::int64_t>(row) * this->Dims[0];
      for (int r = this->RowStart[row]; r < this->RowStart[row + 1]; ++r)
      {
        if (regionReached[this->root(r)])
          std::fill(first + this->Runs[r].first, first + this->Runs[r].last + 1, 1);
      }
    }
    return nodes;
  }

private:
  struct Run
  {
    int first, last; // x of its first and last node
  };
  int root(int r)
  {
    while (this->Parent[r] != r)
      r = this->Parent[r] = this->Parent[this->Parent[r]];
    return r;
  }
  void join(int a, int b)
  {
    a = this->root(a);
    b = this->root(b);
    if (a != b)
      this->Parent[std::max(a, b)] = std::min(a, b);
  }
  // Joins the runs of two neighbouring rows that share an x (both lists ascending in x).
  void joinRows(int row, int other)
  {
    int a = this->RowStart[row], b = this->RowStart[other];
    const int aEnd = this->RowStart[row + 1], bEnd = this->RowStart[other + 1];
    while (a < aEnd && b < bEnd)
    {
      if (this->Runs[a].first <= this->Runs[b].last && this->Runs[b].first <= this->Runs[a].last)
        this->join(a, b);
      if (this->Runs[a].last < this->Runs[b].last)
        ++a;
      else
        ++b;
    }
  }

  std::array<int, 3> Dims;
  std::vector<Run> Runs;
  std::vector<int> RowStart; // per row its first run; one past the last at the end
  std::vector<int> Parent;
};
} // namespace

NodeFlags reachedFromBorder(const GridLattice& lattice, const NodeFlags& blocked)
{
  return FreeRuns(lattice, blocked).reachingBorder();
}

} // namespace shrinkwrap
