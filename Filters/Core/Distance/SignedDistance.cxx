#include "Distance/SignedDistance.h"

#include "Common/HugePages.h"
#include "Common/Memory.h"
#include "Common/Parallel.h"

#include "Distance/ClosestPointSweep.h"
#include "Distance/DistanceBand.h"
#include "Distance/DistanceSource.h"
#include "Distance/EikonalSweep.h"
#include "Distance/PointSource.h"
#include "Distance/SignVotes.h"
#include "Distance/UnionSource.h"
#include "Distance/WindingSign.h"

#include <chrono>
#include <cmath>
#include <sstream>

namespace shrinkwrap
{

namespace
{
double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Far field by closest-point passes; the distance of every node is that to its site (the band node
// whose closest point it is), which `site` keeps for the sign.
bool closestPointFarField(const GridLattice& lattice, const DistanceBand& band, float* distance,
  LargeVector<std::int32_t>& site, const Progress& progress)
{
  site.assign(lattice.nodeCount(), -1);
  for (std::size_t k = 0; k < band.nodes.size(); ++k)
  {
    site[band.nodes[k]] = static_cast<std::int32_t>(k);
  }
  return sweepClosestPoints(lattice, band.closest, site.data(), distance, progress);
}

// Far field by the paper's Eikonal sweeps from the band, whose nodes are the nonzero states so far.
bool eikonalFarField(const GridLattice& lattice, const DistanceBand& band,
  const std::uint8_t* state, int rounds, float* distance, const Progress& progress)
{
  for (std::size_t k = 0; k < band.nodes.size(); ++k)
  {
    distance[band.nodes[k]] = band.distance[k];
  }
  return sweepEikonal(lattice, state, distance, rounds, progress);
}

// The votes disagreed: the winding number decides where the closest point's side is in doubt. The
// Eikonal far field keeps no sites: closest-point passes find them (their distances are not kept).
// False if aborted.
bool signByWinding(const DistanceSource& source, const GridLattice& lattice,
  const DistanceBand& band, LargeVector<std::int32_t>& site, std::uint8_t* state,
  const Progress& progress, SignedDistanceResult& result)
{
  if (site.empty())
  {
    LargeVector<float> scratch(lattice.nodeCount());
    if (!closestPointFarField(lattice, band, scratch.data(), site, progress.stage(0, 0.3)))
    {
      return false;
    }
  }
  const WindingSignResult w = signByWindingNumber(source, lattice, band.closest,
    trustedNormals(source, band), site.data(), state, progress.stage(0.3, 1));
  if (!w.completed)
  {
    return false;
  }
  result.windingEvaluations = w.evaluated;
  result.unconfirmedTriangles = w.unconfirmed;
  result.invertedOrientation = false; // the winding number follows each piece's own orientation
  result.isSigned = w.inside > 0;
  result.signMethod = result.isSigned ? SignMethod::WindingNumber : SignMethod::None;
  return true;
}

} // namespace

std::string signStatus(const SignedDistanceResult& r, bool asked)
{
  std::ostringstream s;
  const auto turned = [&] {
    if (r.reorientedTriangles > 0)
    {
      s << "; " << r.reorientedTriangles
        << " triangles faced against their neighbours and were turned";
    }
  };
  if (r.points > 0 && r.triangles > 0)
  {
    s << "unsigned: distances to the nearest of " << r.triangles << " triangles and " << r.points
      << " input points (points have no inside)";
  }
  else if (r.points > 0)
  {
    s << "unsigned: distances to the nearest of " << r.points
      << " input points (points have no inside)";
  }
  else if (!asked)
  {
    s << "unsigned: Compute Sign is off";
  }
  else if (r.signMethod == SignMethod::Votes)
  {
    s << "signed: the surface is closed (the sign votes of every region agree)";
    if (r.invertedOrientation)
    {
      s << "; its triangles face inwards, so the signs follow the geometry (negative inside)";
    }
    turned();
  }
  else if (r.signMethod == SignMethod::WindingNumber)
  {
    s << "signed by the generalized winding number (inside where it exceeds 1/2), as the surface "
      << "is open or crosses itself: " << r.boundaryEdges << " rim edges, " << r.nonManifoldEdges
      << " non-manifold edges, " << r.unconfirmedTriangles
      << " triangles inside another part or crossing one; " << r.windingEvaluations
      << " nodes took their side from the winding number, the others from their closest point";
    turned();
  }
  else if (r.signMethod == SignMethod::VotesDisagreed)
  {
    s << "unsigned: the surface is open or crosses itself (" << r.boundaryEdges << " rim edges, "
      << r.nonManifoldEdges << " non-manifold edges), so the sign votes disagreed at "
      << r.signDisagreements << " grid edges, and no winding number was asked for";
  }
  else
  {
    s << "unsigned: the surface encloses nothing (its generalized winding number stays below 1/2: "
         "a sheet, a "
         "disc or a fin; "
      << r.boundaryEdges << " rim edges)";
  }
  return s.str();
}

std::optional<Note::Kind> signNoteKind(const SignedDistanceResult& r, bool asked)
{
  if (!asked || r.points > 0)
  {
    return std::nullopt;
  }
  if (!r.isSigned)
  {
    return Note::Warning;
  }
  if (r.signMethod == SignMethod::WindingNumber || r.invertedOrientation)
  {
    return Note::Info;
  }
  return std::nullopt;
}

int workingBytesPerNode(const SignedDistanceSettings& settings)
{
  // Node state always; the site index of the closest-point passes (the Eikonal sweep needs them,
  // and scratch distances, only for a winding-number sign).
  return 1 + (settings.sweep == SweepMethod::ClosestPoint ? 4 : (settings.windingNumber ? 8 : 0));
}

namespace
{
// Algorithm 1, line 1 (the tree, and the pseudonormals that sign the band), then the rest; the
// source is handed to `keep` when asked for.
SignedDistanceResult fromSoup(const TriangleSoup& input, const GridLattice& lattice,
  const SignedDistanceSettings& settings, float* distance, const Progress& progress,
  std::shared_ptr<const TriangleSource>* keep)
{
  const auto clock = std::chrono::steady_clock::now();
  auto source = std::make_shared<const TriangleSource>(input);
  const double treeSeconds = secondsSince(clock);
  SignedDistanceResult result;
  if (progress.report(0.05))
  {
    result = computeSignedDistance(*source, lattice, settings, distance, progress);
  }
  result.treeSeconds = treeSeconds;
  if (keep)
  {
    *keep = std::move(source);
  }
  return result;
}
} // namespace

SignedDistanceResult computeSignedDistance(const TriangleSoup& input, const GridLattice& lattice,
  const SignedDistanceSettings& settings, float* distance, const Progress& progress)
{
  return fromSoup(input, lattice, settings, distance, progress, nullptr);
}

SignedDistanceResult computeSignedDistance(const TriangleSource& source, const GridLattice& lattice,
  const SignedDistanceSettings& settings, float* distance, const Progress& progress)
{
  SignedDistanceResult result = computeSignedDistance(
    static_cast<const DistanceSource&>(source), lattice, settings, distance, progress);
  result.boundaryEdges = source.boundaryEdges();
  result.nonManifoldEdges = source.nonManifoldEdges();
  result.reorientedTriangles = source.reorientedTriangles();
  return result;
}

SignedDistanceResult computeSignedDistance(const DistanceSource& source, const GridLattice& lattice,
  const SignedDistanceSettings& settings, float* distance, const Progress& progress)
{
  SignedDistanceResult result;
  // Lines 2-5 (progress from 0.05 on: line 1 built the source): the octree outline and exact
  // distances on its nodes.
  auto clock = std::chrono::steady_clock::now();
  IndexList cells;
  if (!source.outline(lattice, progress.stage(0.05, 0.2), cells))
  {
    return result;
  }
  LargeVector<std::uint8_t> state(lattice.nodeCount(), Unvisited);
  result.outlineSeconds = secondsSince(clock);
  clock = std::chrono::steady_clock::now();
  DistanceBand band;
  const Box grid = lattice.bounds();
  const Box surface = source.bounds();
  const bool meshInsideGrid = strictlyInside(surface, grid);
  IndexList nodes =
    bandNodes(lattice, cells, settings.bandLayers, allFaces(!meshInsideGrid), state.data());
  if (!computeBand(source, lattice, std::move(nodes),
        bandSearchRadius(lattice, settings.bandLayers), onSurfaceDistance(lattice),
        progress.stage(0.2, 0.45), band, state.data()))
  {
    return result;
  }
  result.bandNodes = static_cast<long long>(band.nodes.size());
  result.bandSeconds = secondsSince(clock);

  // Lines 6-7: the far field.
  clock = std::chrono::steady_clock::now();
  const Progress sweepProgress = progress.stage(0.45, 0.8);
  LargeVector<std::int32_t> site;
  const bool swept = settings.sweep == SweepMethod::ClosestPoint
    ? closestPointFarField(lattice, band, distance, site, sweepProgress)
    : eikonalFarField(
        lattice, band, state.data(), settings.eikonalIterations, distance, sweepProgress);
  if (!swept)
  {
    return result;
  }
  result.sweepSeconds = secondsSince(clock);

  // Line 8: the sign.
  clock = std::chrono::steady_clock::now();
  if (settings.computeSign)
  {
    bool aborted;
    const SignVotes votes = signRegions(lattice, meshInsideGrid, nodeExtent(lattice, band.nodes),
      state.data(), progress.stage(0.8, 0.85), aborted);
    if (aborted)
    {
      return result;
    }
    result.signDisagreements = votes.disagreeing;
    result.invertedOrientation = votes.inverted;
    result.isSigned = votes.consistent();
    result.signMethod = result.isSigned ? SignMethod::Votes
      : settings.windingNumber          ? SignMethod::None
                                        : SignMethod::VotesDisagreed;
    if (!result.isSigned && settings.windingNumber && !source.sidesConfirmed().empty() &&
      !signByWinding(source, lattice, band, site, state.data(), progress.stage(0.85, 0.98), result))
    {
      return result;
    }
  }
  applySigns(state.data(), lattice.nodeCount(), result.isSigned, distance);
  result.signSeconds = secondsSince(clock);
  result.completed = progress.report(1);
  return result;
}

SignedDistanceResult computePointDistance(const std::vector<Vec3>& points,
  const GridLattice& lattice, const SignedDistanceSettings& settings, float* distance,
  const Progress& progress)
{
  const auto clock = std::chrono::steady_clock::now();
  const PointSource source(points);
  const double treeSeconds = secondsSince(clock);
  SignedDistanceResult result = computePointDistance(source, lattice, settings, distance, progress);
  result.treeSeconds = treeSeconds;
  return result;
}

namespace
{
// A field from points: unsigned, whatever `settings` ask (progress from 0.05 on: the source is
// built).
SignedDistanceResult unsignedDistance(const DistanceSource& source, const GridLattice& lattice,
  const SignedDistanceSettings& settings, float* distance, const Progress& progress)
{
  SignedDistanceSettings unsignedSettings = settings;
  unsignedSettings.computeSign = false;
  return progress.report(0.05)
    ? computeSignedDistance(source, lattice, unsignedSettings, distance, progress)
    : SignedDistanceResult();
}
} // namespace

SignedDistanceResult computePointDistance(const PointSource& source, const GridLattice& lattice,
  const SignedDistanceSettings& settings, float* distance, const Progress& progress)
{
  SignedDistanceResult result = unsignedDistance(source, lattice, settings, distance, progress);
  result.points = static_cast<long long>(source.points().size());
  return result;
}

SignedDistanceResult computeUnionDistance(const TriangleSoup& soup, const std::vector<Vec3>& points,
  const GridLattice& lattice, const SignedDistanceSettings& settings, float* distance,
  const Progress& progress)
{
  const auto clock = std::chrono::steady_clock::now();
  const UnionSource source(
    { std::make_shared<const TriangleSource>(soup), std::make_shared<const PointSource>(points) });
  const double treeSeconds = secondsSince(clock);
  SignedDistanceResult result = unsignedDistance(source, lattice, settings, distance, progress);
  result.treeSeconds = treeSeconds;
  result.points = static_cast<long long>(points.size());
  result.triangles = static_cast<long long>(soup.triangles.size());
  return result;
}

SignedDistanceResult computeDistance(const TriangleSoup& soup, const std::vector<Vec3>& points,
  const GridLattice& lattice, const SignedDistanceSettings& settings, float* distance,
  const Progress& progress)
{
  if (points.empty())
  {
    return computeSignedDistance(soup, lattice, settings, distance, progress);
  }
  return soup.triangles.empty()
    ? computePointDistance(points, lattice, settings, distance, progress)
    : computeUnionDistance(soup, points, lattice, settings, distance, progress);
}

namespace
{
std::string gibibytes(double bytes)
{
  std::ostringstream s;
  s.precision(3);
  s << bytes / (1024.0 * 1024.0 * 1024.0) << " GiB";
  return s.str();
}
} // namespace

Status checkSoup(const TriangleSoup& soup)
{
  if (soup.triangles.empty())
    return Status::failure(
      "the mesh has no polygons or triangle strips, so no surface to measure from");
  if (!soup.allFinite())
    return Status::failure(
      "the mesh has NaN or infinite point coordinates; fix or remove those points first");
  if (!withinCoordinateRange(soup.bounds()))
    return Status::failure(
      "the mesh has coordinates beyond +-1e30, which distances in float cannot hold; "
      "scale or translate it first");
  if (!(soup.maxTriangleArea() > 0))
    return Status::failure(
      "every triangle of the mesh is degenerate (zero area): there is no surface");
  return {};
}

namespace
{
template <typename Points>
Status checkPointsIn(const Points& points)
{
  if (points.empty())
    return Status::failure(
      "the input has no polygons, no 3-D cells and no points, so nothing to measure from");
  Box box;
  for (const Vec3& p : points)
  {
    if (!p.allFinite())
      return Status::failure(
        "the points have NaN or infinite coordinates; fix or remove those points first");
    box.extend(p);
  }
  if (!withinCoordinateRange(box))
    return Status::failure(
      "the points have coordinates beyond +-1e30, which distances in float cannot hold; "
      "scale or translate them first");
  return {};
}
} // namespace

Status checkPoints(const std::vector<Vec3>& points)
{
  return checkPointsIn(points);
}

Status checkPoints(const PointList& points)
{
  return checkPointsIn(points);
}

Status checkMemory(const GridLattice& lattice, const SignedDistanceSettings& settings)
{
  // In floating point: the node count of an absurd grid overflows 64-bit integers.
  const double nodes = static_cast<double>(lattice.dims[0]) * lattice.dims[1] * lattice.dims[2];
  const double needed = nodes * (sizeof(float) + workingBytesPerNode(settings));
  const double available = availableMemory();
  if (needed > 0.8 * available)
  {
    std::ostringstream why;
    why << "a " << lattice.dims[0] << " x " << lattice.dims[1] << " x " << lattice.dims[2]
        << " grid would need " << gibibytes(needed) << " but only " << gibibytes(available)
        << " of memory is available";
    return Status::failure(why.str());
  }
  return {};
}

Status signedDistanceGrid(const TriangleSoup& soup, const GridLattice& lattice,
  const SignedDistanceSettings& settings, DistanceGrid& grid, SignedDistanceResult& result,
  const Progress& progress, std::shared_ptr<const TriangleSource>* target)
{
  Status status = checkSoup(soup);
  if (status)
  {
    status = checkMemory(lattice, settings);
  }
  if (!status)
  {
    return status;
  }
  FieldValues values(lattice.nodeCount());
  result = fromSoup(soup, lattice, settings, values.data(), progress, target);
  grid = result.completed ? DistanceGrid(lattice, std::move(values)) : DistanceGrid();
  return {};
}

} // namespace shrinkwrap
