#include "Wrap/AutomaticSizes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace shrinkwrap
{

namespace
{
// A point cloud's automatic Gap Size, in median neighbour distances (of its sparsest part where its
// density varies): the union of balls of half of it covers a uniform sample's random gaps.
constexpr double kPointGapPerSpacing = 8;
// ... and at least this many cells of the field: a closing under a cell or so is lost in the grid's
// interpolation and leaves sub-cell tunnels.
constexpr double kMinPointGapCells = 1.5;
// A dense cloud's field is made finer (up to kMaxPointResolutionFactor) until that floor spans at
// most this many spacings.
constexpr double kDensePointGapPerSpacing = 11;
constexpr double kMaxPointResolutionFactor = 1.5;
// A sparser clean cloud's field is made finer (up to the same factor) until its gap spans this many
// cells: a closing over fewer joins what lies a gap and a cell apart.
constexpr double kSparsePointGapCells = 2.5;
// A cloud's automatic L, in median neighbour distances, between the diagonal / kLengthDivisor and
// the diagonal / kMaxPointLengthDivisor.
constexpr double kPointEdgePerSpacing = 10;
constexpr double kMaxPointLengthDivisor = 200;
// On a noisy cloud L may grow to kEdgePerNoise times its noise, at most the diagonal /
// kNoisyPointLengthDivisor: finer triangles would show only the noise.
constexpr double kEdgePerNoise = 16;
constexpr double kNoisyPointLengthDivisor = 30;
// The offset start's farthest distance from the closed target, in Gap Sizes: beyond half the gap
// the start merges parts the closing keeps apart.
constexpr double kMaxStartOffsetPerGap = 0.4;
// The shortest edge, in cells of the field, that the evolution's steps can carry.
constexpr double kShortestEdgeInCells = 0.45;
// A Target Edge Length that leaves fewer vertices than this (on the target's box) is warned of.
constexpr double kFewestVertices = 50;
} // namespace

double gapSizeFor(const WrapSettings& settings, const Box& targetBox)
{
  return settings.gapSize ? *settings.gapSize : targetBox.diagonal() / WrapSettings::kGapDivisor;
}

std::optional<double> edgeLengthFor(const WrapSettings& settings, const Box& targetBox)
{
  if (!settings.remeshing)
  {
    return std::nullopt;
  }
  return settings.targetEdgeLength ? *settings.targetEdgeLength
                                   : targetBox.diagonal() / WrapSettings::kLengthDivisor;
}

double maxStartOffset(double gapSize)
{
  return kMaxStartOffsetPerGap * gapSize;
}

namespace
{
// Beyond the box scaled by GridPlacement::boxScale, o s on every side (s its longest side) must
// hold the start's offset, the closing's radius and three cells of room: o s >= (offset + 3) h +
// gap / 2, with h = s (1 + 2 o) / resolution; so o (1 - 2 c) >= c + gap / (2 s), c below.
struct FieldRoom
{
  double side;  // s, target units
  double cells; // c = (offset + 3) / resolution
  double room() const { return 1 - 2 * this->cells; }
};

FieldRoom fieldRoom(const WrapSettings& settings, const Box& targetBox)
{
  return { GridPlacement().boxScale * targetBox.size().maxCoeff(),
    (settings.start.offset + 3) / std::max(settings.resolution, 1) };
}
} // namespace

GridPlacement fieldPlacement(
  const WrapSettings& settings, double gapSize, const Box& targetBox, bool givenStart)
{
  GridPlacement placement;
  placement.resolution = settings.resolution;
  placement.offsetFactor = kPaperOffsetFactor;
  const FieldRoom r = fieldRoom(settings, targetBox);
  if (!givenStart && settings.start.shape == StartShape::OffsetSurface && r.side > 0 &&
    r.room() > 0)
  {
    placement.offsetFactor =
      std::min((r.cells + 0.5 * gapSize / r.side) / r.room(), kPaperOffsetFactor);
  }
  return placement;
}

Status checkGapSize(const WrapSettings& settings, double gapSize, const Box& targetBox)
{
  const FieldRoom r = fieldRoom(settings, targetBox);
  const double largest = 2 * r.side * (kPaperOffsetFactor * r.room() - r.cells);
  if (gapSize <= largest)
  {
    return {};
  }
  // With o = 1: 1 - 3 c >= gap / (2 s), so the Resolution that holds the gap.
  const double share = 1 - gapSize / (2 * r.side);
  std::ostringstream message;
  if (share >= 0.5)
  {
    message << "Resolution " << settings.resolution << " is too coarse for the start ("
            << settings.start.offset << " cells out, Start Offset In Cells) and the gap closing "
            << "(Gap Size " << gapSize << ") around this target: raise it to at least "
            << std::ceil(3 * (settings.start.offset + 3) / share);
  }
  else
  {
    message << "Gap Size " << gapSize << " does not fit in the distance field around this target "
            << "(at most " << std::max(largest, 0.0) << " here): lower it (0: automatic, "
            << targetBox.diagonal() / WrapSettings::kGapDivisor << " here)";
  }
  return Status::failure(message.str());
}

namespace
{
// The cell of the field placed for `settings` around `box`, if it can be placed.
std::optional<double> fieldCell(const WrapSettings& settings, const Box& box, bool givenStart)
{
  GridLattice lattice;
  if (!placeGrid(
        box, fieldPlacement(settings, gapSizeFor(settings, box), box, givenStart), lattice))
  {
    return std::nullopt;
  }
  return lattice.spacing.maxCoeff();
}
} // namespace

WrapSettings withPointSizes(
  WrapSettings settings, const Box& box, const PointCloud& cloud, bool givenStart)
{
  const double spacing = cloud.spacing;
  const double diagonal = box.diagonal();
  // Noise above what an edge of the mesh's automatic length would show.
  const bool noisy = kEdgePerNoise * cloud.noise() > diagonal / WrapSettings::kLengthDivisor;
  if (!settings.targetEdgeLength && spacing > 0)
  {
    const double coarsest = std::clamp(kEdgePerNoise * cloud.noise(),
      diagonal / WrapSettings::kLengthDivisor, diagonal / kNoisyPointLengthDivisor);
    settings.targetEdgeLength =
      std::clamp(kPointEdgePerSpacing * spacing, diagonal / kMaxPointLengthDivisor, coarsest);
  }
  if (settings.gapSize)
  {
    return settings;
  }
  const double spacingGap = kPointGapPerSpacing * std::max(spacing, cloud.sparseSpacing);
  settings.gapSize = spacingGap;
  // A dense cloud's spacing gap lies under the grid's floor: a finer field lowers the floor. A
  // sparser clean one's may span too few cells for the closing: a finer field resolves it.
  if (const std::optional<double> cell = fieldCell(settings, box, givenStart))
  {
    const double dense = kMinPointGapCells * *cell / (kDensePointGapPerSpacing * spacing);
    const bool sparse = !noisy && spacingGap >= kMinPointGapCells * *cell;
    const double finer = std::max(dense, sparse ? kSparsePointGapCells * *cell / spacingGap : 0.0);
    if (finer > 1)
    {
      const double resolution =
        std::ceil(std::min(finer, kMaxPointResolutionFactor) * settings.resolution);
      settings.resolution =
        static_cast<int>(std::min(resolution, double(std::numeric_limits<int>::max())));
    }
  }
  // The cell depends on the gap (the box holds the closing): twice round settles it.
  for (int pass = 0; pass < 2; ++pass)
  {
    const std::optional<double> cell = fieldCell(settings, box, givenStart);
    if (!cell)
    {
      break;
    }
    settings.gapSize = std::max(spacingGap, kMinPointGapCells * *cell);
  }
  return settings;
}

Status checkEdgeLength(const WrapSettings& settings, double edgeLength, const Box& targetBox)
{
  // Equilateral triangles of the shortest adaptive edge over the box's surface (more than the
  // wrap's): vertices about 2 A / (sqrt(3) l^2).
  const double shortest = settings.edgeLengthRange[0] * edgeLength;
  const double vertices = 2 * 2 * targetBox.halfArea() / (std::sqrt(3.0) * shortest * shortest);
  if (!(vertices <= WrapSettings::kMaxVertices))
  {
    std::ostringstream message;
    message << "Target Edge Length " << edgeLength << " would make about " << vertices
            << " vertices on this target (at most " << WrapSettings::kMaxVertices << "); raise it";
    return Status::failure(message.str());
  }
  return {};
}

Status checkEdgeOnField(
  const WrapSettings& settings, double edgeLength, double cell, bool computesField)
{
  const double shortest = settings.edgeLengthRange[0] * edgeLength;
  if (!(shortest < kShortestEdgeInCells * cell))
  {
    return {};
  }
  std::ostringstream message;
  message << "Target Edge Length " << edgeLength << " makes edges down to " << shortest / cell
          << " cells of the distance field (cell " << cell << "), under the "
          << kShortestEdgeInCells << " its steps can carry: ";
  if (computesField)
  {
    message << "raise Resolution to at least "
            << std::ceil(settings.resolution * kShortestEdgeInCells * cell / shortest)
            << ", or raise the Target Edge Length (0: automatic)";
  }
  else
  {
    message << "give a finer Distance Field, or raise the Target Edge Length (0: automatic)";
  }
  return Status::failure(message.str());
}

Notes sizeWarnings(double gapSize, const std::optional<double>& edgeLength, const Box& targetBox)
{
  Notes notes;
  const double diagonal = targetBox.diagonal();
  const double automatic = diagonal / WrapSettings::kLengthDivisor;
  if (edgeLength)
  {
    // Equilateral triangles of edge L over the box's surface: more vertices than the wrap has.
    const double vertices =
      2 * 2 * targetBox.halfArea() / (std::sqrt(3.0) * *edgeLength * *edgeLength);
    if (vertices < kFewestVertices)
    {
      std::ostringstream message;
      message << "Target Edge Length " << *edgeLength << " leaves the wrap at most about "
              << std::max(4.0, std::round(vertices)) << " vertices on this target (its diagonal is "
              << diagonal << "): too coarse to follow it; lower it (0: automatic, " << automatic
              << " here)";
      warn(notes, message.str());
    }
  }
  const double side = targetBox.size().maxCoeff();
  if (gapSize > 0.5 * side)
  {
    std::ostringstream message;
    message << "Gap Size " << gapSize << " is over half the target's longest side (" << side
            << "): every gap and hole closes and the wrap is a blob around the whole target; "
            << "lower it (0: automatic, " << diagonal / WrapSettings::kGapDivisor << " here)";
    warn(notes, message.str());
  }
  return notes;
}

} // namespace shrinkwrap
