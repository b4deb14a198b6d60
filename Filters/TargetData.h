// The target's own data on its wrap (Pass Target Arrays) and the target measured against the wrap
// (Shrink Wrap's second output): where each wrap vertex stands on the target (TargetFeet.h), and
// how far each part of the target lies from the wrap (TargetMeasure.h), as VTK data.
#ifndef ShrinkWrap_TargetData_h
#define ShrinkWrap_TargetData_h

#include "Common/Notes.h"
#include "Common/TriangleSoup.h"
#include "Distance/AABBTree.h"
#include "Distance/DistanceSource.h"
#include "Wrap/PointCloud.h"
#include "Wrap/TargetFeet.h"

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <memory>
#include <string>
#include <vector>

class vtkDataObject;
class vtkDataSet;
class vtkPolyData;

namespace shrinkwrap
{
namespace convert
{

// Where a run reads the target's data: the cell of each triangle of the target's soup, and the
// nearest point on that soup, through the session's distance source while the run holds it (no
// second tree), else a tree of its own. Made once per run, when the target has arrays to pass,
// from its geometry, which the run's key holds fixed; its arrays are read anew at each output.
struct TargetCarrier
{
  std::shared_ptr<const TriangleSoup> triangles; // the target's soup, as the run wrapped it
  std::vector<vtkIdType> cells;                  // per triangle: its cell over the meshes (soupOf)
  std::shared_ptr<const TriangleSource> source;  // the session's, of `triangles`; or
  std::unique_ptr<AABBTree> tree;                // a tree of its own
  NearestOnSoup nearest() const;
};
// `whole`: the target as wrapped (wholeTarget); `triangles`: its soup; `source`: the session's
// distance to it (used when it is that soup's TriangleSource). Null when `whole` does not give the
// soup's triangles (an internal error).
std::unique_ptr<TargetCarrier> makeCarrier(vtkDataObject* whole,
  std::shared_ptr<const TriangleSoup> triangles, std::shared_ptr<const DistanceSource> source);

// Whether `target` (a dataset or a composite) has arrays to pass: point, cell or field arrays
// besides the ghost marks.
bool hasArraysToPass(vtkDataObject* target);

// The target as one dataset: itself, or a composite's leaves appended (as the run converts it).
vtkSmartPointer<vtkDataObject> wholeTarget(vtkDataObject* target);

// The target's arrays onto `wrap`'s points: each point array read at the vertex's closest point on
// the target (barycentric on its triangle: `carrier`; for a target wrapped as points alone,
// `cloud`, the fit's weights), each cell array from the cell that point lies on, field data passed.
// Names the wrap uses already are given " (target)" (cell arrays whose name a point array has, "
// (target cells)"), and listed in `renamed`.
void passTargetArrays(vtkDataObject* whole, const TargetCarrier* carrier, const PointCloud* cloud,
  vtkPolyData* wrap, std::vector<std::string>& renamed);

// The run summary's sampled distances both ways between the wrap and its target.
constexpr int kSummarySamples = 5000;

// `target` measured against the wrap (a closed surface as a distance source): the dataset (a
// mesh as it is, other data by its outer surface) with point array DistanceToWrap (signed: > 0
// outside the wrap, < 0 inside; the active scalars) and cell array FarFromWrap (the share of the
// cell's area, or of its points for vertices and lines, farther than `gap` from the wrap), field
// data GapSize and, with `largest`, LargestDistanceToWrap (over the whole surface, not only its
// points: largestDistance; the run's last step asks for it).
vtkSmartPointer<vtkPolyData> measureTarget(
  vtkDataSet* target, const DistanceSource& wrap, double gap, bool largest);

} // namespace convert
} // namespace shrinkwrap

#endif
