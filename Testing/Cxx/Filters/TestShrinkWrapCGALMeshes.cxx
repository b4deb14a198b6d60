// Shrink Wrap on real meshes (CGAL's data set, Debian libcgal-demo) and the paper's "bent chair"
// (Fig. 3: a deformed cube with holes). From the icosphere without remeshing (the paper's scheme
// with edge flips and collapses; C = 3, 100 steps) at subdivision levels 3 and 4: no failure, a
// closed 2-manifold in one piece; on bunny00 and armadillo the median |d| within one cell (of the
// field the wrap moved on, its FieldCellSize) and fewer than 2% of triangles with a minimum angle
// below 20 degrees (issue #4's bar; CGAL's alpha wrap at similar vertex counts has 5-17%). The same
// with D = 0.5, below 2.5%. At the defaults (offset start, remeshing, exact near field, gap
// closing, fronts that stop where they meet; issue #10), on bunny00, armadillo and knot1: no
// failure, closed, one piece, no self-intersection, the median |d| within a tenth of that cell,
// fewer than 1% of triangles below 20 degrees, and sampled mean distances both ways below 0.15% of
// the diagonal (alpha_wrap_3 at diag/50: 0.07-0.23%, Testing/Benchmarks/RESULTS.md); the bunny
// keeps its ears and knot1 its genus, and the genus-3 CAD part mech-holes-shark its genus, with its
// open shell's rims inside the wrap; the adaptive edge length follows the fandisk's creases closer
// than L alone, with no more vertices, and Crease Angle 45 closer still (the creases covered as
// rims). Settings whose triangles degenerate (D = 1, C2 = 0.1) run through with edge collapses.
// Argument: the folder holding CGAL's data/meshes/*.off.
#include "Distance/SoupEdges.h"
#include "Surface/SurfaceMesh.h"
#include "TestUtilities.h"
#include "WrapEvaluation.h"
#include "vtkShrinkWrapFilter.h"

#include <vtkCellData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkStringArray.h>

#include <chrono>
#include <functional>
#include <utility>

