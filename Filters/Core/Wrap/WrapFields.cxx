#include "Wrap/WrapFields.h"

#include "Distance/SignedDistance.h"
#include "Distance/UnionSource.h"
#include "Evolution/GapClosing.h"

#include <algorithm>
#include <string>

namespace shrinkwrap
{

namespace
{
const char* const kUnsignedEffect =
  ": the wrap stops at the distance it reaches from outside and inside alike";

// The given field's grid, checked: signed when it has an inside.
Status givenGrid(const DistanceGrid& given, Notes& notes, DistanceGrid& grid, bool& isSigned)
{
  const FieldValues& values = given.values();
  if (std::all_of(values.begin(), values.end(), [](float d) { return d < 0; }))
  {
    return Status::failure("the Distance Field has no outside (every value is negative), so no "
                           "surface can start around the target");
  }
  isSigned = std::any_of(values.begin(), values.end(), [](float d) { return d < 0; });
  if (!isSigned)
  {
    warn(notes,
      std::string("The Distance Field has no inside (no negative value): it is taken as "
                  "unsigned") +
        kUnsignedEffect);
  }
  grid = given;
  return {};
}

// What an open or self-crossing target gives with Close Holes off, in one sentence.
std::string openTarget(const SignedDistanceResult& result)
{
  if (result.boundaryEdges > 0)
  {
    return "The target is open (" + std::to_string(result.boundaryEdges) +
      " rim edges) and Close Holes is off: holes wider than the Gap Size stay open, and the wrap "
      "goes into them and wraps open sheets from both sides (Close Holes on closes them)";
  }
  return "The target crosses or overlaps itself (" + std::to_string(result.nonManifoldEdges) +
    " non-manifold edges) and Close Holes is off: the wrap moves on its unsigned distance (Close "
    "Holes on signs it by the winding number)";
}

// The target's field computed on the plan's lattice, and the target as a distance source.
Status computedGrid(const TriangleSoup& soup, const WrapPlan& plan, const Progress& progress,
  Notes& notes, DistanceGrid& grid, bool& isSigned, std::shared_ptr<const TriangleSource>& exact)
{
  SignedDistanceSettings distance;
  distance.windingNumber = plan.settings.closeHoles;
  SignedDistanceResult result;
  if (Status made =
        signedDistanceGrid(soup, plan.lattice, distance, grid, result, progress, &exact);
      !made)
  {
    return Status::failure("the target's distance field: " + made.message());
  }
  if (!result.completed)
  {
    return Status::failure("aborted");
  }
  isSigned = result.isSigned;
  if (result.signMethod == SignMethod::VotesDisagreed)
  {
    inform(notes, openTarget(result));
  }
  else if (const auto kind = signNoteKind(result, true))
  {
    notes.push_back({ *kind,
      "The target's distance field is " + signStatus(result, true) +
        (result.isSigned ? "" : kUnsignedEffect) });
  }
  return {};
}

Status meshFields(const WrapTarget& target, const WrapPlan& plan, const Progress& progress,
  Notes& notes, WrapFields& fields)
{
  DistanceGrid grid;
  bool isSigned = true;
  std::shared_ptr<const TriangleSource> exact;
  Status status;
  if (target.field)
  {
    status = givenGrid(*target.field, notes, grid, isSigned);
    if (status && plan.settings.exactNearTarget)
    {
      exact = std::make_shared<const TriangleSource>(*target.polygons);
    }
  }
  else
  {
    status =
      computedGrid(*target.polygons, plan, progress.stage(0, 0.7), notes, grid, isSigned, exact);
  }
  if (!status)
  {
    return status;
  }
  // A target whose triangles all face inwards (a reversed file): its near field takes its side
  // from the grid's sign, not from them.
  const bool inward = isSigned && exact && exact->facesInward(grid);
  status = wrapFields(std::move(grid), isSigned, exact, plan, fields, progress.stage(0.7, 1));
  fields.driving.setFacesInward(inward);
  fields.target.setFacesInward(inward);
  return status;
}

// The unsigned field of the points (and of the polygons beside them, if any).
Status pointFields(
  const WrapTarget& target, const WrapPlan& plan, const Progress& progress, WrapFields& fields)
{
  const PointCloud& cloud = *target.points;
  std::shared_ptr<const TriangleSource> polygons;
  if (target.polygons)
  {
    polygons = std::make_shared<const TriangleSource>(*target.polygons);
  }
  if (Status fits = checkMemory(plan.lattice, SignedDistanceSettings()); !fits)
  {
    return Status::failure("the points' distance field: " + fits.message());
  }
  FieldValues values(plan.lattice.nodeCount());
  SignedDistanceResult result;
  if (polygons)
  {
    SignedDistanceSettings unsignedDistance;
    unsignedDistance.computeSign = false;
    result = computeSignedDistance(UnionSource({ polygons, cloud.points }), plan.lattice,
      unsignedDistance, values.data(), progress.stage(0, 0.7));
  }
  else
  {
    result = computePointDistance(
      *cloud.points, plan.lattice, SignedDistanceSettings(), values.data(), progress.stage(0, 0.7));
  }
  if (!result.completed)
  {
    return Status::failure("aborted");
  }
  return pointWrapFields(DistanceGrid(plan.lattice, std::move(values)), cloud, plan, fields,
    polygons, progress.stage(0.7, 1));
}
} // namespace

Status makeWrapFields(const WrapTarget& target, const WrapPlan& plan, const Progress& progress,
  Notes& notes, WrapFields& fields)
{
  return target.points ? pointFields(target, plan, progress, fields)
                       : meshFields(target, plan, progress, notes, fields);
}

Status wrapFields(DistanceGrid grid, bool isSigned, std::shared_ptr<const DistanceSource> exact,
  const WrapPlan& plan, WrapFields& fields, const Progress& progress)
{
  DistanceGrid closed;
  if (Status status = closingField(grid, 0.5 * plan.gapSize, exact.get(), false, closed, progress);
      !status)
  {
    return status;
  }
  if (!plan.settings.exactNearTarget)
  {
    exact.reset();
  }
  const double band = plan.settings.exactBand;
  fields.driving = TargetDistance(std::move(closed), exact, band, isSigned);
  fields.target = TargetDistance(std::move(grid), exact, band, isSigned);
  return {};
}

Status pointWrapFields(DistanceGrid grid, const PointCloud& cloud, const WrapPlan& plan,
  WrapFields& fields, std::shared_ptr<const DistanceSource> polygons, const Progress& progress)
{
  using Sources = std::vector<std::shared_ptr<const DistanceSource>>;
  // The grid is the distance to the points and the polygons: the closing's sites come from the
  // nearer.
  std::shared_ptr<const DistanceSource> nearest = cloud.points;
  if (polygons)
  {
    nearest = std::make_shared<const UnionSource>(Sources{ polygons, cloud.points });
  }
  // Cavities filled: the union of balls around points that sample a sheet is a shell.
  DistanceGrid closed;
  if (Status status = closingField(grid, 0.5 * plan.gapSize, nearest.get(), true, closed, progress);
      !status)
  {
    return status;
  }
  // The driving distance's near field: the points' fitted surface, not the nearest point (which
  // would pull the closing's membranes between the points into dimples).
  std::shared_ptr<const DistanceSource> surface = cloud.surface;
  if (polygons)
  {
    surface =
      surface ? std::make_shared<const UnionSource>(Sources{ polygons, surface }) : polygons;
  }
  const bool exact = plan.settings.exactNearTarget;
  fields.driving =
    TargetDistance(std::move(closed), exact ? surface : nullptr, plan.settings.exactBand, true);
  // The wrap lies within half the gap of a point (inside the union of balls the closing erodes): a
  // band that wide makes the Distance array exact at every vertex.
  const double cell = grid.lattice().spacing.maxCoeff();
  const double band = std::max(plan.settings.exactBand, 0.5 * plan.gapSize / cell + 1);
  fields.target = TargetDistance(std::move(grid), exact ? nearest : nullptr, band, false);
  return {};
}

} // namespace shrinkwrap
