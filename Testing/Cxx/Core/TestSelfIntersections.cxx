// Self-intersections of a surface (issue #10): an icosphere has none; two icospheres that overlap
// cross along a circle, and exactly the triangles near it are flagged; one vertex pushed through
// the opposite side makes its fan cross; shared vertices and edges are never counted. The grid
// behind them reports every overlapping box once (against brute force); fronts that meet are held
// back pair by pair, and named; many small boxes are covered by few lattice cells; the guard of a
// pass's edits refuses a flip whose new triangles would cross the surface, and remembers the pass's
// own edits, and a guard limited to boxes (thousands of them) checks only what reaches into them,
// looking everywhere when a question reaches far; the crossings edits made are found from the
// triangles they made alone; a round of edits is checked once and made again guarded near its
// crossings, then everywhere. And TargetDistance: near the target, d and grad d are the exact
// distance and direction to it.
#include "Distance/SignedDistance.h"
#include "Distance/TargetDistance.h"
#include "Remeshing/CheckedEdits.h"
#include "Surface/Icosphere.h"
#include "Surface/SelfIntersections.h"
#include "Surface/TriangleGrid.h"
#include "TestUtilities.h"

#include <algorithm>
#include <limits>
#include <random>

namespace
{
using namespace shrinkwrap;

void selfIntersections()
{
  const TriangleSoup sphere = icosphere(3, Vec3::Zero(), 1.0);
  SW_CHECK(findSelfIntersections(sphere.points, sphere.triangles).pairs == 0,
    "an icosphere does not cross itself");

  TriangleSoup two = sphere;
  const TriangleSoup other = icosphere(3, Vec3(1.0, 0.1, 0.05), 1.0);
  const int offset = static_cast<int>(two.points.size());
  two.points.insert(two.points.end(), other.points.begin(), other.points.end());
  for (auto t : other.triangles)
  {
    two.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  const SelfIntersections crossing = findSelfIntersections(two.points, two.triangles);
  int flagged = 0, far = 0;
  for (std::size_t t = 0; t < two.triangles.size(); ++t)
  {
    const Vec3 c = (two.points[two.triangles[t][0]] + two.points[two.triangles[t][1]] +
                     two.points[two.triangles[t][2]]) /
      3;
    const Vec3 other = t < sphere.triangles.size() ? Vec3(1.0, 0.1, 0.05) : Vec3::Zero();
    flagged += crossing.intersecting[t];
    // The circle where the spheres cross lies at distance 1 from both centres.
    far += crossing.intersecting[t] && std::abs((c - other).norm() - 1.0) > 0.15;
  }
  std::printf("two overlapping icospheres: %lld crossing pairs, %d triangles flagged\n",
    crossing.pairs, flagged);
  SW_CHECK(crossing.pairs > 20 && flagged > 20 && far == 0,
    "two overlapping spheres cross along their circle, and only there");

  TriangleSoup pushed = sphere;
  pushed.points[0] = -1.3 * pushed.points[0]; // through the other side
  SW_CHECK(findSelfIntersections(pushed.points, pushed.triangles).pairs > 0,
    "a vertex pushed through the sphere");
}

void triangleGrid()
{
  // Small random triangles in a unit cube: their boxes overlap in clusters.
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  unsigned state = 7;
  auto random = [&] { return (state = state * 1664525u + 1013904223u) / 4294967296.0; };
  for (int t = 0; t < 600; ++t)
  {
    const Vec3 c(random(), random(), random());
    for (int k = 0; k < 3; ++k)
    {
      points.push_back(c + 0.12 * Vec3(random(), random(), random()));
    }
    triangles.push_back({ 3 * t, 3 * t + 1, 3 * t + 2 });
  }
  const TriangleGrid grid(points, triangles);
  std::vector<Box> boxes(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int v : triangles[t])
    {
      boxes[t].extend(points[v]);
    }
  }
  long long expected = 0, reported = 0, wrong = 0;
  std::vector<int> times(triangles.size() * triangles.size(), 0);
  grid.forEachOverlappingPair(0, grid.bucketCount(), [&](int s, int t) {
    ++reported;
    ++times[std::min(s, t) * triangles.size() + std::max(s, t)];
  });
  for (std::size_t s = 0; s < triangles.size(); ++s)
  {
    for (std::size_t t = s + 1; t < triangles.size(); ++t)
    {
      const bool overlap = boxes[s].overlaps(boxes[t]);
      expected += overlap;
      wrong += times[s * triangles.size() + t] != (overlap ? 1 : 0);
    }
  }
  std::printf("grid of 600 random triangles: %lld overlapping pairs by brute force, %lld reported, "
              "%lld wrong\n",
    expected, reported, wrong);
  SW_CHECK(expected > 100 && reported == expected && wrong == 0,
    "every overlapping pair once, and no other");
  Box query;
  query.extend(Vec3(0.3, 0.3, 0.3));
  query.extend(Vec3(0.6, 0.5, 0.7));
  std::vector<int> near;
  grid.forEachNear(query, [&](int t) { near.push_back(t); });
  std::vector<int> brute;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (boxes[t].overlaps(query))
    {
      brute.push_back(static_cast<int>(t));
    }
  }
  std::sort(near.begin(), near.end());
  SW_CHECK(!brute.empty() && near == brute, "a box query finds every overlapping triangle once");

