#include "WrapOutput.h"

#include "VTKConversions.h"

#include "Surface/MeshQuality.h"
#include "Surface/SurfaceGeometry.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shrinkwrap
{
namespace convert
{

Status writeWrap(const WrapSession& session, int wanted, double timeStep, double seconds,
  bool finished, vtkPolyData* output, Notes& notes, const MeasureWrap& measure)
{
  const WrapSession::Surface surface = session.surface(wanted);
  SurfaceMesh mesh;
  if (const Status closed = SurfaceMesh::build(surface.points, *surface.cached->triangles, mesh);
      !closed)
  {
    return Status::failure(
      "step " + std::to_string(surface.step) + " is not a closed surface: " + closed.message());
  }
  writeSurface(surface.points, mesh, session.targetSamples(surface),
    surface.cached->tangentialVelocity, output);
  // The wrap must not pass through itself; if it does at this step, the cells say where.
  const SelfIntersections crossings = findSelfIntersections(surface.points, mesh.triangles());
  addSelfIntersections(crossings, output);
  WrapSummary summary = summarize(output, session.plan().sizes(), surface.step, seconds);
  if (measure)
  {
    summary.sampled = measure(TriangleSoup{ surface.points, mesh.triangles() });
  }
  std::optional<double> motion; // of the last step, measured once (WrapSession::meanMotion)
  std::string status = "ok";
  if (session.lastGood() >= 0 && wanted > session.lastGood())
  {
    status = "failed: " + session.failure();
  }
  else if (crossings.pairs > 0)
  {
    status = "self-intersecting: " + std::to_string(crossings.pairs) + " triangle pairs cross";
    warn(notes,
      "The surface of step " + std::to_string(surface.step) + " passes through itself (" +
        std::to_string(crossings.pairs) + " triangle pairs cross; cell array SelfIntersecting)");
  }
  else if (surface.step == session.plan().settings.steps &&
    !landed(summary, motion = session.meanMotion(surface.step)))
  {
    const std::string why = notLanded(summary, motion);
    status = "not landed: " + why;
    if (finished)
    {
      warn(notes,
        "The wrap has not landed on the target after its " + std::to_string(surface.step) +
          " steps: " + why +
          "; raise Number Of Steps, or lower Time Per Step or Advection Speed if it overshoots");
    }
  }
  else if (surface.step == session.plan().settings.steps)
  {
    summary.leftOut = session.leftOut(surface.step);
    if (summary.leftOut.leftOut > 0)
    {
      status = "left out: " + leftOutText(summary.leftOut);
      if (finished)
      {
        warn(notes, leftOutWarning(summary));
      }
    }
  }
  addStepFields(surface.step, surface.step * timeStep, status, output);
  addSummary(summary, output);
  if (finished)
  {
    inform(notes, summary.text());
  }
  return {};
}

bool landed(const WrapSummary& summary, const std::optional<double>& motion)
{
  const double cell = summary.sizes.cell;
  return (motion && *motion < kStillCells) ||
    (summary.vertices > 0 && cell > 0 && summary.distance[1] <= kLandedCells * cell);
}

std::string notLanded(const WrapSummary& summary, const std::optional<double>& motion)
{
  char text[200];
  std::snprintf(text, sizeof text,
    "95%% of its vertices lie within %.3g cells of the target, not within %.3g",
    summary.distance[1] / summary.sizes.cell, kLandedCells);
  std::string why = text;
  if (motion)
  {
    std::snprintf(text, sizeof text, ", and its last step still moved it by %.2g cells", *motion);
    why += text;
  }
  return why;
}

std::string leftOutText(const LeftOutParts& parts)
{
  return std::to_string(parts.leftOut) + " of the target's " + std::to_string(parts.parts) +
    " parts lie wholly outside the wrap";
}

std::string leftOutWarning(const WrapSummary& summary)
{
  char text[400];
  std::snprintf(text, sizeof text,
    "Left out %lld of the target's %lld parts: they lie wholly outside the wrap, more than %.3g "
    "cells of the field (%.3g) from it. A part smaller than about the Target Edge Length (%.3g) "
    "and farther than the Gap Size (%.3g) from the rest cannot be wrapped: lower Target Edge "
    "Length and raise Resolution to wrap such parts, or raise Gap Size to bridge them into one "
    "body",
    summary.leftOut.leftOut, summary.leftOut.parts, WrapSession::kLeftOutCells,
    WrapSession::kLeftOutCells * summary.sizes.cell,
    summary.sizes.edgeLength.value_or(summary.sizes.cell), summary.sizes.gap);
  return text;
}

namespace
{
template <typename Array>
Array* named(Array* array, const char* name, int components, vtkIdType tuples)
{
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

// Per vertex: d, -grad d . N, H (h = -H N), |V_i|, N and v_T.
void addPointArrays(const std::vector<Vec3>& x, const SurfaceMesh& mesh,
  const std::vector<DistanceSample>& samples, const std::vector<Vec3>& tangentialVelocity,
  vtkPolyData* output)
{
  SurfaceGeometry g;
  computeGeometry(mesh, x, g);
  const int nv = static_cast<int>(x.size());
  vtkNew<vtkFloatArray> distance, alignment, curvature, coVolume, normals, tangential;
  named(distance.Get(), "Distance", 1, nv);
  named(alignment.Get(), "AdvectionAlignment", 1, nv);
  named(curvature.Get(), "MeanCurvature", 1, nv);
  named(coVolume.Get(), "CoVolume", 1, nv);
  named(normals.Get(), "Normals", 3, nv);
  named(tangential.Get(), "TangentialVelocity", 3, nv);
  for (int i = 0; i < nv; ++i)
  {
    const DistanceSample& d = samples[i];
    distance->SetValue(i, static_cast<float>(d.value));
    alignment->SetValue(i, static_cast<float>(-d.gradient.dot(g.normal[i])));
    curvature->SetValue(i, static_cast<float>(-g.curvature[i].dot(g.normal[i])));
    coVolume->SetValue(i, static_cast<float>(g.coVolume[i]));
    normals->SetTuple3(i, g.normal[i].x(), g.normal[i].y(), g.normal[i].z());
    const Vec3& v = tangentialVelocity[i];
    tangential->SetTuple3(i, v.x(), v.y(), v.z());
  }
  for (vtkDataArray* a :
    { distance.Get(), alignment.Get(), curvature.Get(), coVolume.Get(), tangential.Get() })
  {
    output->GetPointData()->AddArray(a);
  }
  output->GetPointData()->SetNormals(normals);
  output->GetPointData()->SetActiveScalars("Distance");
}

// Per triangle: the quality measures of MeshQuality.h.
void addCellArrays(const std::vector<Vec3>& x, const SurfaceMesh& mesh, vtkPolyData* output)
{
  const int nt = mesh.triangleCount();
  vtkNew<vtkFloatArray> minAngle, maxAngle, jacobian;
  named(minAngle.Get(), "MinAngle", 1, nt);
  named(maxAngle.Get(), "MaxAngle", 1, nt);
  named(jacobian.Get(), "JacobianCondition", 1, nt);
  for (int t = 0; t < nt; ++t)
  {
    const auto& tri = mesh.triangles()[t];
    const TriangleQuality q = triangleQuality(x[tri[0]], x[tri[1]], x[tri[2]]);
    minAngle->SetValue(t, static_cast<float>(q.minAngle));
    maxAngle->SetValue(t, static_cast<float>(q.maxAngle));
    jacobian->SetValue(t, static_cast<float>(q.jacobianCondition));
  }
  for (vtkDataArray* a : { minAngle.Get(), maxAngle.Get(), jacobian.Get() })
  {
    output->GetCellData()->AddArray(a);
  }
}
} // namespace

void writeSurface(const std::vector<Vec3>& x, const SurfaceMesh& mesh,
  const std::vector<DistanceSample>& samples, const std::vector<Vec3>& tangentialVelocity,
  vtkPolyData* output)
{
  setTriangles(x, mesh.triangles(), output);
  addPointArrays(x, mesh, samples, tangentialVelocity, output);
  addCellArrays(x, mesh, output);
}

void addSelfIntersections(const SelfIntersections& crossings, vtkPolyData* output)
{
  vtkNew<vtkUnsignedCharArray> cells;
  named(cells.Get(), "SelfIntersecting", 1, static_cast<vtkIdType>(crossings.intersecting.size()));
  for (std::size_t t = 0; t < crossings.intersecting.size(); ++t)
  {
    cells->SetValue(static_cast<vtkIdType>(t), crossings.intersecting[t]);
  }
  output->GetCellData()->AddArray(cells);
  vtkNew<vtkIntArray> pairs;
  pairs->SetName("SelfIntersections");
  pairs->InsertNextValue(static_cast<int>(std::min<long long>(crossings.pairs, VTK_INT_MAX)));
  output->GetFieldData()->AddArray(pairs);
}

void addStepFields(int step, double time, const std::string& status, vtkPolyData* output)
{
  vtkNew<vtkIntArray> stepIndex;
  stepIndex->SetName("StepIndex");
  stepIndex->InsertNextValue(step);
  vtkNew<vtkDoubleArray> times;
  times->SetName("Time");
  times->InsertNextValue(time);
  vtkNew<vtkStringArray> statuses;
  statuses->SetName("Status");
  statuses->InsertNextValue(status);
  output->GetFieldData()->AddArray(stepIndex);
  output->GetFieldData()->AddArray(times);
  output->GetFieldData()->AddArray(statuses);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
}

WrapSummary summarize(vtkPolyData* output, const WrapSizes& sizes, int steps, double seconds)
{
  WrapSummary summary;
  summary.sizes = sizes;
  summary.steps = steps;
  summary.seconds = seconds;
  summary.vertices = static_cast<int>(output->GetNumberOfPoints());
  if (vtkDataArray* d = output->GetPointData()->GetArray("Distance");
      d && d->GetNumberOfTuples() > 0)
  {
    std::vector<double> a(d->GetNumberOfTuples());
    for (vtkIdType i = 0; i < d->GetNumberOfTuples(); ++i)
    {
      a[i] = std::abs(d->GetComponent(i, 0));
    }
    std::sort(a.begin(), a.end());
    const double last = static_cast<double>(a.size() - 1);
    summary.distance = { a[static_cast<std::size_t>(0.5 * last)],
      a[static_cast<std::size_t>(0.95 * last)], a.back() };
  }
  if (vtkDataArray* m = output->GetCellData()->GetArray("MinAngle");
      m && m->GetNumberOfTuples() > 0)
  {
    vtkIdType small = 0;
    for (vtkIdType t = 0; t < m->GetNumberOfTuples(); ++t)
    {
      small += m->GetComponent(t, 0) < 20.0;
    }
    summary.smallAngleShare = static_cast<double>(small) / m->GetNumberOfTuples();
  }
  if (vtkDataArray* p = output->GetFieldData()->GetArray("SelfIntersections"))
  {
    summary.selfIntersections = static_cast<long long>(p->GetComponent(0, 0));
  }
  return summary;
}

std::string WrapSummary::text() const
{
  char line[512];
  const double c = this->sizes.cell > 0 ? this->sizes.cell : 1.0;
  char length[64] = "Remeshing off"; // no L is used then
  if (this->sizes.edgeLength)
  {
    std::snprintf(length, sizeof(length), "Target Edge Length %.3g", *this->sizes.edgeLength);
  }
  std::snprintf(line, sizeof(line),
    "%d steps in %.2f s, %d vertices: |distance| to the target median %.3g (%.2g cells), 95%% %.3g "
    "(%.2g cells), "
    "largest %.3g (%.2g cells); %.2f%% of triangles under 20 degrees; closed 2-manifold, %lld "
    "self-intersecting "
    "triangle pairs; Gap Size %.3g, %s, field cell %.3g",
    this->steps, this->seconds, this->vertices, this->distance[0], this->distance[0] / c,
    this->distance[1], this->distance[1] / c, this->distance[2], this->distance[2] / c,
    100 * this->smallAngleShare, this->selfIntersections, this->sizes.gap, length,
    this->sizes.cell);
  std::string text = line;
  if (this->sampled)
  {
    const Closeness& s = *this->sampled;
    std::snprintf(line, sizeof(line),
      "; sampled on both surfaces, wrap to target mean %.3g largest %.3g, target to wrap mean "
      "%.3g largest %.3g",
      s.wrapToTarget.mean, s.wrapToTarget.largest, s.targetToWrap.mean, s.targetToWrap.largest);
    text += line;
  }
  if (this->leftOut.leftOut > 0)
  {
    text += "; " + leftOutText(this->leftOut);
  }
  return text;
}

void addSummary(const WrapSummary& summary, vtkPolyData* output)
{
  vtkFieldData* fields = output->GetFieldData();
  auto add = [&](const char* name, std::vector<double> values) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(static_cast<int>(values.size()));
    a->InsertNextTuple(values.data());
    fields->AddArray(a);
  };
  const std::array<double, 3>& d = summary.distance;
  const double c = summary.sizes.cell > 0 ? summary.sizes.cell : 1.0;
  add("DistancePercentiles", { d[0], d[1], d[2] });
  add("DistancePercentilesInCells", { d[0] / c, d[1] / c, d[2] / c });
  add("FieldCellSize", { summary.sizes.cell });
  add("GapSize", { summary.sizes.gap });
  add("TargetEdgeLength", { summary.sizes.edgeLength.value_or(0) }); // 0: Remeshing off
  add("SmallAngleShare", { summary.smallAngleShare });
  add("ComputeSeconds", { summary.seconds });
  add("LeftOutParts",
    { static_cast<double>(summary.leftOut.leftOut), static_cast<double>(summary.leftOut.parts) });
  if (const std::optional<Closeness>& s = summary.sampled)
  {
    add("SampledDistances",
      { s->wrapToTarget.mean, s->wrapToTarget.largest, s->targetToWrap.mean,
        s->targetToWrap.largest });
  }
  vtkNew<vtkStringArray> text;
  text->SetName("Summary");
  text->InsertNextValue(summary.text());
  fields->AddArray(text);
}

} // namespace convert
} // namespace shrinkwrap
