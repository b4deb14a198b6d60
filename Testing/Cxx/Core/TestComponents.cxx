// Connected components of a starting surface: specks smaller than the size asked are removed, and
// only those; the walls of cavities (facing the other way from the largest piece) too.
#include "Surface/Components.h"
#include "Surface/Icosphere.h"
#include "TestUtilities.h"

namespace
{
using namespace shrinkwrap;

void removesSpecks()
{
  TriangleSoup s = icosphere(2, Vec3(0, 0, 0), 1.0);
  const auto append = [&s](const TriangleSoup& more) {
    const int offset = static_cast<int>(s.points.size());
    s.points.insert(s.points.end(), more.points.begin(), more.points.end());
    for (auto t : more.triangles)
    {
      s.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
    }
  };
  append(icosphere(1, Vec3(3, 0, 0), 0.04));  // a speck: 0.08 across
  append(icosphere(1, Vec3(-3, 0, 0), 0.06)); // 0.12 across: kept
  const int removed = removeSpecks(s, 0.1);
  SW_CHECK(removed == 1, "one speck removed (" << removed << ")");
  SW_CHECK(
    s.points.size() == 162 + 42 && s.triangles.size() == 320 + 80, "the other two pieces kept");
  SurfaceMesh mesh;
  std::string error;
  SW_CHECK(testing::builds(s.points, s.triangles, mesh, error), "still closed: " << error);
  SW_CHECK(removeSpecks(s, 0.1) == 0, "nothing more to remove");

  // A cavity: a smaller sphere inside, facing inwards. A second object beside it faces outwards.
  TriangleSoup cavity = icosphere(1, Vec3(0, 0, 0), 0.5);
  for (auto& t : cavity.triangles)
  {
    std::swap(t[1], t[2]);
  }
  append(cavity);
  SW_CHECK(removeCavities(s) == 1 && s.points.size() == 162 + 42 && s.triangles.size() == 400,
    "the cavity's wall is removed, the two outer pieces kept");
}
} // namespace

int TestComponents(int, char*[])
{
  removesSpecks();
  return testing::finish("TestComponents");
}
