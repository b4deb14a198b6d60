// Where a closed triangle surface passes through itself: pairs of triangles that cross, not
// counting the vertices and edges they share. The wrap must never output one. Candidates come from
// a grid of triangle boxes (TriangleGrid, cells about two mean edge lengths wide); two triangles
// cross when an edge of one passes through the other, decided by the signs of tetrahedron volumes.
// Coplanar overlaps and mere touching (measure zero in an evolution) are not reported.
#ifndef ShrinkWrap_SelfIntersections_h
#define ShrinkWrap_SelfIntersections_h

#include "Common/Box.h"
#include "Common/Vec3.h"
#include "Surface/SurfaceMesh.h"
#include "Surface/TriangleGrid.h"

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

namespace shrinkwrap
{

struct SelfIntersections
{
  long long pairs = 0;            // crossing triangle pairs
  std::vector<char> intersecting; // per triangle: 1 if it crosses another
};

SelfIntersections findSelfIntersections(
  const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles);

// The crossings that edits made on a surface that did not cross itself (`before`): those of the
// triangles of (points, triangles) that `before` does not have (the same corners at the same
// positions, in any numbering; a split's halves count as made) with any other. Two triangles the
// edits left as they were did not cross before and do not now. `stop`, asked between the phases
// and within the search, ends the check early with the crossings found so far (a stopped step's
// result is discarded).
SelfIntersections findNewSelfIntersections(const SurfaceMesh& before,
  const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
  const std::function<bool()>& stop = {});

// Fronts stop where they meet: the vertices of each pair of triangles that crosses at `next` but
// did not at `previous` (the same triangles) go back to their `previous` positions, again until no
// new crossing is left (at worst every vertex of a crossing stays where it was). One grid of the
// boxes swept over the step serves every round; a round re-tests only the triangles it moved.
// Returns how many vertices were held; `crossing`, if given, gets the triangles of the crossings
// they were held for. `stop`, asked between and within the rounds, ends them early (a stopped
// step's result is discarded).
int holdNewCrossings(const std::vector<Vec3>& previous, std::vector<Vec3>& next,
  const std::vector<std::array<int, 3>>& triangles, std::vector<int>* crossing = nullptr,
  const std::function<bool()>& stop = {});

// Boxes `reach` around the triangles that `found` marks: where the edits that made them must be
// guarded.
std::vector<Box> boxesAround(const std::vector<Vec3>& points,
  const std::vector<std::array<int, 3>>& triangles, const SelfIntersections& found, double reach);

// The cells of size `cell` (a lattice through the origin) that any of `boxes` overlaps, one box
// each: many small overlapping boxes covered by few.
std::vector<Box> cellsCovering(const std::vector<Box>& boxes, double cell);

// For the local edits of a pass (collapses, flips): whether the triangles an edit would make cross
// the surface: the surface as it was when the pass began (points and triangles the guard only
// refers to: copies, not the mesh's own, which its edits change), and what the pass already made
// (two edits of one pass can meet across a thin part). The grid is built at the first question:
// most passes of an evolution ask none.
class CrossingGuard
{
public:
  // only: the boxes within which edits are checked (their triangles are recorded everywhere);
  // empty: every edit is.
  CrossingGuard(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
    std::vector<Box> only = {});
  // Merging gone into keep at m, which turns the triangles around them into (m, u, w), one for each
  // (u, w) of the rim. Once made, the fan replaces every triangle around keep and gone.
  bool collapseCrosses(
    int keep, int gone, const Vec3& m, const std::vector<std::array<int, 2>>& rim);
  void addCollapse(int keep, int gone, const Vec3& m, const std::vector<std::array<int, 2>>& rim);
  // Flipping edge (i, j) of triangles (i, j, c) and (j, i, d) to (c, d).
  bool flipCrosses(int i, int j, int c, int d);
  void addFlip(int i, int j, int c, int d);
  // `stop` (empty: never), asked within the build of the guard's grid: once it said yes, every edit
  // is said to cross (a stopped pass makes no more edits).
  void setStop(std::function<bool()> stop) { this->Stop = std::move(stop); }

private:
  struct Made
  {
    std::array<Vec3, 3> p;
    std::array<int, 3> id;
    Box box;
  };
  std::vector<Made> fan(int keep, const Vec3& m, const std::vector<std::array<int, 2>>& rim) const;
  std::vector<Made> flipped(int i, int j, int c, int d) const;
  // Whether any of `made` crosses a triangle of the surface not incident to a or b (the edit's
  // vertices whose triangles it replaces; -1: none), or an earlier edit's triangle.
  bool anyCrosses(const std::vector<Made>& made, int a, int b);
  bool guards(const Box& box) const; // whether edits overlapping `box` are checked
  void add(const std::vector<Made>& made);
  const TriangleGrid& grid();        // built at the first question, with the edits so far indexed
  void index(int edit);              // into EditCells
  const Vec3& position(int v) const; // where the pass's merges put it

  const std::vector<Vec3>& Points;
  const std::vector<std::array<int, 3>>& Triangles;
  std::vector<Box> Only;
  std::unique_ptr<TriangleGrid> OnlyBinned; // Only in a grid: it may hold thousands
  Box OnlyAround;                           // the box around them, when binned
  // The surface's triangles a question may meet (Ids: which), and the edits in the grid's cells:
  // all, or where a few boxes are guarded, those within Reach of them (a question's box overlaps a
  // guarded one and is at most Reach wide), until a wider question asks for all (IndexAll). A pass
  // that collapses a whole contour makes tens of thousands of edits, few near the guarded boxes.
  std::unique_ptr<TriangleGrid> Grid;
  std::vector<int> Ids;
  std::deque<Made> Edits; // no copies as it grows
  // Per vertex: merged by the pass (its old triangles are gone), as the merge's kept vertex, at
  // MovedTo, or as the gone one.
  enum : char
  {
    kUntouched = 0,
    kGone = 1,
    kKept = 2
  };
  std::vector<char> Merged;
  std::vector<Vec3> MovedTo;
  std::unordered_map<std::uint64_t, std::vector<int>> EditCells;
  double Cell = 0; // the grid's
  double Reach = 0;
  bool IndexAll = false;
  std::function<bool()> Stop;
};

} // namespace shrinkwrap

#endif
