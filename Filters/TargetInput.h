// What both filters take of their input, by Input Geometry: the triangles of its polygons (and of
// its 3-D cells' outer surface) and its points, with the notes a user should read about the choice.
#ifndef ShrinkWrap_TargetInput_h
#define ShrinkWrap_TargetInput_h

#include "Common/Notes.h"
#include "Common/Status.h"
#include "Common/TriangleSoup.h"
#include "Distance/PointTree.h"
#include "VTKConversions.h"
#include "Wrap/WrapPlan.h"

#include <string>

class vtkDataObject;

namespace shrinkwrap
{
namespace convert
{

// How a filter names its input and what it does with it, for the notes ("target", "wrapped").
struct Wording
{
  const char* input;
  const char* verb;
};

struct TargetParts
{
  TriangleSoup polygons; // empty unless the polygons are taken
  Box polygonBounds;     // of the points the polygons and strips use (surfaceBounds)
  PointList points;      // empty unless points are taken (and, beside polygons, there are any)
  Geometry use;          // what was taken
  SoupCounts counts;     // of the polygons' conversion
};

// The parts of `data` that `inputGeometry` (vtkInputGeometry) takes; why there are none, if none.
Status readTarget(
  vtkDataObject* data, int inputGeometry, const Wording& words, TargetParts& parts, Notes& notes);

// The target of a wrap from `data` (Wrap.h: makeTarget), with a note of the points wrapped.
Status wrapTarget(vtkDataObject* data, int inputGeometry, WrapTarget& target, Notes& notes);

} // namespace convert
} // namespace shrinkwrap

#endif