  // Three small triangles far apart: the grid spans far more cells than it has triangles, and a
  // query over many of them tests triangle by triangle.
  const std::vector<Vec3> sparse{ { 0, 0, 0 }, { 0.1, 0, 0 }, { 0, 0.1, 0 }, { 10, 10, 10 },
    { 10.1, 10, 10 }, { 10, 10.1, 10 }, { 20, 0, 0 }, { 20.1, 0, 0 }, { 20, 0.1, 0 } };
  const TriangleGrid apart(sparse, { { 0, 1, 2 }, { 3, 4, 5 }, { 6, 7, 8 } });
  Box most;
  most.extend(Vec3(-1, -1, -1));
  most.extend(Vec3(15, 15, 15));
  std::vector<int> found;
  apart.forEachNear(most, [&](int t) { found.push_back(t); });
  SW_CHECK((found == std::vector<int>{ 0, 1 }),
    "a query wider than the grid's cells finds the triangles in it once");
}

void heldFronts()
{
  const TriangleSoup sphere = icosphere(3, Vec3::Zero(), 1.0);
  std::vector<Vec3> next;
  for (const Vec3& p : sphere.points)
  {
    next.push_back(0.99 * p); // every vertex moves
  }
  next[0] = -1.3 * sphere.points[0]; // and one through the other side
  SW_CHECK(findSelfIntersections(next, sphere.triangles).pairs > 0, "the step would cross");
  std::vector<int> crossing;
  const int held = holdNewCrossings(sphere.points, next, sphere.triangles, &crossing);
  int unmoved = 0;
  for (std::size_t v = 0; v < next.size(); ++v)
  {
    unmoved += next[v] == sphere.points[v];
  }
  std::printf("a step through the sphere: %d vertices held, %d of %zu at their old positions\n",
    held, unmoved, next.size());
  SW_CHECK(findSelfIntersections(next, sphere.triangles).pairs == 0 && next[0] == sphere.points[0],
    "the crossing vertex is held, and no crossing is left");
  SW_CHECK(held == unmoved && held < 30, "only the vertices of crossing pairs are held");
  // The triangles it names are those of the crossings: the pushed vertex's fan among them, and
  // every one with a vertex it held.
  bool fan = false, allHeld = !crossing.empty();
  for (int t : crossing)
  {
    const auto& c = sphere.triangles[t];
    fan = fan || c[0] == 0 || c[1] == 0 || c[2] == 0;
    bool some = false;
    for (int v : c)
    {
      some =
        some || next[v] == sphere.points[v]; // every vertex moved: one at its old position was held
    }
    allHeld = allHeld && some;
  }
  SW_CHECK(
    fan && allHeld, "the crossings held are named by their triangles (" << crossing.size() << ")");
}