namespace
{
// A cube of 6 x 6 quads per face, without the middle 2 x 2 quads of its four side faces, bent.
vtkSmartPointer<vtkPolyData> bentChair()
{
  const int n = 6;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> quads;
  auto corner = [&](int face, int u, int v) {
    const double a = -0.5 + static_cast<double>(u) / n, b = -0.5 + static_cast<double>(v) / n;
    double p[3];
    switch (face)
    {
      case 0:
        p[0] = -0.5;
        p[1] = b;
        p[2] = a;
        break;
      case 1:
        p[0] = 0.5;
        p[1] = a;
        p[2] = b;
        break;
      case 2:
        p[0] = a;
        p[1] = -0.5;
        p[2] = b;
        break;
      case 3:
        p[0] = b;
        p[1] = 0.5;
        p[2] = a;
        break;
      case 4:
        p[0] = b;
        p[1] = a;
        p[2] = -0.5;
        break;
      default:
        p[0] = a;
        p[1] = b;
        p[2] = 0.5;
        break;
    }
    // The bend: the top leans over, the seat sags.
    p[0] += 0.35 * (p[2] + 0.5) * (p[2] + 0.5);
    p[2] -= 0.2 * (0.25 - p[0] * p[0]);
    return points->InsertNextPoint(p);
  };
  for (int face = 0; face < 6; ++face)
  {
    for (int u = 0; u < n; ++u)
    {
      for (int v = 0; v < n; ++v)
      {
        const bool hole = face < 4 && u >= 2 && u < 4 && v >= 2 && v < 4;
        if (!hole)
        {
          const vtkIdType q[4] = { corner(face, u, v), corner(face, u + 1, v),
            corner(face, u + 1, v + 1), corner(face, u, v + 1) };
          quads->InsertNextCell(4, q);
        }
      }
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points); // duplicated points along face seams: the triangle soup welds them
  mesh->SetPolys(quads);
  return mesh;
}

struct Figures
{
  double median = 0, p90 = 0, smallAngles = 0, seconds = 0;
  double rimsLargest = 0; // the largest distance from `rims` to the wrap, % of the diagonal
  bool ok = false, closed = false;
  int pieces = 0;
  vtkIdType vertices = 0;
};

// Points along the rims of `soup` (its edges of one triangle), eleven per edge, ends included.
std::vector<shrinkwrap::Vec3> rimPoints(const shrinkwrap::TriangleSoup& soup)
{
  const shrinkwrap::TriangleSoup welded = shrinkwrap::weldDuplicatePoints(soup);
  const shrinkwrap::EdgeUses uses = shrinkwrap::edgeUses(welded);
  std::vector<shrinkwrap::Vec3> points;
  shrinkwrap::forEachEdge(uses, [&](std::size_t first, std::size_t last) {
    if (last - first == 1)
    {
      const auto& t = welded.triangles[uses[first].triangle];
      const shrinkwrap::Vec3 a = welded.points[t[uses[first].slot]],
                             b = welded.points[t[(uses[first].slot + 1) % 3]];
      for (int k = 0; k <= 10; ++k)
      {
        points.push_back(a + (k / 10.0) * (b - a));
      }
    }
  });
  return points;
}

// The default wrap of `target`, with the settings `set` changes; judged by sampling too
// (WrapEvaluation.h) when `sampled` and the target's triangles are given, and from `rims` (with the
// triangles) when given.
Figures wrap(vtkPolyData* target, const std::function<void(vtkShrinkWrapFilter*)>& set,
  testing::WrapFigures* sampled = nullptr, const shrinkwrap::TriangleSoup* soup = nullptr,
  const std::vector<shrinkwrap::Vec3>* rims = nullptr)
{
  vtkNew<vtkShrinkWrapFilter> filter;
  filter->SetInputData(target);
  set(filter);
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  Figures f;
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkPolyData* out = filter->GetOutput();
  auto* status = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("Status"));
  f.ok = status && status->GetValue(0) == "ok" && out->GetNumberOfPoints() > 0;
  f.vertices = out->GetNumberOfPoints();
  if (out->GetNumberOfPoints() == 0)
  {
    return f;
  }
  if (soup && (sampled || rims))
  {
    const shrinkwrap::TriangleSoup wrapped = testing::triangulated(out);
    if (sampled)
    {
      *sampled = testing::evaluateWrap(wrapped, *soup);
    }
    if (rims)
    {
      f.rimsLargest = testing::oneSided(*rims, wrapped, soup->bounds().diagonal()).largest;
    }
  }
  const double h = testing::fieldCell(out);
  std::vector<double> d;
  vtkDataArray* distance = out->GetPointData()->GetArray("Distance");
  for (vtkIdType i = 0; i < distance->GetNumberOfTuples(); ++i)
  {
    d.push_back(std::abs(distance->GetTuple1(i)) / h);
  }
  std::sort(d.begin(), d.end());
  f.median = d[d.size() / 2];
  f.p90 = d[d.size() * 9 / 10];
  vtkDataArray* angles = out->GetCellData()->GetArray("MinAngle");
  int small = 0;
  for (vtkIdType t = 0; t < angles->GetNumberOfTuples(); ++t)
  {
    small += angles->GetTuple1(t) < 20.0;
  }
  f.smallAngles = 100.0 * small / angles->GetNumberOfTuples();
  std::vector<shrinkwrap::Vec3> x(out->GetNumberOfPoints());
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    out->GetPoint(i, x[i].data());
  }
  shrinkwrap::SurfaceMesh mesh;
  std::string error;
  f.closed = testing::builds(x, testing::triangulated(out).triangles, mesh, error);
  vtkNew<vtkPolyDataConnectivityFilter> pieces;
  pieces->SetInputData(out);
  pieces->SetExtractionModeToAllRegions();
  pieces->Update();
  f.pieces = pieces->GetNumberOfExtractedRegions();
  return f;
}
} // namespace

