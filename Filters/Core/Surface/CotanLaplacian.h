// The cotangent Laplacian of a surface as a sparse matrix on its one-rings (paper Section 2.2): row
// i holds i and its neighbours, in column order, with the cotangent weights w_ij of
// SurfaceGeometry. The pattern is built once per connectivity; assemble() sets the values, row by
// row, as
//   a_ii = shift_i + scale_i sum_j w_ij,   a_ij = -scale_i w_ij,
// which gives both the evolver's system (eq. (5): shift 1 or |V_i|/eps_i, scale tau times the row's
// factor) and the plain Laplacian of the volume redistribution (shift 0, scale 1).
#ifndef ShrinkWrap_CotanLaplacian_h
#define ShrinkWrap_CotanLaplacian_h

#include "Surface/SurfaceMesh.h"

#include <Eigen/SparseCore>

#include <utility>
#include <vector>

namespace shrinkwrap
{

class CotanLaplacian
{
public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

  explicit CotanLaplacian(const SurfaceMesh& mesh);

  // row(i) returns {shift_i, scale_i}; weight is indexed like the one-rings.
  template <typename Row>
  void assemble(const SurfaceMesh& mesh, const std::vector<double>& weight, Row&& row)
  {
    double* values = this->M.valuePtr();
    for (int i = 0; i < mesh.vertexCount(); ++i)
    {
      const std::pair<double, double> shiftAndScale = row(i);
      const double scale = shiftAndScale.second;
      double sum = 0;
      for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
      {
        values[this->OffDiagonal[p]] = -(scale * weight[p]);
        sum += weight[p];
      }
      values[this->Diagonal[i]] = shiftAndScale.first + scale * sum;
    }
  }

  // Fixes the value at vertex v (a Dirichlet condition that makes a pure Laplacian definite): row
  // and column v become those of the identity.
  void pin(const SurfaceMesh& mesh, int v);

  const Matrix& matrix() const { return this->M; }

private:
  Matrix M;
  std::vector<int> Diagonal;    // value index of (i, i)
  std::vector<int> OffDiagonal; // value index of (i, ring(p)), per one-ring entry p
};

} // namespace shrinkwrap

#endif