// Many small boxes, overlapping in clusters, covered by the lattice cells they touch: every point
// of every box lies in a cell, no cell twice, far fewer cells than boxes, and no cell that no box
// touches.
void coveringCells()
{
  unsigned state = 11;
  auto random = [&] { return (state = state * 1664525u + 1013904223u) / 4294967296.0; };
  std::vector<Box> boxes;
  for (int b = 0; b < 2000; ++b)
  {
    const Vec3 c =
      Vec3(random() < 0.5 ? 0.0 : 3.0, 0, 0) + 0.5 * Vec3(random(), random(), random());
    boxes.push_back({ c, c + 0.05 * Vec3(random(), random(), random()) });
  }
  const double cell = 0.1;
  const std::vector<Box> cells = cellsCovering(boxes, cell);
  int outside = 0, touched = 0;
  for (const Box& box : boxes)
  {
    for (int k = 0; k < 8; ++k)
    {
      const Vec3 corner((k & 1) ? box.max.x() : box.min.x(), (k & 2) ? box.max.y() : box.min.y(),
        (k & 4) ? box.max.z() : box.min.z());
      const Vec3 inside =
        box.min + (box.max - box.min).cwiseProduct(Vec3(random(), random(), random()));
      for (const Vec3& p : { corner, inside })
      {
        outside += std::none_of(
          cells.begin(), cells.end(), [&](const Box& c) { return c.squaredDistance(p) == 0; });
      }
    }
  }
  std::vector<Box> sorted = cells;
  auto less = [](const Box& a, const Box& b) {
    return std::lexicographical_compare(
      a.min.data(), a.min.data() + 3, b.min.data(), b.min.data() + 3);
  };
  std::sort(sorted.begin(), sorted.end(), less);
  const bool distinct =
    std::adjacent_find(sorted.begin(), sorted.end(),
      [](const Box& a, const Box& b) { return a.min == b.min; }) == sorted.end();
  for (const Box& c : cells)
  {
    const Box inner{ c.min + Vec3::Constant(1e-9), c.max - Vec3::Constant(1e-9) };
    touched +=
      std::any_of(boxes.begin(), boxes.end(), [&](const Box& b) { return b.overlaps(inner); });
  }
  std::printf("2000 small boxes in two clusters: covered by %zu cells of %g, %d points outside\n",
    cells.size(), cell, outside);
  SW_CHECK(
    outside == 0 && distinct && touched == static_cast<int>(cells.size()) && cells.size() < 500,
    "the cells cover every box, once each, and only cells a box touches");
}

