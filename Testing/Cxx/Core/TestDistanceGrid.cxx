// Trilinear sampling of a distance grid: value and gradient exact for a linear field.
#include "Distance/DistanceGrid.h"
#include "TestUtilities.h"

#include <vtkSMPTools.h>

#include <random>

namespace
{
using namespace shrinkwrap;
using testing::meshOf;

void distanceSampling()
{
  // A linear function is reproduced exactly by trilinear interpolation, and so is its gradient.
  GridLattice lattice;
  lattice.origin = Vec3(-1, -2, 0.5);
  lattice.spacing = Vec3(0.1, 0.2, 0.15);
  lattice.dims = { 21, 17, 13 };
  const Vec3 a(0.3, -1.2, 2.0);
  std::vector<float> values(lattice.nodeCount());
  for (int k = 0; k < lattice.dims[2]; ++k)
    for (int j = 0; j < lattice.dims[1]; ++j)
      for (int i = 0; i < lattice.dims[0]; ++i)
        values[lattice.index(i, j, k)] = static_cast<float>(a.dot(lattice.position(i, j, k)) + 0.7);
  const DistanceGrid grid(lattice, values);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0, worstGradient = 0;
  const Box box = lattice.bounds();
  for (int n = 0; n < 1000; ++n)
  {
    const Vec3 x = box.min + Vec3(u(random), u(random), u(random)).cwiseProduct(box.size());
    const DistanceSample s = grid.sample(x);
    worst = std::max(worst, std::abs(s.value - (a.dot(x) + 0.7)));
    worstGradient = std::max(worstGradient, (s.gradient - a).norm());
  }
  SW_CHECK(worst < 1e-5 && worstGradient < 1e-4,
    "trilinear value and gradient exact for a linear field (" << worst << ", " << worstGradient
                                                              << ")");
}

} // namespace

int TestDistanceGrid(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] { distanceSampling(); });
  return testing::finish("TestDistanceGrid");
}
