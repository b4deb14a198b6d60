#include "Wrap/WrapPlan.h"

#include "Distance/SignedDistance.h"
#include "Wrap/AutomaticSizes.h"

namespace shrinkwrap
{

namespace
{
// The box of what is wrapped: the triangles' corners and the points.
Box boxOf(const WrapTarget& target)
{
  Box box = target.polygons ? target.polygons->bounds() : Box();
  if (target.points)
  {
    box.extend(target.points->points->bounds());
  }
  return box;
}

Status checkTarget(const WrapTarget& target, const Box& box)
{
  if (!target.polygons && !target.points)
    return Status::failure("the target has nothing to wrap");
  if (box.empty() || !box.min.allFinite() || !box.max.allFinite())
    return Status::failure("the target has NaN or infinite coordinates");
  if (target.points && target.fieldLattice)
    return Status::failure("points are not wrapped on a Distance Field: disconnect it (the wrap "
                           "computes the points' own)");
  return {};
}

// The field's lattice: the given field's, or placed around the target for the plan's sizes.
Status placeField(const WrapTarget& target, WrapPlan& plan)
{
  plan.computesField = !target.fieldLattice;
  if (target.fieldLattice)
  {
    plan.lattice = *target.fieldLattice;
    return {};
  }
  const GridPlacement placement =
    fieldPlacement(plan.settings, plan.gapSize, plan.targetBox, target.givenStart);
  Status status = placeGrid(plan.targetBox, placement, plan.lattice);
  return status ? checkMemory(plan.lattice, SignedDistanceSettings()) : status;
}
} // namespace

Status planWrap(const WrapTarget& target, const WrapSettings& settings, WrapPlan& plan)
{
  plan = WrapPlan();
  Status status = settings.validate();
  const Box box = boxOf(target);
  if (status)
  {
    status = checkTarget(target, box);
  }
  if (!status)
  {
    return status;
  }
  plan.targetBox = box;
  plan.settings =
    target.points ? withPointSizes(settings, box, *target.points, target.givenStart) : settings;
  plan.gapSize = gapSizeFor(plan.settings, box);
  plan.edgeLength = edgeLengthFor(plan.settings, box);
  if (plan.edgeLength)
  {
    status = checkEdgeLength(plan.settings, *plan.edgeLength, box);
  }
  if (status && !target.fieldLattice)
  {
    status = checkGapSize(plan.settings, plan.gapSize, box);
  }
  plan.notes = sizeWarnings(plan.gapSize, plan.edgeLength, box);
  status = status ? placeField(target, plan) : status;
  if (status && plan.edgeLength)
  {
    status = checkEdgeOnField(
      plan.settings, *plan.edgeLength, plan.lattice.spacing.maxCoeff(), plan.computesField);
  }
  return status;
}

EvolverSettings WrapPlan::evolution() const
{
  EvolverSettings e = this->settings.evolution;
  e.remeshing.reset();
  if (this->edgeLength)
  {
    RemeshSettings r = EvolverSettings::duringEvolution();
    r.targetLength = *this->edgeLength;
    r.shortest = this->settings.edgeLengthRange[0];
    r.longest = this->settings.edgeLengthRange[1];
    r.chordError = WrapSettings::kChordError;
    e.remeshing = r;
  }
  return e;
}

StartSettings WrapPlan::start() const
{
  StartSettings s = this->settings.start;
  s.coarsenTo = this->edgeLength;
  s.maxOffset = maxStartOffset(this->gapSize);
  return s;
}

} // namespace shrinkwrap