void guardedEdits()
{
  // A roof: ridge i-j at z = 0.2 over the corners c, d at z = 0. Flipping to c-d makes a valley,
  // and a small upright triangle under the roof at (0.45, 0.35) would pierce it.
  const std::vector<Vec3> x{ { 0, 0, 0.2 }, { 1, 1, 0.2 }, { 1, 0, 0 }, { 0, 1, 0 },
    { 0.43, 0.35, 0.0 }, { 0.47, 0.35, 0.0 }, { 0.45, 0.35, 0.1 } };
  const std::vector<std::array<int, 3>> roof{ { 0, 1, 2 }, { 1, 0, 3 } };
  std::vector<std::array<int, 3>> withPost = roof;
  withPost.push_back({ 4, 5, 6 });
  CrossingGuard open(x, roof), blocked(x, withPost);
  SW_CHECK(!open.flipCrosses(0, 1, 2, 3), "a flip with nothing under the roof is allowed");
  SW_CHECK(blocked.flipCrosses(0, 1, 2, 3), "a flip whose valley would pierce the post is refused");
  // The post made by a later collapse in the same pass (m = its tip, rim (4, 5)) meets the flipped
  // valley, which the surface of the pass's beginning does not hold.
  SW_CHECK(!open.collapseCrosses(6, 6, x[6], { { 4, 5 } }), "the post misses the roof as it was");
  open.addFlip(0, 1, 2, 3);
  SW_CHECK(open.collapseCrosses(6, 6, x[6], { { 4, 5 } }), "but meets the valley the pass flipped");

  // A guard limited to boxes checks only the edits that reach into them.
  const Box there{ Vec3(0.4, 0.3, -0.1), Vec3(0.5, 0.4, 0.3) },
    elsewhere{ Vec3(5, 5, 5), Vec3(6, 6, 6) };
  CrossingGuard near(x, withPost, { elsewhere, there }), away(x, withPost, { elsewhere });
  SW_CHECK(near.flipCrosses(0, 1, 2, 3), "a guard whose boxes hold the flip refuses it");
  SW_CHECK(!away.flipCrosses(0, 1, 2, 3), "a guard whose boxes miss the flip lets it be");
  // Thousands of boxes (where the hold-back kept two parts apart), looked up through their own
  // grid.
  std::vector<Box> many;
  for (int k = 0; k < 3000; ++k)
  {
    const Vec3 c(2.0 + 0.01 * (k % 50), 2.0 + 0.01 * (k / 50), 0.0);
    many.push_back({ c, c + Vec3::Constant(0.02) });
  }
  CrossingGuard manyAway(x, withPost, many);
  many.push_back(there);
  CrossingGuard manyNear(x, withPost, many);
  SW_CHECK(manyNear.flipCrosses(0, 1, 2, 3) && !manyAway.flipCrosses(0, 1, 2, 3),
    "among thousands of boxes, the one that holds the flip guards it");
  // Boxes no grid can bin (an empty one, one without finite bounds) are asked one by one.
  many.push_back(Box{});
  const double inf = std::numeric_limits<double>::infinity();
  many.push_back({ Vec3::Constant(-inf), Vec3::Constant(inf) });
  CrossingGuard unbinnable(x, withPost, many);
  SW_CHECK(
    unbinnable.flipCrosses(0, 1, 2, 3), "with boxes no grid bins, the flip is still guarded");
  // Asked one by one, the finite boxes still decide: an empty box guards nothing.
  CrossingGuard emptyAway(x, withPost, { elsewhere, Box{} }),
    emptyNear(x, withPost, { Box{}, there });
  SW_CHECK(!emptyAway.flipCrosses(0, 1, 2, 3) && emptyNear.flipCrosses(0, 1, 2, 3),
    "beside an empty box, only the box that holds the flip guards it");
}

// A guard limited to a box looks only at the triangles and edits within reach of it, as far as its
// questions are narrow; a wide question (a fan from the box to the far side of the surface) makes
// it look at all of them, as a guard of everything does.
void guardReach()
{
  // A flat sheet at z = 0 over [0, 10]^2 (edges of 0.5, so the reach is a few units), then loose
  // vertices for the edits and questions.
  std::vector<Vec3> x;
  std::vector<std::array<int, 3>> sheet;
  const int n = 20;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
    {
      x.emplace_back(0.5 * i, 0.5 * j, 0.0);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      sheet.push_back({ a, b, d });
      sheet.push_back({ a, d, c });
    }
  auto loose = [&](const Vec3& p) {
    x.push_back(p);
    return static_cast<int>(x.size()) - 1;
  };
  // Near A = (1, 1): a small triangle above the sheet, and one through it.
  const int keepA = loose({ 1, 1, 1 }), goneA = loose({ 1, 1, 1 }), a1 = loose({ 1.2, 1, 1 }),
            a2 = loose({ 1, 1.2, 1 });
  const int b1 = loose({ 1.2, 1, -0.3 }), b2 = loose({ 1, 1.2, -0.3 });
  // Near B = (9, 9): a pass's edit, a flat triangle at z = 1 over (9, 9).
  const int keepB = loose({ 8.5, 8.5, 1 }), goneB = loose({ 8.5, 8.5, 1 }),
            p = loose({ 9.8, 8.8, 1 }), q = loose({ 8.8, 9.8, 1 });
  // The wide question: a fan triangle from A to a vertical edge through that edit at (9, 9).
  const int u = loose({ 9, 9, 0.5 }), w = loose({ 9, 9, 1.5 });
  const Box atA{ Vec3(0.5, 0.5, -0.5), Vec3(1.5, 1.5, 1.5) };

  auto ask = [&](CrossingGuard& guard) {
    std::array<bool, 3> answers{};
    answers[0] = guard.collapseCrosses(keepA, goneA, x[keepA], { { a1, a2 } }); // narrow, above: no
    answers[1] = guard.collapseCrosses(
      keepA, goneA, Vec3(1, 1, 0.3), { { b1, b2 } }); // narrow, through the sheet
    guard.addCollapse(keepB, goneB, x[keepB], { { p, q } });
    answers[2] =
      guard.collapseCrosses(keepA, goneA, x[keepA], { { u, w } }); // wide, through B's edit
    return answers;
  };
  CrossingGuard everything(x, sheet), limited(x, sheet, { atA });
  const std::array<bool, 3> all = ask(everything), some = ask(limited);
  SW_CHECK(!all[0] && all[1] && all[2],
    "a guard of everything: the narrow triangle above the sheet passes, the one "
    "through it and the wide fan through the far edit are refused");
  SW_CHECK(some == all,
    "a guard of a box at A answers the same: the far edit, indexed nowhere while the questions "
    "were narrow, is seen by the wide one ("
      << some[0] << some[1] << some[2] << ")");
  CrossingGuard elsewhere(x, sheet, { Box{ Vec3(4, 4, -1), Vec3(5, 5, 1) } });
  SW_CHECK(!elsewhere.collapseCrosses(keepA, goneA, Vec3(1, 1, 0.3), { { b1, b2 } }),
    "a guard of a box away from A lets the crossing at A be");
}

