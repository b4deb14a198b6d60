// A wrap that follows a target through time (issue #63), on three series:
//   BenchFollow <CGAL data/meshes folder> [--frames N] [--series twist,apart,blobs] [--samples N]
//     twist  armadillo.off twisted about the vertical axis of its box, up to 90 degrees at the top
//            over the series (the same triangles every frame: the wrap is carried with them)
//     apart  two spheres of radius 1 that overlap, then come apart (one part, then two)
//     blobs  the isosurface f = 0.5 of three Gaussian blobs circling each other, contoured anew
//            every frame (no two frames share triangles), as a simulation's output would be
// Each series is followed by one Shrink Wrap at the defaults (Time Mode: Automatic), frame after
// frame as an animation plays it, and wrapped afresh frame by frame by a new filter (Evolution
// Steps); per frame, the figures of both (WrapEvaluation.h: mean and largest distances both ways in
// % of the diagonal, closed, 2-manifold, crossing pairs), the followed one's over the fresh one's,
// the share of vertices whose TrackId was in the frame before, and how its Displacement agrees with
// the analytic motion: twist and apart, |D - D_true| over |D_true| on average, D_true the motion
// of the target's point under the vertex; blobs, the component along the normal (the surface's
// motion along its normal is all a contour defines). Times: the whole series, both ways.
#include "SeriesSource.h"
#include "TestUtilities.h"
#include "WrapEvaluation.h"
#include "vtkShrinkWrapFilter.h"

#include "Wrap/TargetFeet.h"

#include <vtkContourFilter.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkSphereSource.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <set>
#include <sstream>

namespace
{
using shrinkwrap::TriangleSoup;
using shrinkwrap::Vec3;

double seconds(const std::chrono::steady_clock::time_point& begin)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

// A series: the target at frame k of n.
using Frame = std::function<vtkSmartPointer<vtkPolyData>(int k)>;
using testing::SeriesSource;

vtkSmartPointer<vtkPolyData> withPoints(vtkPolyData* mesh, const std::vector<Vec3>& x)
{
  auto moved = vtkSmartPointer<vtkPolyData>::New();
  moved->ShallowCopy(mesh);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), x[i].data());
  }
  moved->SetPoints(points);
  return moved;
}

std::vector<Vec3> pointsOf(vtkPolyData* mesh)
{
  std::vector<Vec3> x(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    mesh->GetPoint(i, x[i].data());
  }
  return x;
}

// The twist: a point at height s (0 at the bottom of the box, 1 at the top) turns about the box's
// vertical axis by s * 90 degrees * k / (n - 1).
struct Twist
{
  std::vector<Vec3> rest;
  Vec3 center;
  double low = 0, height = 1;
  Vec3 at(const Vec3& p, double phase) const
  {
    const double s = (p.y() - low) / height, angle = phase * s * M_PI / 2;
    const double c = std::cos(angle), sn = std::sin(angle);
    const Vec3 d = p - center;
    return center + Vec3(c * d.x() + sn * d.z(), d.y(), -sn * d.x() + c * d.z());
  }
};

// Two spheres at x = -+ (0.6 + 1.0 * k / (n - 1)): overlapping, then 1.2 apart.
Vec3 sphereShift(int part, double phase)
{
  const double c = 0.6 + 1.0 * phase;
  return Vec3(part == 0 ? -c : c, 0, 0);
}

// Three blobs circling the origin: f = sum exp(-|x - c_i|^2 / 0.5), contoured at 0.5.
std::array<Vec3, 3> blobCenters(double phase)
{
  std::array<Vec3, 3> c;
  for (int i = 0; i < 3; ++i)
  {
    const double a = 2 * M_PI * i / 3 + phase * M_PI / 2;
    const double r = 0.9 + 0.3 * std::sin(phase * M_PI + i);
    c[i] = Vec3(r * std::cos(a), 0.25 * std::sin(a + phase), r * std::sin(a));
  }
  return c;
}
double blobField(const Vec3& x, double phase)
{
  double f = 0;
  for (const Vec3& c : blobCenters(phase))
  {
    f += std::exp(-(x - c).squaredNorm() / 0.5);
  }
  return f;
}
Vec3 blobGradient(const Vec3& x, double phase)
{
  Vec3 g = Vec3::Zero();
  for (const Vec3& c : blobCenters(phase))
  {
    g += -2 / 0.5 * std::exp(-(x - c).squaredNorm() / 0.5) * (x - c);
  }
  return g;
}
vtkSmartPointer<vtkPolyData> blobSurface(double phase)
{
  const int n = 72;
  const double lo = -2.6, h = 5.2 / (n - 1);
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, n);
  image->SetOrigin(lo, lo, lo);
  image->SetSpacing(h, h, h);
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  f->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        f->SetValue(i + n * (j + n * static_cast<vtkIdType>(k)),
          blobField(Vec3(lo + i * h, lo + j * h, lo + k * h), phase));
      }
    }
  }
  image->GetPointData()->SetScalars(f);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(image);
  contour->SetValue(0, 0.5);
  contour->ComputeNormalsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->ShallowCopy(contour->GetOutput());
  return surface;
}

