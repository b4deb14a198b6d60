// A wrap planned before it runs: the target as the core takes it, and every size the wrap will use,
// chosen once. The filter shows the plan's sizes in its panel before the run (planning is cheap: no
// field is computed) and starts the wrap from the same plan.
#ifndef ShrinkWrap_WrapPlan_h
#define ShrinkWrap_WrapPlan_h

#include "Common/Box.h"
#include "Common/Notes.h"
#include "Common/Status.h"
#include "Common/TriangleSoup.h"
#include "Distance/DistanceGrid.h"
#include "Distance/GridLattice.h"
#include "Wrap/PointCloud.h"
#include "Wrap/WrapSettings.h"

#include <memory>
#include <optional>

namespace shrinkwrap
{

// What is wrapped, and what is given beside it.
struct WrapTarget
{
  std::shared_ptr<const TriangleSoup> polygons; // the target's triangles; none: points only
  std::shared_ptr<const PointCloud> points;     // its points, measured once; none: polygons only
  // A distance field given beside the target: its lattice (all planning needs) and its values
  // (needed when the wrap starts). An unsigned one has no negative value.
  std::optional<GridLattice> fieldLattice;
  std::shared_ptr<const DistanceGrid> field;
  bool givenStart = false;                   // a surface to start from is given: `start` holds it
  std::shared_ptr<const TriangleSoup> start; // when the wrap starts
};

// The wrap's sizes as the panel shows them.
struct WrapSizes
{
  double cell = 0;                  // of the field the wrap moves on, target units
  double gap = 0;                   // Gap Size, target units
  std::optional<double> edgeLength; // Target Edge Length L, target units; none with Remeshing off
};

struct WrapPlan
{
  WrapSettings settings;            // as given, with a point cloud's automatic sizes chosen
  Box targetBox;                    // of the triangles' corners and the points wrapped
  GridLattice lattice;              // of the field the wrap moves on: the given one or computed
  bool computesField = true;        // false: the given field
  double gapSize = 0;               // target units
  std::optional<double> edgeLength; // L, target units; none with Remeshing off
  Notes notes;                      // sizes that make a useless wrap (sizeWarnings)

  WrapSizes sizes() const { return { this->lattice.spacing.x(), this->gapSize, this->edgeLength }; }
  // The evolver's settings: settings.evolution, remeshing towards L (adaptive within the range).
  EvolverSettings evolution() const;
  // The start's settings: settings.start, coarsened to L and at most 0.4 Gap Size from the target.
  StartSettings start() const;
};

// Plans the wrap of `target` with `settings`: checks both, chooses the sizes left unset (for points
// from their spacing, AutomaticSizes.h) and places the field.
Status planWrap(const WrapTarget& target, const WrapSettings& settings, WrapPlan& plan);

} // namespace shrinkwrap

#endif