// The crossings edits made, from the triangles the edits made: a vertex pushed through the sphere
// (its fan is new), the same surface renumbered (nothing new), a split (its halves are new, and
// cross nothing).
void newCrossings()
{
  const TriangleSoup sphere = icosphere(3, Vec3::Zero(), 1.0);
  SurfaceMesh before;
  SW_CHECK(
    SurfaceMesh::build(sphere.points, sphere.triangles, before), "the sphere is a closed surface");
  TriangleSoup pushed = sphere;
  pushed.points[0] = -1.3 * pushed.points[0];
  const SelfIntersections all = findSelfIntersections(pushed.points, pushed.triangles);
  const SelfIntersections made = findNewSelfIntersections(before, pushed.points, pushed.triangles);
  SW_CHECK(made.pairs > 0 && made.pairs == all.pairs && made.intersecting == all.intersecting,
    "a vertex pushed through: the same " << all.pairs
                                         << " crossing pairs as the whole surface's check");

  // Renumbered: vertices in reverse, triangles rotated and in reverse.
  const int nv = static_cast<int>(pushed.points.size());
  std::vector<Vec3> reversed(pushed.points.rbegin(), pushed.points.rend());
  std::vector<std::array<int, 3>> renumbered;
  for (auto it = pushed.triangles.rbegin(); it != pushed.triangles.rend(); ++it)
  {
    renumbered.push_back({ nv - 1 - (*it)[1], nv - 1 - (*it)[2], nv - 1 - (*it)[0] });
  }
  SurfaceMesh pushedMesh;
  SW_CHECK(SurfaceMesh::build(pushed.points, pushed.triangles, pushedMesh),
    "the pushed sphere is a closed surface");
  SW_CHECK(findNewSelfIntersections(pushedMesh, reversed, renumbered).pairs == 0,
    "the same surface renumbered: no triangle is new, so no crossing is new");

  SurfaceMesh split = before;
  SW_CHECK(split.split(0, split.ring(split.ringBegin(0))) >= 0 && split.commit(), "a split");
  SW_CHECK(findNewSelfIntersections(before, split.points(), split.triangles()).pairs == 0,
    "a split's halves cross nothing");
}

