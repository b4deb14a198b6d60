// The Euler characteristic of a grid's marching-cubes contour, counted cell by cell without
// building it, on the grid and on its trilinear interpolant at half the spacing
// (DistanceGrid::refined). The case table settles a face whose corners alternate in sign by joining
// the corners below the value, not as the interpolant may; where that adds handles or joins
// components, the count at half the spacing is higher, and the start is taken of the grid with
// those faces separated, corner by corner (withFacesSeparated; contour() in VTKConversions.h).
#ifndef ShrinkWrap_ContourTopology_h
#define ShrinkWrap_ContourTopology_h

#include "Common/TriangleSoup.h"
#include "Distance/DistanceGrid.h"

#include <array>
#include <functional>
#include <vector>

namespace shrinkwrap
{

// The triangles the classic marching-cubes case table (VTK's vtkMarchingCubesTriangleCases, which
// the filters' contour uses) puts in a cell, by case: bit k of the case set where corner k of the
// cell (VTK's hexahedron order) lies at or above the value.
const std::array<int, 256>& marchingCubesTriangleCounts();

// V - F / 2 of the contour at `value` (V - E + F of a closed triangle surface, E = 3F / 2; 2 per
// component less 2 per handle): a vertex per grid edge that crosses the value, the case table's
// triangles per cell. `grid` of the grid's contour, `halfSpacing` of the contour of grid.refined(),
// both in one pass over the cells that cross the value (a trilinear cell's values lie between its
// corners').
struct ContourEuler
{
  long long grid = 0;
  long long halfSpacing = 0;
};
ContourEuler contourEulerCharacteristic(const DistanceGrid& grid, double value);
// The same for several values in one pass over the cells.
std::vector<ContourEuler> contourEulerCharacteristics(
  const DistanceGrid& grid, const std::vector<double>& values);

// The grid with the case table's wrong joins undone on the faces: where two diagonal corners of a
// face lie below `value` and the face's bilinear saddle does not (the interpolant keeps them apart,
// the table joins them), the shallower of the two is raised above the value, so that it counts as
// above, unless that would change the Euler characteristic of the interpolant's contour at half the
// spacing or lower the grid's. The contour moves by under a cell there and keeps the grid's
// triangle count, where refined() would quadruple it.
DistanceGrid withFacesSeparated(const DistanceGrid& grid, double value);

// Marching cubes of a grid at one value, with the case table of marchingCubesTriangleCounts (the
// filters give VTK's Flying Edges).
using Contour = std::function<TriangleSoup(const DistanceGrid& grid, double value)>;

// The contour of `grid` at `value`, of the grid with its faces separated (withFacesSeparated) where
// the interpolant at half the spacing has fewer handles or joined components than the grid's
// contour: there the case table joins two parts the field keeps apart (a bridge a cell wide between
// parts about twice the value apart). Elsewhere the grid's own, since raised corners would still
// move the contour.
TriangleSoup contourWithFewerJoins(const DistanceGrid& grid, double value, const Contour& contour);

} // namespace shrinkwrap

#endif
