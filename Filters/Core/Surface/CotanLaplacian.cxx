#include "Surface/CotanLaplacian.h"

#include <algorithm>

namespace shrinkwrap
{

CotanLaplacian::CotanLaplacian(const SurfaceMesh& mesh)
{
  const int nv = mesh.vertexCount();
  this->M.resize(nv, nv);
  this->M.resizeNonZeros(mesh.ringEnd(nv - 1) + nv);
  int* outer = this->M.outerIndexPtr();
  int* inner = this->M.innerIndexPtr();
  std::fill(this->M.valuePtr(), this->M.valuePtr() + this->M.nonZeros(), 0.0);
  this->Diagonal.resize(nv);
  this->OffDiagonal.resize(mesh.ringEnd(nv - 1));
  std::vector<std::pair<int, int>> row; // (column, ring entry or -1 for the diagonal)
  outer[0] = 0;
  for (int i = 0; i < nv; ++i)
  {
    row.assign(1, { i, -1 });
    for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
    {
      row.emplace_back(mesh.ring(p), p);
    }
    std::sort(row.begin(), row.end());
    for (std::size_t k = 0; k < row.size(); ++k)
    {
      const int at = outer[i] + static_cast<int>(k);
      inner[at] = row[k].first;
      (row[k].second < 0 ? this->Diagonal[i] : this->OffDiagonal[row[k].second]) = at;
    }
    outer[i + 1] = outer[i] + static_cast<int>(row.size());
  }
}

void CotanLaplacian::pin(const SurfaceMesh& mesh, int v)
{
  double* values = this->M.valuePtr();
  for (int p = mesh.ringBegin(v); p < mesh.ringEnd(v); ++p)
  {
    values[this->OffDiagonal[p]] = 0;                               // row v
    values[this->OffDiagonal[mesh.ringEntry(mesh.ring(p), v)]] = 0; // column v
  }
  values[this->Diagonal[v]] = 1;
}

} // namespace shrinkwrap