// Issue #61: a stop asked within the search ends it between its batches with the crossings found so
// far: on a sphere jittered everywhere (every triangle new), a stop that says yes at its fourth ask
// (three before and between the phases, then the first between batches) finds some, fewer than
// the whole search.
void stoppedSearch()
{
  const TriangleSoup sphere = icosphere(5, Vec3::Zero(), 1.0); // enough buckets for 8 batches
  SurfaceMesh before;
  SW_CHECK(
    SurfaceMesh::build(sphere.points, sphere.triangles, before), "the sphere is a closed surface");
  std::vector<Vec3> jittered = sphere.points;
  std::mt19937 draw(61);
  std::uniform_real_distribution<double> offset(-0.03, 0.03);
  for (Vec3& p : jittered)
  {
    p += Vec3(offset(draw), offset(draw), offset(draw));
  }
  int asked = 0;
  const SelfIntersections some =
    findNewSelfIntersections(before, jittered, sphere.triangles, [&] { return ++asked >= 4; });
  const SelfIntersections all = findNewSelfIntersections(before, jittered, sphere.triangles);
  std::printf("a stopped search: %lld of %lld crossing pairs, the stop asked %d times\n",
    some.pairs, all.pairs, asked);
  SW_CHECK(asked == 4 && some.pairs > 0 && some.pairs < all.pairs && all.pairs > 100,
    "the search stopped after its first batch with the crossings found so far");

  // A grid whose build was stopped is empty and says so; a guard whose grid was stopped refuses
  // every edit (its pass makes no more).
  std::vector<Box> boxes;
  for (const auto& t : sphere.triangles)
  {
    boxes.push_back(Box::around(sphere.points, t));
  }
  asked = 0;
  const TriangleGrid stoppedGrid(boxes, 0.1, [&] { return ++asked > 0; });
  const TriangleGrid wholeGrid(boxes, 0.1, [] { return false; });
  SW_CHECK(stoppedGrid.stopped() && stoppedGrid.empty() && asked == 1 && !wholeGrid.stopped() &&
      !wholeGrid.empty(),
    "a stopped grid build leaves an empty grid");
  const int i = 0, p = before.ringBegin(0), j = before.ring(p);
  const int c = before.ring(before.next(i, p)), d = before.ring(before.previous(i, p));
  CrossingGuard free(sphere.points, sphere.triangles), stopped(sphere.points, sphere.triangles);
  stopped.setStop([] { return true; });
  SW_CHECK(!free.flipCrosses(i, j, c, d) && stopped.flipCrosses(i, j, c, d),
    "a guard stopped within its grid's build refuses the flip an unstopped one allows");
}

// A round of edits checked once: unguarded first, then guarded near where it crossed, then
// everywhere.
void checkedEdits()
{
  const TriangleSoup sphere = icosphere(3, Vec3::Zero(), 1.0);
  SurfaceMesh start;
  SW_CHECK(
    SurfaceMesh::build(sphere.points, sphere.triangles, start), "the sphere is a closed surface");
  // The "edit": pushes vertex 0 through the sphere unless guarded where it lies (or everywhere).
  std::vector<std::pair<bool, std::size_t>> calls;
  auto pushUnlessGuarded = [&](bool guardsVertex0) {
    return [&calls, guardsVertex0](SurfaceMesh& mesh, bool guarded, const std::vector<Box>& only) {
      calls.emplace_back(guarded, only.size());
      const bool covered = guarded &&
        (only.empty() || (guardsVertex0 && std::any_of(only.begin(), only.end(), [&](const Box& b) {
          return b.squaredDistance(mesh.points()[0]) == 0;
        })));
      if (!covered)
      {
        mesh.points()[0] = -1.3 * mesh.points()[0];
      }
      return true;
    };
  };
  SurfaceMesh mesh = start;
  editCheckedOnce(mesh, 0.1, pushUnlessGuarded(true));
  SW_CHECK(calls.size() == 2 && !calls[0].first && calls[1].first && calls[1].second > 0,
    "a crossing trial is made again with the edits near the crossing guarded");
  SW_CHECK(findSelfIntersections(mesh.points(), mesh.triangles()).pairs == 0 &&
      mesh.points()[0] == start.points()[0],
    "and that surface is kept");
  calls.clear();
  mesh = start;
  editCheckedOnce(mesh, 0.1, pushUnlessGuarded(false));
  SW_CHECK(calls.size() == 4 && calls[3].first && calls[3].second == 0 &&
      calls[2].second >= calls[1].second,
    "where guarding near the crossings does not help (twice, the boxes growing), every edit is "
    "guarded");
  SW_CHECK(
    findSelfIntersections(mesh.points(), mesh.triangles()).pairs == 0, "and no crossing is left");

  // Where a round crossed, the next is guarded from its first try: no redo there.
  calls.clear();
  mesh = start;
  const std::vector<Box> found = editCheckedOnce(mesh, 0.1, {}, pushUnlessGuarded(true));
  SW_CHECK(calls.size() == 2 && found.size() == calls[1].second && !found.empty(),
    "a round returns the boxes it needed guarded");
  calls.clear();
  mesh = start;
  const std::vector<Box> again = editCheckedOnce(mesh, 0.1, found, pushUnlessGuarded(true));
  SW_CHECK(calls.size() == 1 && calls[0].first && calls[0].second == found.size() &&
      again.empty() && mesh.points()[0] == start.points()[0],
    "the next round, guarded there from its first try, needs no redo and finds no crossing");
  calls.clear();
  const std::vector<Box> none =
    editCheckedOnce(mesh, 0.1, {}, [&](SurfaceMesh& m, bool guarded, const std::vector<Box>& only) {
      calls.emplace_back(guarded, only.size());
      m.points()[1] *= 1.01; // crosses nothing
      return true;
    });
  SW_CHECK(calls.size() == 1 && !calls[0].first && none.empty(),
    "a round without crossings is unguarded and finds none");
}

