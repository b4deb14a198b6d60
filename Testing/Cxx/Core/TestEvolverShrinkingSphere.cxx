// The shrinking sphere of Section 4.2: pure mean curvature flow (eps = 1, C = 0) of the unit
// icosphere, whose exact radius is r(t) = sqrt(1 - 4t) (eq. (6), n = 3), up to t_s = 0.06, on
// levels s = 1..4 with tau = 0.01 / 4^(s-1). Error norm as the paper's tables were computed:
//   err = sqrt(tau sum_k sum_i (|F_i^k| - r(t_k))^2 |V_i|),
// with |V_i| the co-volumes that step k computed (from F^(k-1), Algorithm 3 line 4): with them
// Table 2 comes out to four digits; with the co-volumes of F^k level 1 is 2.3% lower. Eq. (11) as
// printed squares the inner sum; that variant is printed too, and does not give the tables'
// figures.
#include "Evolution/Evolver.h"
#include "Surface/Icosphere.h"
#include "TestUtilities.h"

#include <vtkSMPTools.h>

#include <cmath>

namespace
{
using namespace shrinkwrap;

struct Errors
{
  double tables = 0;  // the norm the tables were computed with
  double printed = 0; // eq. (11) as printed
  bool ok = true;
};

Errors shrinkingSphere(int level, const EvolverSettings& base)
{
  const TriangleSoup sphere = icosphere(level);
  SurfaceMesh mesh;
  std::string error;
  testing::builds(sphere.points, sphere.triangles, mesh, error);
  EvolverSettings settings = base;
  settings.timeStep = 0.01 / std::pow(4.0, level - 1);
  settings.C1 = 1.0;
  settings.C2 = 0.0; // eps = C1 = 1
  settings.C = 0.0;  // eta = 0
  settings.solverTolerance = 1e-12;
  Evolver evolver(mesh, settings);
  const int steps = static_cast<int>(std::lround(0.06 / settings.timeStep));
  Errors e;
  double tables = 0, printed = 0;
  for (int k = 1; k <= steps; ++k)
  {
    const SurfaceGeometry before = evolver.geometry();
    const StepReport report = evolver.step();
    if (!report.ok())
    {
      std::cerr << report.message << std::endl;
      e.ok = false;
      return e;
    }
    const double r = std::sqrt(1.0 - 4.0 * k * settings.timeStep);
    const std::vector<Vec3> x = evolver.positions();
    double sum = 0;
    for (int i = 0; i < mesh.vertexCount(); ++i)
    {
      const double diff = x[i].norm() - r;
      sum += diff * diff * before.coVolume[i];
    }
    tables += settings.timeStep * sum;
    printed += settings.timeStep * sum * sum;
  }
  e.tables = std::sqrt(tables);
  e.printed = std::sqrt(printed);
  return e;
}

// Runs levels 1..4 and checks err within `tolerance` (relative) of `expected`, EOC as given.
void table(const std::string& name, const EvolverSettings& settings, const double expected[4],
  const double expectedEoc[3], double tolerance, double eocTolerance, bool eocAtLeast)
{
  std::printf(
    "%s\n  N_V    tau          err (tables)  paper        EOC     paper   | eq. (11) as printed\n",
    name.c_str());
  double previous = 0;
  for (int level = 1; level <= 4; ++level)
  {
    const Errors e = shrinkingSphere(level, settings);
    SW_CHECK(e.ok, name << ": the evolution runs to t = 0.06 on level " << level);
    const double eoc = level > 1 ? std::log2(previous / e.tables) : 0;
    std::printf("  %-6lld %-12.4e %-13.4e %-12.4e %-7.4f %-7.4f | %.4e\n",
      icosphereVertexCount(level), 0.01 / std::pow(4.0, level - 1), e.tables, expected[level - 1],
      eoc, level > 1 ? expectedEoc[level - 2] : 0.0, e.printed);
    SW_CHECK(std::abs(e.tables - expected[level - 1]) <= tolerance * expected[level - 1],
      name << ": err within " << 100 * tolerance << "% of the table on level " << level);
    if (level > 1)
    {
      const double target = expectedEoc[level - 2];
      SW_CHECK(eocAtLeast ? eoc >= target : std::abs(eoc - target) <= eocTolerance,
        name << ": EOC on level " << level << " (" << eoc << " vs " << target << ")");
    }
    previous = e.tables;
  }
}
} // namespace

