// The sizes a wrap chooses where the user leaves them unset, as rules of the target's box and, for
// a point cloud, of its spacing and noise. The panel's documentation of Gap Size, Target Edge
// Length and Resolution states these rules to users (Plugin/ShrinkWrap.xml); a test holds the two
// together.
#ifndef ShrinkWrap_AutomaticSizes_h
#define ShrinkWrap_AutomaticSizes_h

#include "Common/Box.h"
#include "Common/Notes.h"
#include "Distance/GridLattice.h"
#include "Wrap/PointCloud.h"
#include "Wrap/WrapSettings.h"

#include <optional>

namespace shrinkwrap
{

// The Gap Size: the given one, else the box's diagonal / WrapSettings::kGapDivisor.
double gapSizeFor(const WrapSettings& settings, const Box& targetBox);
// The Target Edge Length L: the given one, else the diagonal / kLengthDivisor; none without
// Remeshing.
std::optional<double> edgeLengthFor(const WrapSettings& settings, const Box& targetBox);

// Where the field computed for a wrap lies: `settings.resolution` cells along the longest side of a
// box just large enough for the offset start and the gap closing, or the paper's box for an
// icosphere or a given start, which may lie anywhere around the target.
GridPlacement fieldPlacement(
  const WrapSettings& settings, double gapSize, const Box& targetBox, bool givenStart);

// The settings of a wrap onto `cloud` within `box`, with the sizes left unset chosen from its
// spacing: L (coarser on a noisy cloud) and the Gap Size (at least a few cells of the field placed
// for it), and, with the automatic Gap Size, a Resolution up to 1.5 times finer for a dense cloud
// (so that the cells do not widen the gap far beyond the spacing's) and for a clean one whose gap
// spans few cells (so that they resolve it).
WrapSettings withPointSizes(
  WrapSettings settings, const Box& box, const PointCloud& cloud, bool givenStart);

// Why the field computed around the target cannot hold the start and the gap closing (a Gap Size
// too large, a Resolution too coarse), if it cannot.
Status checkGapSize(const WrapSettings& settings, double gapSize, const Box& targetBox);
// Why the field's cell `cell` cannot carry edges of length L (shorter than kShortestEdgeInCells
// cells: the steps fail), naming the Resolution that can, if it cannot.
Status checkEdgeOnField(
  const WrapSettings& settings, double edgeLength, double cell, bool computesField);
// Why L would make too many vertices on a target of this box (at most kMaxVertices), if it would.
Status checkEdgeLength(const WrapSettings& settings, double edgeLength, const Box& targetBox);
// Warnings for sizes that make a wrap but a useless one: a Target Edge Length that leaves the wrap
// a handful of vertices, a Gap Size that closes every gap of the target (over half its longest
// side).
Notes sizeWarnings(double gapSize, const std::optional<double>& edgeLength, const Box& targetBox);

// The offset start's farthest distance from the closed target, target units.
double maxStartOffset(double gapSize);

} // namespace shrinkwrap

#endif