int TestShrinkWrapCGALMeshes(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: TestShrinkWrapCGALMeshes <CGAL data/meshes folder>" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string folder = argv[1];
  std::printf("%-30s %-8s %-8s %-12s %-14s %-14s %-8s\n", "mesh", "start", "status", "median |d|",
    "90th pct |d|", "min angle<20", "seconds");
  const auto report = [](const std::string& label, const std::string& start, const Figures& f) {
    std::printf("%-30s %-8s %-8s %6.2f h     %6.2f h       %6.1f %%       %.2f\n", label.c_str(),
      start.c_str(), f.ok ? "ok" : "FAILED", f.median, f.p90, f.smallAngles, f.seconds);
    SW_CHECK(f.ok, label << " from " << start << ": 200 steps without failure");
    SW_CHECK(f.closed && f.pieces == 1,
      label << " from " << start << ": a closed 2-manifold in one piece (" << f.pieces
            << " pieces)");
  };
  for (const std::string name :
    { "bunny00", "armadillo", "elephant-with-holes", "knot1", "bent chair" })
  {
    vtkSmartPointer<vtkPolyData> target =
      name == "bent chair" ? bentChair() : testing::readOFF(folder + "/" + name + ".off");
    SW_CHECK(target != nullptr, name << " found in " << folder);
    if (!target)
    {
      continue;
    }
    const bool bar = name == "bunny00" || name == "armadillo";
    const bool defaultsBar = bar || name == "knot1";
    // D = 0 is the default (paper Fig. 11); D = 0.5, stable with edge flips, is what the README
    // recommends for closer wraps, so it is held to the same bars.
    for (const double D : { 0.0, 0.5 })
    {
      for (int level : { 3, 4 })
      {
        const Figures f = wrap(target, [&](vtkShrinkWrapFilter* w) {
          // The icosphere keeps its vertices: it moves at C = 3 over 100 steps (the defaults' C =
          // 12 over 25 steps suits a remeshed offset start, and leaves these triangles worse).
          w->SetStartingShape(vtkShrinkWrapFilter::ICOSPHERE);
          w->SetRemeshing(false);
          w->SetAdvectionSpeed(3);
          w->SetNumberOfSteps(100);
          w->SetSubdivisionLevel(level);
          w->SetConcavityPush(D);
        });
        const std::string label = name + (D > 0 ? " D=0.5" : "");
        report(label, "s=" + std::to_string(level), f);
        SW_CHECK(
          !bar || f.median <= 1.0, label << " s=" << level << ": median |d| within one cell");
        // Issue #4's bar is for D = 0. At D = 0.5 armadillo s = 3 measures 1.9-2.2% over
        // Resolutions 110-130 on the target's own d (2.2% with no gap closing at all): 2.5%.
        const double smallBar = D > 0 ? 2.5 : 2.0;
        SW_CHECK(!bar || f.smallAngles < smallBar,
          label << " s=" << level << ": fewer than " << smallBar
                << "% of triangles with an angle below 20 degrees");
      }
    }
    // The defaults, held to the bars on bunny00, armadillo and knot1 (genus 1, strands nearly
    // touching). The bent chair (whose start's contour nearly touches itself) is held to no
    // crossing; the open elephant (106 holes, which the wrap spans) also to issue #10's mean
    // distances: no farther than alpha_wrap_3's at diag/50 either way (0.215% and 0.099% of the
    // diagonal, RESULTS.md).
    const shrinkwrap::TriangleSoup soup = testing::triangulated(target);
    testing::WrapFigures sampled;
    const Figures f = wrap(
      target, [](vtkShrinkWrapFilter*) {}, &sampled, &soup);
    if (!defaultsBar)
    {
      std::printf("%-30s %-8s %-8s %6.2f h     %6.2f h       %6.1f %%       %.2f\n", name.c_str(),
        "defaults", f.ok ? "ok" : "FAILED", f.median, f.p90, f.smallAngles, f.seconds);
    }
    else
    {
      report(name, "defaults", f);
    }
    std::printf(
      "  sampled: mean %.3f%% / %.3f%%, largest %.2f%% / %.2f%% of the diagonal (wrap to target / "
      "target to wrap), %lld self-intersecting pairs, genus %d, %d vertices\n",
      sampled.wrapToTarget.mean, sampled.targetToWrap.mean, sampled.wrapToTarget.largest,
      sampled.targetToWrap.largest, sampled.selfIntersections, sampled.genus, sampled.vertices);
    SW_CHECK(sampled.selfIntersections == 0, name << " at the defaults: no self-intersection");
    if (defaultsBar)
    {
      SW_CHECK(f.median <= 0.1 && f.smallAngles < 1.0,
        name << " at the defaults: median |d| within a tenth of a cell, fewer than 1% below 20 "
                "degrees");
      SW_CHECK(sampled.wrapToTarget.mean < 0.15 && sampled.targetToWrap.mean < 0.15,
        name << " at the defaults: sampled mean distances below 0.15% of the diagonal both ways");
    }
    // Thin parts kept: the bunny's tall ear (lost, the largest distance from the target to the wrap
    // was 8-12% of the diagonal from the icosphere), knot1's genus.
    SW_CHECK(name != "bunny00" || sampled.targetToWrap.largest < 2.0,
      "bunny00: the ears kept (largest target to wrap " << sampled.targetToWrap.largest
                                                        << "% of the diagonal)");
    SW_CHECK(
      name != "knot1" || sampled.genus == 1, "knot1: genus 1 kept (" << sampled.genus << ")");
    SW_CHECK(name != "elephant-with-holes" ||
        (sampled.wrapToTarget.mean <= 0.215 && sampled.targetToWrap.mean <= 0.099),
      "elephant-with-holes: mean distances within alpha wrap's ("
        << sampled.wrapToTarget.mean << "% / " << sampled.targetToWrap.mean << "%)");
  }

  // Close Holes on the open elephant (1353 rim edges, holes wider than the Gap Size): its inside by
  // the winding number (issue #11), so the wrap stays outside instead of entering the holes;
  // measured 0.157% / 0.099% mean distances against alpha_wrap_3's 0.215% / 0.099% at diag/50
  // (RESULTS.md).
  {
    vtkSmartPointer<vtkPolyData> open = testing::readOFF(folder + "/elephant-with-holes.off");
    if (open)
    {
      const shrinkwrap::TriangleSoup soup = testing::triangulated(open);
      testing::WrapFigures sampled;
      const Figures f = wrap(
        open, [](vtkShrinkWrapFilter* w) { w->SetCloseHoles(true); }, &sampled, &soup);
      report("elephant-with-holes", "closed", f);
      std::printf("  sampled: mean %.3f%% / %.3f%%, genus %d, %lld self-intersecting pairs\n",
        sampled.wrapToTarget.mean, sampled.targetToWrap.mean, sampled.genus,
        sampled.selfIntersections);
      SW_CHECK(sampled.selfIntersections == 0 && sampled.wrapToTarget.mean < 0.2 &&
          sampled.targetToWrap.mean < 0.12,
        "elephant-with-holes, Close Holes: no crossing, sampled means below 0.2% and 0.12% of the "
        "diagonal");
    }
  }

  // A genus-3 CAD part (three holes through it) keeps its genus from the offset start, without a
  // crossing.
  {
    vtkSmartPointer<vtkPolyData> part = testing::readOFF(folder + "/mech-holes-shark.off");
    SW_CHECK(part != nullptr, "mech-holes-shark found");
    if (part)
    {
      const shrinkwrap::TriangleSoup soup = testing::triangulated(part);
      testing::WrapFigures sampled;
      const std::vector<shrinkwrap::Vec3> rims = rimPoints(soup);
      const Figures f = wrap(
        part, [](vtkShrinkWrapFilter*) {}, &sampled, &soup, &rims);
      report("mech-holes-shark", "defaults", f);
      std::printf("  sampled: mean %.3f%% / %.3f%%, genus %d, %lld self-intersecting pairs\n",
        sampled.wrapToTarget.mean, sampled.targetToWrap.mean, sampled.genus,
        sampled.selfIntersections);
      SW_CHECK(sampled.genus == 3 && sampled.selfIntersections == 0,
        "mech-holes-shark: genus 3 kept, no crossing (genus " << sampled.genus << ")");
      // Its open shell's rims stay inside the wrap (Cover Rims): without, the wrap's folds creep
      // back along the sheets and the rims poke out by 1.7-2.1% of the diagonal (RESULTS.md, issue
      // #10). With it, within issue #10's bar: 1.5 times alpha_wrap_3's largest at diag/50 (0.27%).
      // Measured from the rims themselves: the largest over the whole part is a pit narrower than
      // the gap, which the wrap spans 0.3-0.7% above with a 1% change of C (RESULTS.md, 2026-11-28,
      // late night).
      const Figures uncovered = wrap(
        part, [](vtkShrinkWrapFilter* w) { w->SetCoverRims(false); }, nullptr, &soup, &rims);
      std::printf("  largest rim to wrap: %.2f%% of the diagonal (%zu rim points), %.2f%% without "
                  "Cover Rims; "
                  "largest target to wrap %.2f%%\n",
        f.rimsLargest, rims.size(), uncovered.rimsLargest, sampled.targetToWrap.largest);
      SW_CHECK(!rims.empty() && f.rimsLargest <= 1.5 * 0.27 &&
          f.rimsLargest < 0.75 * uncovered.rimsLargest,
        "mech-holes-shark: the rims covered (largest rim to wrap "
          << f.rimsLargest << "% against " << uncovered.rimsLargest << "% without Cover Rims)");
    }
  }

  // A CAD part with sharp creases: the adaptive edge length (Edge Length Range 0.6 1.6) follows
  // them closer than L alone, with no more vertices. Its flat faces the wraps match alike, so the
  // mean distance from the target tells the creases apart (RESULTS.md: 0.050% against 0.055%); the
  // largest, one sample at a corner, does not always (1.16% against 1.30% in "Adaptive edge
  // length", 1.19% against 1.20% since the start keeps its slivers' orientation).
  {
    vtkSmartPointer<vtkPolyData> fandisk = testing::readOFF(folder + "/fandisk.off");
    SW_CHECK(fandisk != nullptr, "fandisk found");
    if (fandisk)
    {
      const shrinkwrap::TriangleSoup soup = testing::triangulated(fandisk);
      testing::WrapFigures uniform, adaptive;
      const Figures u = wrap(
        fandisk, [](vtkShrinkWrapFilter*) {}, &uniform, &soup);
      const Figures a = wrap(
        fandisk, [](vtkShrinkWrapFilter* w) { w->SetEdgeLengthRange(0.6, 1.6); }, &adaptive, &soup);
      std::printf("fandisk: target to wrap mean %.3f%%, largest %.2f%% with L alone (%lld "
                  "vertices); mean %.3f%%, "
                  "largest %.2f%% adaptive (%lld vertices, %.2f%% of angles under 20 degrees, %lld "
                  "crossing pairs)\n",
        uniform.targetToWrap.mean, uniform.targetToWrap.largest, static_cast<long long>(u.vertices),
        adaptive.targetToWrap.mean, adaptive.targetToWrap.largest,
        static_cast<long long>(a.vertices), a.smallAngles, adaptive.selfIntersections);
      SW_CHECK(a.ok && adaptive.selfIntersections == 0 && a.smallAngles < 1.0,
        "fandisk adaptive: no crossing, good triangles");
      // With Fit Facets the uniform wrap's mean fell from 0.054% to 0.042% and the adaptive one's
      // count rose past the uniform one's by 1% (2,938 against 2,908; 2,760 against 2,851 without
      // the fit).
      SW_CHECK(adaptive.targetToWrap.mean < 0.95 * uniform.targetToWrap.mean &&
          a.vertices <= 1.02 * u.vertices,
        "fandisk adaptive: its creases followed closer, with at most 2% more vertices");
      // Crease Angle 45: the creases count as rims and pull the wrap onto them (RESULTS.md: the
      // mean from the target 0.033% against 0.055%, with 8% more vertices; with Fit Facets 0.028%
      // against 0.042%, with 6% more).
      testing::WrapFigures creased;
      const Figures c = wrap(
        fandisk, [](vtkShrinkWrapFilter* w) { w->SetCreaseAngle(45); }, &creased, &soup);
      std::printf("fandisk at Crease Angle 45: target to wrap mean %.3f%%, largest %.2f%% (%lld "
                  "vertices, %.2f%% of angles "
                  "under 20 degrees, %lld crossing pairs)\n",
        creased.targetToWrap.mean, creased.targetToWrap.largest, static_cast<long long>(c.vertices),
        c.smallAngles, creased.selfIntersections);
      SW_CHECK(c.ok && creased.selfIntersections == 0 && c.smallAngles < 1.0 && creased.genus == 0,
        "fandisk at Crease Angle 45: no crossing, good triangles, genus 0");
      SW_CHECK(creased.targetToWrap.mean < 0.8 * uniform.targetToWrap.mean &&
          creased.wrapToTarget.mean < 0.9 * uniform.wrapToTarget.mean,
        "fandisk at Crease Angle 45: closer both ways than without (target to wrap "
          << creased.targetToWrap.mean << "% against " << uniform.targetToWrap.mean << "%)");
    }
  }

  // Settings where triangles degenerate as the surface is pulled into pockets (D = 1; C2 = 0.1 on
  // the open elephant): edge collapses keep the run going, with a few vertices fewer than the 642
  // it began with.
  const std::pair<std::string, std::function<void(vtkShrinkWrapFilter*)>> hard[] = {
    { "armadillo D=1", [](vtkShrinkWrapFilter* w) { w->SetConcavityPush(1.0); } },
    { "elephant-with-holes C2=0.1", [](vtkShrinkWrapFilter* w) { w->SetSmoothingFalloff(0.1); } },
  };
  for (const auto& entry : hard)
  {
    const std::string mesh = entry.first.substr(0, entry.first.find(' '));
    const Figures f =
      wrap(testing::readOFF(folder + "/" + mesh + ".off"), [&](vtkShrinkWrapFilter* w) {
        w->SetStartingShape(vtkShrinkWrapFilter::ICOSPHERE);
        w->SetRemeshing(false);
        w->SetGapSize(1e-9); // below a cell: the target's own field, as these runs were tuned on
        entry.second(w);
      });
    report(entry.first, "s=3", f);
    // (The elephant at C2 = 0.1 no longer degenerates since d is exact near the target: it runs
    // through without collapses.)
    SW_CHECK(mesh != "armadillo" || f.vertices < 642,
      entry.first << ": edges were collapsed (" << f.vertices << " vertices)");
  }

  // With remeshing (the default) cached steps differ in vertex count: a step recomputed from a
  // thinned cache (1 MiB) is still exactly the step of a fresh run.
  vtkSmartPointer<vtkPolyData> armadillo = testing::readOFF(folder + "/armadillo.off");
  const auto surfaceAt = [&](vtkShrinkWrapFilter* w, int step) {
    w->UpdateTimeStep(step * w->GetTimePerStep());
    vtkPolyData* out = w->GetOutput();
    std::vector<double> values;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      const double* p = out->GetPoint(i);
      values.insert(values.end(), p, p + 3);
    }
    for (const auto& t : testing::triangulated(out).triangles)
    {
      values.insert(values.end(), t.begin(), t.end());
    }
    return std::make_pair(out->GetNumberOfPoints(), values);
  };
  vtkNew<vtkShrinkWrapFilter> thinned, fresh;
  for (vtkShrinkWrapFilter* w : { thinned.Get(), fresh.Get() })
  {
    w->SetInputData(armadillo);
    w->SetNumberOfSteps(200);
  }
  thinned->SetCacheMemoryMiB(1);
  const auto last = surfaceAt(thinned, 200);
  const auto again = surfaceAt(thinned, 150);
  const auto expected = surfaceAt(fresh, 150);
  std::printf(
    "armadillo: %lld vertices at step 150, %lld at step 200; %d steps computed in all with a "
    "1 MiB cache\n",
    static_cast<long long>(expected.first), static_cast<long long>(last.first),
    thinned->GetNumberOfComputedSteps());
  SW_CHECK(last.first != expected.first,
    "steps 150 and 200 differ in vertex count (remeshing between them)");
  SW_CHECK(thinned->GetNumberOfComputedSteps() > 200, "step 150 was recomputed from a kept step");
  SW_CHECK(again == expected, "the recomputed step 150 equals a fresh run's");
  return testing::finish("TestShrinkWrapCGALMeshes");
}