void exactNearTarget()
{
  const TriangleSoup sphere = icosphere(3, Vec3::Zero(), 1.0);
  const TriangleSoup soup{ sphere.points, sphere.triangles };
  GridLattice lattice;
  placeGrid(soup.bounds(), GridPlacement{ 1.1, 0.3, 32, 0 }, lattice);
  std::vector<float> values(lattice.nodeCount());
  computeSignedDistance(soup, lattice, {}, values.data());
  const auto source = std::make_shared<const TriangleSource>(soup);
  const TargetDistance grid(DistanceGrid(lattice, values)),
    exact(DistanceGrid(lattice, values), source, 2, true);
  const double h = lattice.spacing.maxCoeff();
  double gridError = 0, exactError = 0, gradientError = 0;
  for (int k = 0; k < 200; ++k)
  {
    // Points within a cell of the surface, outside and inside, off the vertices.
    const Vec3 direction = Vec3(std::sin(0.7 * k) * std::cos(1.3 * k),
      std::sin(0.7 * k) * std::sin(1.3 * k), std::cos(0.7 * k))
                             .normalized();
    const Vec3 x = (1.0 + (k % 2 ? 0.5 : -0.5) * h) * direction;
    const double reference = testing::bruteForceDistance(soup, x) * (x.norm() > 1.0 ? 1 : -1);
    const SourcePoint p = source->closestPoint(x, 1e9);
    const Vec3 outward = (reference > 0 ? 1.0 : -1.0) * (x - p.point).normalized();
    gridError = std::max(gridError, std::abs(grid.sample(x).value - reference));
    const DistanceSample s = exact.sample(x);
    exactError = std::max(exactError, std::abs(s.value - reference));
    gradientError = std::max(gradientError, (s.gradient - outward).norm());
  }
  std::printf("within half a cell of a sphere: largest |d| error %.2g h from the grid, %.2g h "
              "exact; grad d off by %.2g\n",
    gridError / h, exactError / h, gradientError);
  SW_CHECK(exactError < 1e-9 * h && gradientError < 1e-9, "near the target d and grad d are exact");
  SW_CHECK(gridError > 0.01 * h, "where the grid alone is not");
}
} // namespace

int TestSelfIntersections(int, char*[])
{
  selfIntersections();
  triangleGrid();
  heldFronts();
  coveringCells();
  guardedEdits();
  guardReach();
  newCrossings();
  checkedEdits();
  stoppedSearch();
  exactNearTarget();
  return testing::finish("TestSelfIntersections");
}
