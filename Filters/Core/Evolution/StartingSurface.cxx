#include "StartingSurface.h"

#include "CheckedEdits.h"
#include "Components.h"
#include "Icosphere.h"
#include "Relaxation.h"
#include "Remesher.h"
#include "SelfIntersections.h"
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
    const double offset = std::max(std::min(settings.offset * h, settings.maxOffset), std::min(settings.offset, 1.0) * h);
    if (Status status = offsetSurface(field, offset, contour, start); !status)
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
  if (!given && settings.shape == StartShape::OffsetSurface && settings.coarsenTo > 0)
  {
    // The evolution's thresholds. Collapses chain over a dozen passes here, so the ones behind a
    // crossing lie farther from it than a step's do.
    const RemeshSettings remeshing;
    editCheckedOnce(mesh, 4 * settings.coarsenTo, [&](SurfaceMesh& m, bool guarded, const std::vector<Box>& only) {
      CollapseSettings collapses;
      collapses.avoidCrossings = guarded;
      collapses.orientDegenerate = true;
      collapses.guardOnlyIn = only;
      return collapseShortEdges(m, remeshing.collapseBelow * settings.coarsenTo,
               remeshing.splitAbove * settings.coarsenTo, collapses) > 0;
    });
  }
  // A contour's slivers would fail the first step (the icosphere needs no relaxation). Where two parts
  // of a contour nearly touch, relaxing can make them cross: then fewer iterations, down to none (a
  // contour never crosses itself; a given surface is taken as it is).
  if (settings.shape != StartShape::Icosphere || given)
  {
    const long long crossing = findSelfIntersections(mesh.points(), mesh.triangles()).pairs;
    RelaxSettings relax;
    relax.flips = flips;
    relax.flips.avoidCrossings = false; // the relaxed surface as a whole is checked below
    for (int iterations = settings.relaxation; iterations > 0; iterations /= 2)
    {
      SurfaceMesh relaxed = mesh;
      relax.iterations = iterations;
      relaxTangentially(relaxed, relax);
      if (findSelfIntersections(relaxed.points(), relaxed.triangles()).pairs <= crossing)
      {
        mesh = std::move(relaxed);
        break;
      }
    }
  }
  return {};
}

} // namespace shrinkwrap