int TestEvolverShrinkingSphere(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] {
    // Table 2: no tangential redistribution.
    EvolverSettings none = EvolverSettings::paper();
    const double table2[4] = { 3.067e-3, 8.676e-4, 2.106e-4, 5.112e-5 };
    const double eoc2[3] = { 1.8217, 2.0423, 2.0426 };
    table("Table 2 (no redistribution)", none, table2, eoc2, 0.01, 0.01, false);

    // Table 3: volume-based redistribution, omega_vol = 1, v_T = grad psi averaged over V_i.
    EvolverSettings volume = EvolverSettings::paper();
    volume.redistribution = Redistribution::Volume;
    volume.omegaVolume = 1.0;
    // Level 1 cannot reproduce the paper's 2.845e-3: every vertex of the level-1 icosphere is the
    // centre of a rotation of the mesh onto itself (5-fold at the 12 icosahedron vertices, 2-fold
    // at the 30 edge midpoints), and a tangent vector that such a rotation leaves unchanged is
    // zero. So v_T = 0 there for any scheme that respects the symmetry, and err equals Table 2's;
    // the paper's code must break the symmetry. Checked directly, then levels 2-4 are held to the
    // table.
    {
      const TriangleSoup sphere = icosphere(1);
      SurfaceMesh mesh;
      std::string error;
      testing::builds(sphere.points, sphere.triangles, mesh, error);
      EvolverSettings pure = volume;
      pure.C2 = 0;
      pure.C = 0;
      pure.timeStep = 0.01;
      Evolver evolver(mesh, pure);
      evolver.step();
      double largest = 0;
      for (const Vec3& v : evolver.tangentialVelocity())
      {
        largest = std::max(largest, v.norm());
      }
      std::printf("Table 3, level 1: max |v_T| = %.2e (zero by symmetry)\n", largest);
      SW_CHECK(largest < 1e-10, "v_T vanishes on the symmetric level-1 icosphere");
    }
    const double table3[4] = { 3.067e-3 /* Table 2's; the paper prints 2.845e-3 */, 8.598e-4,
      2.105e-4, 5.073e-5 };
    const double eoc3[3] = { 1.7, 2.0, 2.0 };
    table("Table 3 (volume-based, omega_vol = 1)", volume, table3, eoc3, 0.05, 0, true);
    // The paper's code left out the division by |V_i|; shown for comparison, not held to the table.
    volume.volumePerArea = false;
    std::printf("  (without the 1/|V_i| factor, as the paper's code:)\n");
    for (int level = 1; level <= 4; ++level)
    {
      std::printf("  N_V %-6lld err %.4e\n", icosphereVertexCount(level),
        shrinkingSphere(level, volume).tables);
    }

    // Table 4: angle-based redistribution, omega_angle = 1, really switched on (the paper's code
    // had it off in this test, so its Table 4 equals Table 2 to three digits).
    EvolverSettings angle = EvolverSettings::paper();
    angle.redistribution = Redistribution::Angle;
    angle.omegaAngle = 1.0;
    const double table4[4] = { 3.067e-3, 8.678e-4, 2.111e-4, 5.113e-5 };
    const double eoc4[3] = { 1.8, 1.8, 1.8 };
    table("Table 4 (angle-based, omega_angle = 1)", angle, table4, eoc4, 0.10, 0, true);
  });
  return testing::finish("TestEvolverShrinkingSphere");
}
