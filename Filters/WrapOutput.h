// The wrap's output as Shrink Wrap writes it: the surface of a step with its arrays (the wrap's
// geometry, closeness and quality), its step and status, and the run's summary.
#ifndef ShrinkWrap_WrapOutput_h
#define ShrinkWrap_WrapOutput_h

#include "Common/Notes.h"
#include "Distance/TargetDistance.h"
#include "Surface/SelfIntersections.h"
#include "Surface/SurfaceMesh.h"
#include "Wrap/Closeness.h"
#include "Wrap/WrapPlan.h"
#include "Wrap/WrapSession.h"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

class vtkPolyData;

namespace shrinkwrap
{
namespace convert
{

// How close the written wrap lies to its target both ways (Closeness.h), measured by the caller on
// the wrap's surface (its triangles as a soup); none: not measured.
using MeasureWrap = std::function<std::optional<Closeness>(const TriangleSoup& wrap)>;

// Step `wanted` of `session` (the last good one after a failure) as `output`, with all the arrays
// below; `seconds` the run's computing time so far, `timeStep` the output's time per step;
// `measure` (if set) adds the sampled distances both ways to the summary. Notes: the surface
// crosses itself; with `finished`, the summary line. A failure when the step is not a closed
// surface (an internal error).
Status writeWrap(const WrapSession& session, int wanted, double timeStep, double seconds,
  bool finished, vtkPolyData* output, Notes& notes, const MeasureWrap& measure = {});

// The wrap's surface as `output`: points x, triangles, point data Distance, AdvectionAlignment
// (from `samples`, the target's field at x), MeanCurvature, CoVolume, Normals, TangentialVelocity;
// cell data MinAngle, MaxAngle, JacobianCondition (see vtkShrinkWrapFilter.h).
void writeSurface(const std::vector<Vec3>& x, const SurfaceMesh& mesh,
  const std::vector<DistanceSample>& samples, const std::vector<Vec3>& tangentialVelocity,
  vtkPolyData* output);

// Cell data SelfIntersecting (1 where a triangle crosses another) and field data SelfIntersections
// (the number of crossing pairs).
void addSelfIntersections(const SelfIntersections& crossings, vtkPolyData* output);

// A wrap's figures as a user reads them, from its output's own arrays: |Distance| at the vertices
// (median, 95th percentile, largest; in the target's units and in cells of the field), the share of
// triangles with MinAngle under 20 degrees, self-intersecting pairs (SelfIntersections), and the
// sizes the run used.
struct WrapSummary
{
  std::array<double, 3>
    distance{}; // median, 95th percentile (value at rank floor(p (n - 1))), largest
  WrapSizes sizes;
  double smallAngleShare = 0; // of the triangles
  long long selfIntersections = 0;
  int vertices = 0, steps = 0;
  double seconds = 0;   // computing (fields, start and steps) in this session
  LeftOutParts leftOut; // of the target, at the last step (WrapSession::leftOut)
  // Sampled on both surfaces (Closeness.h): mean and largest distance, wrap to target and target
  // to wrap, in the target's units; none where not measured.
  std::optional<Closeness> sampled;
  std::string text() const; // one line: what the output messages show at the end of a run
};
WrapSummary summarize(vtkPolyData* output, const WrapSizes& sizes, int steps, double seconds);
// A wrap has landed when 95% of its vertices lie within kLandedCells cells of the field of the
// target, or when its last step moved it by under kStillCells cells on average (a membrane over a
// concavity, a surface between sparse points: where it rests); `motion` from
// WrapSession::meanMotion (none: not known, judged by the distances alone). The last step of one
// that has not is reported ("not landed: ..." and a warning).
constexpr double kLandedCells = 1.5;
constexpr double kStillCells = 0.02;
bool landed(const WrapSummary& summary, const std::optional<double>& motion);
std::string notLanded(const WrapSummary& summary, const std::optional<double>& motion); // why not
// What a wrap leaves out of its target, for its Status and its warning.
std::string leftOutText(const LeftOutParts& parts);
std::string leftOutWarning(const WrapSummary& summary);
// As field data: DistancePercentiles, DistancePercentilesInCells (3 each), FieldCellSize, GapSize,
// TargetEdgeLength, SmallAngleShare, ComputeSeconds, LeftOutParts (left out, of parts),
// SampledDistances (wrap to target mean and largest, target to wrap mean and largest; when
// measured), Summary (the text).
void addSummary(const WrapSummary& summary, vtkPolyData* output);

// Field data of the wrap's output: StepIndex, Time and Status; and the output's DATA_TIME_STEP.
void addStepFields(int step, double time, const std::string& status, vtkPolyData* output);

} // namespace convert
} // namespace shrinkwrap

#endif