struct Series
{
  std::string name;
  int frames = 0;
  Frame make;
  // The analytic displacement, since frame k - 1, of the wrap's vertex x at frame k with outward
  // normal n; `normalOnly`: only its component along n is defined (a contour).
  std::function<Vec3(int k, const Vec3& x, const Vec3& n)> motion;
  bool normalOnly = false;
};

// Where the material point under x (on frame k's target, by its closest point) was at frame k - 1.
Vec3 materialMotion(const TriangleSoup& now, const TriangleSoup& before, const Vec3& x)
{
  static thread_local const TriangleSoup* cached = nullptr;
  static thread_local std::unique_ptr<shrinkwrap::AABBTree> tree;
  if (cached != &now)
  {
    tree = std::make_unique<shrinkwrap::AABBTree>(now);
    cached = &now;
  }
  const shrinkwrap::ClosestHit hit = tree->closestPoint(x);
  const auto& t = now.triangles[hit.triangle];
  const auto w =
    shrinkwrap::barycentric(hit.point, now.points[t[0]], now.points[t[1]], now.points[t[2]]);
  const Vec3 then =
    w[0] * before.points[t[0]] + w[1] * before.points[t[1]] + w[2] * before.points[t[2]];
  return hit.point - then;
}

Series twistSeries(const std::string& folder, int frames)
{
  vtkSmartPointer<vtkPolyData> mesh = testing::readOFF(folder + "/armadillo.off");
  auto twist = std::make_shared<Twist>();
  twist->rest = pointsOf(mesh);
  shrinkwrap::Box box;
  for (const Vec3& p : twist->rest)
  {
    box.extend(p);
  }
  twist->center = box.center();
  twist->low = box.min.y();
  twist->height = box.size().y();
  Series s;
  s.name = "twist";
  s.frames = frames;
  s.make = [mesh, twist, frames](int k) {
    const double phase = double(k) / (frames - 1);
    std::vector<Vec3> x(twist->rest.size());
    for (std::size_t i = 0; i < x.size(); ++i)
    {
      x[i] = twist->at(twist->rest[i], phase);
    }
    return withPoints(mesh, x);
  };
  return s;
}

Series apartSeries(int frames)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  sphere->SetRadius(1);
  sphere->Update();
  auto one = vtkSmartPointer<vtkPolyData>::New();
  one->DeepCopy(sphere->GetOutput());
  Series s;
  s.name = "apart";
  s.frames = frames;
  s.make = [one, frames](int k) {
    const double phase = double(k) / (frames - 1);
    const std::vector<Vec3> rest = pointsOf(one);
    std::vector<Vec3> x;
    for (int part = 0; part < 2; ++part)
    {
      for (const Vec3& p : rest)
      {
        x.push_back(p + sphereShift(part, phase));
      }
    }
    auto both = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkCellArray> polys;
    const vtkIdType n = one->GetNumberOfPoints();
    vtkNew<vtkIdList> ids;
    for (int part = 0; part < 2; ++part)
    {
      for (vtkIdType c = 0; c < one->GetNumberOfCells(); ++c)
      {
        one->GetCellPoints(c, ids);
        std::vector<vtkIdType> shifted;
        for (vtkIdType j = 0; j < ids->GetNumberOfIds(); ++j)
        {
          shifted.push_back(ids->GetId(j) + part * n);
        }
        polys->InsertNextCell(static_cast<vtkIdType>(shifted.size()), shifted.data());
      }
    }
    both->SetPolys(polys);
    return withPoints(both, x);
  };
  return s;
}

Series blobSeries(int frames)
{
  Series s;
  s.name = "blobs";
  s.frames = frames;
  s.normalOnly = true;
  s.make = [frames](int k) { return blobSurface(double(k) / (frames - 1)); };
  // Along the normal: the distance s with f_{k-1}(x - s n) = 0.5 (Newton from s = 0).
  s.motion = [frames](int k, const Vec3& x, const Vec3& n) -> Vec3 {
    const double phase = double(k - 1) / (frames - 1);
    double step = 0;
    for (int it = 0; it < 20; ++it)
    {
      const Vec3 y = x - step * n;
      const double slope = -blobGradient(y, phase).dot(n);
      if (std::abs(slope) < 1e-12)
      {
        break;
      }
      step -= (blobField(y, phase) - 0.5) / slope;
    }
    return step * n;
  };
  return s;
}

