#include "Evolution/StartingSurface.h"

#include "Distance/ContourTopology.h"
#include "Remeshing/CheckedEdits.h"
#include "Remeshing/Relaxation.h"
#include "Remeshing/Remesher.h"
#include "Surface/Components.h"
#include "Surface/Icosphere.h"
#include "Surface/SelfIntersections.h"
#include "Surface/SurfaceGeometry.h"

#include <algorithm>
#include <cmath>

namespace shrinkwrap
{

Status offsetSurface(
  const DistanceGrid& field, double offset, const Contour& contour, TriangleSoup& surface)
{
  surface = contourWithFewerJoins(field, offset, contour);
  SurfaceMesh closed;
  if (surface.triangles.empty() || !SurfaceMesh::build(surface.points, surface.triangles, closed))
  {
    return Status::failure(
      "the contour at Start Offset In Cells is empty or reaches the border of the "
      "distance field; lower it, or give a Distance Field with more room around the target "
      "(Offset Factor of Mesh Signed Distance)");
  }
  removeCavities(surface);
  if (surface.triangles.empty())
  {
    return Status::failure("nothing is left of the offset surface without its cavities");
  }
  return {};
}

namespace
{
// Specks smaller than two cells are noise the field cannot hold (curvature shrinks them away).
constexpr double kSpeckCells = 2;
// Offsets below the start's, down to half a cell, in steps of a quarter cell, are tried for fewer
// handles.
constexpr double kLowestOffsetCells = 0.5;
constexpr double kOffsetStepCells = 0.25;

// The handles a contour keeps once its specks are gone (a speck may be a tiny ring); the contour
// itself stays whole, so that the start's specks are counted where they are removed.
int handlesWithoutSpecks(TriangleSoup surface, double speck)
{
  removeSpecks(surface, speck);
  return handleCount(surface);
}

// `start`, the contour at `offset`, replaced by the contour at the highest lower offset with fewer
// handles, if one has. Where two parts lie a little more than twice the offset apart, the grid's
// contour may join them across the slot: a handle the closed field has not, which the Lagrangian
// wrap can never open again. A lower offset cannot close a hole a higher one keeps open, so fewer
// handles there are such joins undone. The Euler characteristics of the contours, counted without
// building them (ContourTopology.h), pick the offsets worth building. False when `progress` asked
// to stop.
bool fewestHandles(const DistanceGrid& field, double offset, const Contour& contour,
  TriangleSoup& start, const Progress& progress)
{
  const double h = field.lattice().spacing.maxCoeff();
  std::vector<double> offsets{ offset }; // the start's, then lower ones
  for (double d = offset - kOffsetStepCells * h; d >= (kLowestOffsetCells - 1e-9) * h;
       d -= kOffsetStepCells * h)
  {
    offsets.push_back(d);
  }
  if (offsets.size() < 2)
  {
    return true;
  }
  const std::vector<ContourEuler> counts = contourEulerCharacteristics(field, offsets);
  if (!progress.report(0.3))
  {
    return false;
  }
  const auto euler = [&](std::size_t i) { return std::max(counts[i].grid, counts[i].halfSpacing); };
  long long bestEuler = euler(0);
  int handles = -1;
  for (std::size_t i = 1; i < offsets.size(); ++i)
  {
    // A contour with fewer handles has a higher Euler characteristic (or more components as well).
    TriangleSoup candidate;
    if (!progress.report(0.3 + 0.7 * i / offsets.size()))
    {
      return false;
    }
    if (euler(i) <= bestEuler || !offsetSurface(field, offsets[i], contour, candidate))
    {
      continue;
    }
    if (handles < 0)
    {
      handles = handlesWithoutSpecks(start, kSpeckCells * h);
    }
    if (const int fewer = handlesWithoutSpecks(candidate, kSpeckCells * h); fewer < handles)
    {
      start = std::move(candidate);
      handles = fewer;
      bestEuler = euler(i);
    }
  }
  return true;
}
} // namespace

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

namespace
{
const char* const kAborted = "aborted";

// The offset start coarsened towards `last` in stages from two cells, the length doubling: a
// contour coarsened at once to several cells crosses itself where its walls lie a few cells apart,
// and each redo with guards costs three times the collapses. False when progress asked to stop.
bool coarsenStart(SurfaceMesh& mesh, double h, double last, const Progress& progress)
{
  // The evolution's thresholds. Collapses chain over a dozen passes here, so the ones behind a
  // crossing lie farther from it than a step's do.
  const RemeshSettings remeshing;
  const double first = 2 * h > 0 ? std::min(2 * h, last) : last;
  const int stages = 1 + static_cast<int>(std::ceil(std::log2(std::max(last / first, 1.0))));
  int stage = 0;
  const std::function<bool()> stop = [&] {
    return !progress.report(static_cast<double>(stage) / stages);
  };
  for (double length = first;; length = std::min(2 * length, last))
  {
    editCheckedOnce(
      mesh, 4 * length,
      [&](SurfaceMesh& m, bool guarded, const std::vector<Box>& only) {
        CollapseSettings collapses;
        collapses.avoidCrossings = guarded;
        collapses.orientDegenerate = true;
        collapses.guardOnlyIn = only;
        return collapseShortEdges(m, remeshing.collapseBelow * length,
                 remeshing.splitAbove * length, collapses, stop) > 0;
      },
      stop);
    if (!progress.report(static_cast<double>(++stage) / stages))
    {
      return false;
    }
    if (length >= last)
    {
      return true;
    }
  }
}

// A contour's slivers would fail the first step (the icosphere needs no relaxation). Where two
// parts of a contour nearly touch, relaxing can make them cross: then fewer iterations, down to
// none (a contour never crosses itself; a given surface is taken as it is). False when progress
// asked to stop.
bool relaxStart(
  SurfaceMesh& mesh, int relaxation, const FlipSettings& flips, const Progress& progress)
{
  const long long crossing = findSelfIntersections(mesh.points(), mesh.triangles()).pairs;
  if (!progress.report(0.2))
  {
    return false;
  }
  RelaxSettings relax;
  relax.flips = flips;
  relax.flips.avoidCrossings = false; // the relaxed surface as a whole is checked below
  relax.iterations = 1;               // one at a time, progress between them
  // Tries of `iterations`, halved while the relaxed surface crosses itself more: the try of n
  // iterations spans the progress from 1 - n / relaxation to 1 - n / (2 relaxation), after 0.2.
  for (int iterations = relaxation; iterations > 0; iterations /= 2)
  {
    SurfaceMesh relaxed = mesh;
    const double from = 1 - static_cast<double>(iterations) / relaxation, to = 1 - (1 - from) / 2;
    for (int k = 0; k < iterations; ++k)
    {
      relaxTangentially(relaxed, relax);
      if (!progress.report(0.2 + 0.8 * (from + (to - from) * 0.8 * (k + 1) / iterations)))
      {
        return false;
      }
    }
    if (findSelfIntersections(relaxed.points(), relaxed.triangles()).pairs <= crossing)
    {
      mesh = std::move(relaxed);
      break;
    }
    if (!progress.report(0.2 + 0.8 * to))
    {
      return false;
    }
  }
  return progress.report(1);
}

// The start's triangles before they are a mesh: the given surface, the offset surface of the
// field, or the icosphere around the box.
Status startSoup(const DistanceGrid& field, const Box& targetBox, const TriangleSoup* given,
  const StartSettings& settings, const Contour& contour, TriangleSoup& start,
  const Progress& progress)
{
  const double h = field.lattice().spacing.maxCoeff();
  if (given)
  {
    start = *given;
  }
  else if (settings.shape == StartShape::OffsetSurface)
  {
    const double offset = std::max(
      std::min(settings.offset * h, settings.maxOffset), std::min(settings.offset, 1.0) * h);
    if (Status status = offsetSurface(field, offset, contour, start); !status)
    {
      return Status::failure("cannot start from the offset surface: " + status.message());
    }
    if (!progress.report(0.3) ||
      !fewestHandles(field, offset, contour, start, progress.stage(0.3, 1)))
    {
      return Status::failure(kAborted);
    }
  }
  else
  {
    start = icosphere(settings.subdivision, targetBox.center(), 0.5 * 1.05 * targetBox.diagonal());
  }
  return {};
}
} // namespace

Status startingSurface(const DistanceGrid& field, const Box& targetBox, const TriangleSoup* given,
  const StartSettings& settings, const FlipSettings& flips, const Contour& contour,
  SurfaceMesh& mesh, int& specks, const Progress& progress)
{
  const double h = field.lattice().spacing.maxCoeff();
  TriangleSoup start;
  if (Status made =
        startSoup(field, targetBox, given, settings, contour, start, progress.stage(0, 0.1));
      !made)
  {
    return made;
  }
  if (!progress.report(0.1))
  {
    return Status::failure(kAborted);
  }
  specks = removeSpecks(start, kSpeckCells * h);
  Status status = SurfaceMesh::build(start.points, start.triangles, mesh);
  if (status)
  {
    status = orientOutwards(mesh);
  }
  if (!status)
  {
    return Status::failure("the starting surface cannot evolve: " + status.message());
  }
  if (!progress.report(0.2))
  {
    return Status::failure(kAborted);
  }
  const bool coarsens = !given && settings.shape == StartShape::OffsetSurface && settings.coarsenTo;
  if (coarsens && !coarsenStart(mesh, h, *settings.coarsenTo, progress.stage(0.2, 0.7)))
  {
    return Status::failure(kAborted);
  }
  const bool relaxes = settings.shape != StartShape::Icosphere || given;
  if (relaxes && !relaxStart(mesh, settings.relaxation, flips, progress.stage(0.7, 1)))
  {
    return Status::failure(kAborted);
  }
  return {};
}

} // namespace shrinkwrap
