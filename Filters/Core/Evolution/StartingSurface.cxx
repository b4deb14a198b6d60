#include "StartingSurface.h"

#include "Components.h"
#include "Icosphere.h"
#include "Relaxation.h"
#include "SurfaceGeometry.h"

#include <algorithm>

namespace shrinkwrap
{

Status offsetSurface(const DistanceGrid& field, double offset, const Contour& contour, TriangleSurface& surface)
{
  surface = contour(field, offset);
  SurfaceMesh closed;
  if (surface.triangles.empty() || !SurfaceMesh::build(surface.points, surface.triangles, closed))
  {
    return Status::failure("the contour at Start Offset is empty or reaches the border of the distance "
                           "field; lower it, or enlarge the field");
  }
  removeCavities(surface);
  if (surface.triangles.empty())
  {
    return Status::failure("nothing is left of the offset surface without its cavities");
  }
  return {};
}

Status orientOutwards(SurfaceMesh& mesh)
{
  if (enclosedVolume(mesh, mesh.points()) >= 0)
  {
    return {};
  }
  std::vector<std::array<int, 3>> flipped = mesh.triangles();
  for (auto& t : flipped)
  {
    std::swap(t[1], t[2]);
  }
  const std::vector<Vec3> points = mesh.points();
  return SurfaceMesh::build(points, flipped, mesh);
}

Status startingSurface(const DistanceGrid& field, const Box& targetBox, const TriangleSurface* given,
  const StartSettings& settings, const FlipSettings& flips, const Contour& contour, SurfaceMesh& mesh,
  int& specks)
{
  const double h = field.lattice().spacing.maxCoeff();
  TriangleSurface start;
  if (given)
  {
    start = *given;
  }
  else if (settings.shape == StartShape::OffsetSurface)
  {
    if (Status status = offsetSurface(field, settings.offset * h, contour, start); !status)
    {
      return Status::failure("cannot start from the offset surface: " + status.message());
    }
  }
  else
  {
    start = icosphere(settings.subdivision, targetBox.center(), 0.5 * 1.05 * targetBox.diagonal());
  }
  // Specks smaller than two cells are noise the field cannot hold (curvature shrinks them away).
  specks = removeSpecks(start, 2 * h);
  Status status = SurfaceMesh::build(start.points, start.triangles, mesh);
  if (status)
  {
    status = orientOutwards(mesh);
  }
  if (!status)
  {
    return Status::failure("the starting surface cannot evolve: " + status.message());
  }
  // A contour's slivers would fail the first step (the icosphere needs no relaxation).
  if (settings.shape != StartShape::Icosphere || given)
  {
    RelaxSettings relax;
    relax.iterations = settings.relaxation;
    relax.flips = flips;
    relaxTangentially(mesh, relax);
  }
  return {};
}

} // namespace shrinkwrap