TriangleSoup soupOf(vtkPolyData* mesh)
{
  return testing::triangulated(mesh);
}

struct FrameFigures
{
  testing::WrapFigures followed, fresh;
  double kept = 0;        // share of vertices whose TrackId was in the frame before
  double motionError = 0; // mean |D - D_true| over mean |D_true|
  std::string status;
};

std::string statusOf(vtkPolyData* wrap)
{
  auto* a = vtkStringArray::SafeDownCast(wrap->GetFieldData()->GetAbstractArray("Status"));
  return a ? a->GetValue(0) : "";
}

void run(const Series& series, int samples)
{
  vtkNew<SeriesSource> source;
  source->Make = series.make;
  source->Frames = series.frames;
  std::vector<TriangleSoup> targets(series.frames);
  for (int k = 0; k < series.frames; ++k)
  {
    targets[k] = soupOf(series.make(k));
  }
  // Followed, frame after frame.
  vtkNew<vtkShrinkWrapFilter> follow;
  follow->SetInputConnection(source->GetOutputPort());
  std::vector<vtkSmartPointer<vtkPolyData>> followed(series.frames);
  auto begin = std::chrono::steady_clock::now();
  for (int k = 0; k < series.frames; ++k)
  {
    follow->UpdateTimeStep(k);
    followed[k] = vtkSmartPointer<vtkPolyData>::New();
    followed[k]->DeepCopy(follow->GetOutput());
  }
  const double followSeconds = seconds(begin);
  // The wrapping alone (fields, start and steps: each output's ComputeSeconds), without what the
  // filter measures on the written wrap (the target as measured, the summary's samples).
  auto computing = [](vtkPolyData* wrap) {
    vtkDataArray* a =
      vtkDataArray::SafeDownCast(wrap->GetFieldData()->GetAbstractArray("ComputeSeconds"));
    return a ? a->GetTuple1(0) : 0.0;
  };
  double followComputing = 0, freshComputing = 0;
  for (const auto& wrap : followed)
  {
    followComputing += computing(wrap);
  }
  // Fresh, frame by frame.
  std::vector<vtkSmartPointer<vtkPolyData>> fresh(series.frames);
  double freshSeconds = 0;
  for (int k = 0; k < series.frames; ++k)
  {
    vtkSmartPointer<vtkPolyData> target = series.make(k);
    begin = std::chrono::steady_clock::now();
    vtkNew<vtkShrinkWrapFilter> wrap;
    wrap->SetTimeMode(vtkShrinkWrapFilter::TIME_EVOLUTION_STEPS);
    wrap->SetInputData(target);
    wrap->Update();
    freshSeconds += seconds(begin);
    fresh[k] = vtkSmartPointer<vtkPolyData>::New();
    fresh[k]->DeepCopy(wrap->GetOutput());
    freshComputing += computing(fresh[k]);
  }
  std::cout << "\n### " << series.name << " (" << series.frames << " frames)\n\n"
            << "| frame | vertices | mean w->t / t->w % | largest w->t / t->w % | over fresh: mean "
               "w->t / t->w, largest w->t / t->w | closed, crossings | TrackId kept | motion "
               "error | status |\n|---|---|---|---|---|---|---|---|---|\n";
  double worstMean = 0, worstLargest = 0, keptSum = 0, errorSum = 0;
  int keptFrames = 0, bad = 0;
  for (int k = 0; k < series.frames; ++k)
  {
    FrameFigures f;
    f.followed = testing::evaluateWrap(soupOf(followed[k]), targets[k], samples);
    f.fresh = testing::evaluateWrap(soupOf(fresh[k]), targets[k], samples);
    f.status = statusOf(followed[k]);
    auto* ids = vtkIdTypeArray::SafeDownCast(followed[k]->GetPointData()->GetArray("TrackId"));
    vtkDataArray* d = followed[k]->GetPointData()->GetArray("Displacement");
    vtkDataArray* normals = followed[k]->GetPointData()->GetArray("Normals");
    if (k > 0 && ids)
    {
      auto* before =
        vtkIdTypeArray::SafeDownCast(followed[k - 1]->GetPointData()->GetArray("TrackId"));
      std::set<vtkIdType> was;
      for (vtkIdType i = 0; before && i < before->GetNumberOfTuples(); ++i)
      {
        was.insert(before->GetValue(i));
      }
      int kept = 0;
      for (vtkIdType i = 0; i < ids->GetNumberOfTuples(); ++i)
      {
        kept += was.count(ids->GetValue(i)) > 0;
      }
      f.kept = double(kept) / std::max<vtkIdType>(ids->GetNumberOfTuples(), 1);
      double error = 0, size = 0;
      for (vtkIdType i = 0; d && normals && i < followed[k]->GetNumberOfPoints(); ++i)
      {
        Vec3 x, dv, n;
        followed[k]->GetPoint(i, x.data());
        d->GetTuple(i, dv.data());
        normals->GetTuple(i, n.data());
        Vec3 truth = series.normalOnly ? series.motion(k, x, n)
                                       : materialMotion(targets[k], targets[k - 1], x);
        if (series.normalOnly)
        {
          dv = dv.dot(n) * n;
        }
        error += (dv - truth).norm();
        size += truth.norm();
      }
      f.motionError = size > 0 ? error / size : 0;
      keptSum += f.kept;
      errorSum += f.motionError;
      ++keptFrames;
    }
    auto ratio = [](double a, double b) { return b > 0 ? a / b : 0.0; };
    const double meanRatio =
      std::max(ratio(f.followed.wrapToTarget.mean, f.fresh.wrapToTarget.mean),
        ratio(f.followed.targetToWrap.mean, f.fresh.targetToWrap.mean));
    const double largestRatio =
      std::max(ratio(f.followed.wrapToTarget.largest, f.fresh.wrapToTarget.largest),
        ratio(f.followed.targetToWrap.largest, f.fresh.targetToWrap.largest));
    worstMean = std::max(worstMean, meanRatio);
    worstLargest = std::max(worstLargest, largestRatio);
    bad += !f.followed.closedManifold || f.followed.selfIntersections > 0;
    std::ostringstream row;
    row << std::setprecision(3) << "| " << k << " | " << f.followed.vertices << " | "
        << f.followed.wrapToTarget.mean << " / " << f.followed.targetToWrap.mean << " | "
        << f.followed.wrapToTarget.largest << " / " << f.followed.targetToWrap.largest << " | "
        << ratio(f.followed.wrapToTarget.mean, f.fresh.wrapToTarget.mean) << " / "
        << ratio(f.followed.targetToWrap.mean, f.fresh.targetToWrap.mean) << ", "
        << ratio(f.followed.wrapToTarget.largest, f.fresh.wrapToTarget.largest) << " / "
        << ratio(f.followed.targetToWrap.largest, f.fresh.targetToWrap.largest) << " | "
        << (f.followed.closedManifold ? "yes" : "NO") << ", " << f.followed.selfIntersections
        << " | " << (k > 0 ? std::to_string(int(std::lround(100 * f.kept))) + "%" : "-") << " | "
        << (k > 0 ? std::to_string(int(std::lround(100 * f.motionError))) + "%" : "-") << " | "
        << f.status << " |";
    std::cout << row.str() << "\n";
  }
  std::cout << std::setprecision(3) << "\n"
            << series.name << ": followed " << followSeconds << " s, fresh " << freshSeconds
            << " s, ratio " << followSeconds / freshSeconds << " (wrapping alone "
            << followComputing << " s against " << freshComputing << " s, ratio "
            << followComputing / freshComputing << ")"
            << "; worst frame over fresh: mean " << worstMean << ", largest " << worstLargest
            << "; frames not closed 2-manifold or crossing: " << bad << "; TrackId kept "
            << 100 * keptSum / std::max(keptFrames, 1) << "% on average, motion error "
            << 100 * errorSum / std::max(keptFrames, 1) << "% on average" << std::endl;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: BenchFollow <CGAL data/meshes folder> [--frames N] [--series "
                 "twist,apart,blobs] [--samples N]\n";
    return 2;
  }
  const std::string folder = argv[1];
  int frames = 20, samples = 100000;
  std::string names = "twist,apart,blobs";
  for (int a = 2; a + 1 < argc; a += 2)
  {
    const std::string flag = argv[a];
    if (flag == "--frames")
    {
      frames = std::max(2, std::atoi(argv[a + 1]));
    }
    else if (flag == "--series")
    {
      names = argv[a + 1];
    }
    else if (flag == "--samples")
    {
      samples = std::atoi(argv[a + 1]);
    }
  }
  std::cout << "BenchFollow: " << frames << " frames a series, " << samples
            << " points sampled on each surface" << std::endl;
  std::stringstream list(names);
  for (std::string name; std::getline(list, name, ',');)
  {
    if (name == "twist")
    {
      run(twistSeries(folder, frames), samples);
    }
    else if (name == "apart")
    {
      run(apartSeries(frames), samples);
    }
    else if (name == "blobs")
    {
      run(blobSeries(frames), samples);
    }
  }
  return 0;
}
