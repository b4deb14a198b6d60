#include "TargetInput.h"

#include "vtkInputGeometry.h"

#include "Wrap/Wrap.h"

#include <vtkPolyData.h>

#include <string>

namespace shrinkwrap
{
namespace convert
{

namespace
{
Status readPolygons(
  const PolygonMeshes& input, const Wording& words, TargetParts& parts, Notes& notes)
{
  const SoupCounts& counts = parts.counts;
  if (parts.polygons.triangles.empty() && counts.badCells == 0)
  {
    return Status::failure("the " + std::string(words.input) +
      " has no polygons or 3-D cells, and "
      "Input Geometry is Polygons; choose Automatic or Points to take its points");
  }
  if (counts.badCells > 0)
  {
    return Status::failure("the " + std::string(words.input) + " has " +
      std::to_string(counts.badCells) + " cells whose point ids are out of range: it is corrupt");
  }
  if (!input.extractedFrom.empty())
  {
    inform(notes,
      "the " + std::string(words.input) + " (" + input.extractedFrom + ") is " + words.verb +
        " by its outer surface, as Extract Surface gives it");
  }
  if (!parts.use.points && (counts.lines > 0 || counts.vertices > 0))
  {
    warn(notes,
      "Ignoring " + std::to_string(counts.lines) + " lines and " + std::to_string(counts.vertices) +
        " vertices: only polygons and triangle strips have an "
        "inside");
  }
  return {};
}

void readPoints(vtkDataObject* data, const PolygonMeshes& input, const Wording& words,
  TargetParts& parts, Notes& notes)
{
  if (!parts.use.polygons)
  {
    parts.points = pointsOf<PointList>(data);
    return;
  }
  for (vtkPolyData* mesh : input.meshes)
  {
    const PointList loose = loosePointsOf<PointList>(mesh);
    parts.points.insert(parts.points.end(), loose.begin(), loose.end());
  }
  if (parts.points.empty())
  {
    warn(notes,
      "Input Geometry is Polygons and Points, but every point of the " + std::string(words.input) +
        " lies on its polygons: the polygons are " + words.verb);
  }
}
} // namespace

Status readTarget(
  vtkDataObject* data, int inputGeometry, const Wording& words, TargetParts& parts, Notes& notes)
{
  parts = TargetParts();
  const PolygonMeshes input = polygonMeshes(data);
  parts.polygons = soupOf(input.meshes, parts.counts);
  const bool hasPolygons = !parts.polygons.triangles.empty() || parts.counts.badCells > 0;
  parts.use = chooseGeometry(inputGeometry, hasPolygons);
  if (parts.use.polygons)
  {
    if (Status read = readPolygons(input, words, parts, notes); !read)
    {
      return read;
    }
    parts.polygonBounds = surfaceBounds(input.meshes);
  }
  else
  {
    parts.polygons = TriangleSoup();
  }
  if (parts.use.points)
  {
    readPoints(data, input, words, parts, notes);
  }
  return {};
}

namespace
{
// The note that says which points are wrapped ("the target's 20000 points are wrapped").
std::string pointsNote(const TargetParts& parts, int inputGeometry, const Wording& words)
{
  const bool beside = parts.use.polygons;
  return std::string(beside ? "the " + std::string(words.input) + "'s polygons and the "
                            : "the " + std::string(words.input) + "'s ") +
    std::to_string(parts.points.size()) + (beside ? " points beside them" : " points") + " are " +
    words.verb + (inputGeometry == vtkInputGeometry::AUTOMATIC ? " (it has no polygons)" : "");
}
} // namespace

Status wrapTarget(vtkDataObject* data, int inputGeometry, WrapTarget& target, Notes& notes)
{
  const Wording words{ "target", "wrapped" };
  TargetParts parts;
  Status status = readTarget(data, inputGeometry, words, parts, notes);
  const std::string note = parts.points.empty() ? "" : pointsNote(parts, inputGeometry, words);
  if (status)
  {
    status = makeTarget(std::move(parts.polygons), std::move(parts.points), target);
  }
  if (status && !note.empty())
  {
    inform(notes, note);
  }
  return status;
}

} // namespace convert
} // namespace shrinkwrap
