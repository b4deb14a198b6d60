#include "vtkShrinkWrapFilter.h"

#include "AllCores.h"
#include "Evolver.h"
#include "Icosphere.h"
#include "MeshQuality.h"
#include "SignedDistance.h"
#include "StabilityScaling.h"
#include "StartingSurface.h"
#include "vtkMeshSignedDistance.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFlyingEdges3D.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

vtkStandardNewMacro(vtkShrinkWrapFilter);

using namespace shrinkwrap;

namespace
{
Box boundsOf(vtkPolyData* mesh)
{
  Box box;
  double b[6];
  mesh->GetBounds(b);
  if (mesh->GetNumberOfPoints() > 0)
  {
    box.extend(Vec3(b[0], b[2], b[4]));
    box.extend(Vec3(b[1], b[3], b[5]));
  }
  return box;
}

// The SignedDistance array of an image as a DistanceGrid; empty with a message if there is none.
DistanceGrid gridOf(vtkImageData* image, std::string& error)
{
  vtkDataArray* values = image ? image->GetPointData()->GetArray("SignedDistance") : nullptr;
  if (!values || values->GetNumberOfComponents() != 1)
  {
    error = "the distance field has no point array \"SignedDistance\"";
    return {};
  }
  GridLattice lattice;
  int extent[6];
  image->GetExtent(extent);
  image->GetSpacing(lattice.spacing.data());
  image->GetOrigin(lattice.origin.data());
  for (int a = 0; a < 3; ++a)
  {
    lattice.dims[a] = extent[2 * a + 1] - extent[2 * a] + 1;
    lattice.origin[a] += extent[2 * a] * lattice.spacing[a];
  }
  if (lattice.dims[0] < 2 || lattice.dims[1] < 2 || lattice.dims[2] < 2 || !(lattice.spacing.minCoeff() > 0))
  {
    error = "the distance field needs at least 2 nodes and a positive spacing on every axis";
    return {};
  }
  if (values->GetNumberOfTuples() != lattice.nodeCount())
  {
    error = "the distance field's SignedDistance array has " + std::to_string(values->GetNumberOfTuples()) +
      " values for " + std::to_string(lattice.nodeCount()) + " nodes";
    return {};
  }
  std::vector<float> v(values->GetNumberOfTuples());
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    v[i] = static_cast<float>(values->GetTuple1(i));
    if (!std::isfinite(v[i]))
    {
      error = "the distance field has NaN or infinite values (node " + std::to_string(i) + ")";
      return {};
    }
  }
  return DistanceGrid(lattice, std::move(v));
}

// A polydata's triangles as a surface; false if it has other polygons (or none), triangles naming
// points that do not exist, or points that are not finite.
bool trianglesOf(vtkPolyData* mesh, TriangleSurface& surface)
{
  const vtkIdType np = mesh->GetNumberOfPoints();
  surface.points.resize(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    mesh->GetPoint(i, surface.points[i].data());
    if (!surface.points[i].allFinite())
    {
      return false;
    }
  }
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    if (n != 3 || !std::all_of(ids, ids + 3, [np](vtkIdType id) { return id >= 0 && id < np; }))
    {
      return false;
    }
    surface.triangles.push_back({ static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
  }
  return !surface.triangles.empty() && mesh->GetNumberOfStrips() == 0;
}

// Marching cubes of an image's point array at one value.
TriangleSurface contourOf(vtkImageData* image, const char* array, double value)
{
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, array);
  contour->SetValue(0, value);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  TriangleSurface surface;
  trianglesOf(contour->GetOutput(), surface);
  return surface;
}

// The paper's Section 5 start, a contour of d near the target, taken as a morphological closing: the
// target dilated by offset + closing, then eroded by closing. A plain contour nearly touches itself
// where two parts are about twice the offset apart, and the thin necks marching cubes leaves there
// pinch off under curvature at once; the closing fills gaps narrower than 2 (offset + closing). Walls
// of cavities (an unsigned field's contour has them inside an open target) are left out.
bool offsetSurface(vtkImageData* field, const GridLattice& lattice, double offset, double closing,
  TriangleSurface& surface, std::string& error)
{
  const TriangleSurface dilated = contourOf(field, "SignedDistance", offset + closing);
  SurfaceMesh closed;
  if (dilated.triangles.empty() || !SurfaceMesh::build(dilated.points, dilated.triangles, closed, error))
  {
    error = "the contour at Start Offset + Start Closing is empty or reaches the border of the distance "
            "field; lower them, or enlarge the field";
    return false;
  }
  TriangleSoup soup;
  soup.points = dilated.points;
  soup.triangles = dilated.triangles;
  vtkNew<vtkFloatArray> distance;
  distance->SetName("Erosion");
  distance->SetNumberOfTuples(lattice.nodeCount());
  const SignedDistanceResult result =
    computeSignedDistance(soup, lattice, SignedDistanceSettings(), distance->GetPointer(0));
  if (!result.isSigned)
  {
    error = "the distance to the contour at Start Offset + Start Closing has no sign";
    return false;
  }
  vtkNew<vtkImageData> eroded;
  eroded->CopyStructure(field);
  eroded->GetPointData()->AddArray(distance);
  surface = contourOf(eroded, "Erosion", -closing);
  removeCavities(surface);
  if (surface.triangles.empty())
  {
    error = "nothing is left of the offset surface after the closing";
    return false;
  }
  return true;
}

// Outward orientation, which eta N with D > 0 and the output's normals and curvatures rely on.
bool orientOutwards(SurfaceMesh& mesh, std::string& error)
{
  if (enclosedVolume(mesh, mesh.initialPoints()) >= 0)
  {
    return true;
  }
  std::vector<std::array<int, 3>> flipped = mesh.triangles();
  for (auto& t : flipped)
  {
    std::swap(t[1], t[2]);
  }
  const std::vector<Vec3> points = mesh.initialPoints();
  return SurfaceMesh::build(points, flipped, mesh, error);
}
} // namespace

// Everything derived from the inputs and properties: dropped when either changes.
struct vtkShrinkWrapFilter::Session
{
  vtkMTimeType key = 0;
  DistanceGrid field;
  std::unique_ptr<Evolver> evolver;
  using Triangles = std::shared_ptr<const std::vector<std::array<int, 3>>>;
  struct Step
  {
    std::vector<Vec3> state; // the evolver's, exact (scaled coordinates)
    std::vector<Vec3> tangentialVelocity;
    Triangles triangles; // shared by consecutive steps without flips
  };
  Triangles evolverTriangles; // the evolver's current connectivity
  std::map<int, Step> cache;
  int newest = 0;
  int lastGood = -1; // set when a step failed: the last step that did not
  std::string failure;
  int computed = 0;
  int stride = 1; // cached steps kept: multiples of stride, and the newest

  double cacheBytes() const
  {
    std::set<const void*> lists;
    double bytes = 0;
    for (const auto& entry : this->cache)
    {
      bytes += 2.0 * sizeof(Vec3) * entry.second.state.size();
      if (lists.insert(entry.second.triangles.get()).second)
      {
        bytes += sizeof(std::array<int, 3>) * entry.second.triangles->size();
      }
    }
    return bytes;
  }
};

vtkShrinkWrapFilter::vtkShrinkWrapFilter()
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(1);
}

vtkShrinkWrapFilter::~vtkShrinkWrapFilter() = default;

int vtkShrinkWrapFilter::GetNumberOfComputedSteps() const
{
  return this->Current ? this->Current->computed : 0;
}

int vtkShrinkWrapFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 1 ? "vtkImageData" : "vtkPolyData");
  if (port > 0)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkShrinkWrapFilter::ComputePipelineMTime(vtkInformation* request, vtkInformationVector** inInfoVec,
  vtkInformationVector* outInfoVec, int requestFromOutputPort, vtkMTimeType* mtime)
{
  const int result =
    this->Superclass::ComputePipelineMTime(request, inInfoVec, outInfoVec, requestFromOutputPort, mtime);
  if (this->RunAgain)
  {
    this->RunAgainTime.Modified();
    this->RunAgain = false;
  }
  *mtime = std::max(*mtime, this->RunAgainTime.GetMTime());
  return result;
}

int vtkShrinkWrapFilter::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Every evolution step is a time step of the output.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int n = this->NumberOfSteps; // clamped by its setter: at most kMaxSteps
  const double tau = this->TimeStep > 0 ? this->TimeStep : 1.0;
  std::vector<double> times(n + 1);
  for (int k = 0; k <= n; ++k)
  {
    times[k] = k * tau;
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), n + 1);
  const double range[2] = { 0.0, n * tau };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int vtkShrinkWrapFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The whole target, field and starting surface, whatever time is asked of the output.
  for (int port = 0; port < 3; ++port)
  {
    for (int c = 0; c < inputVector[port]->GetNumberOfInformationObjects(); ++c)
    {
      vtkInformation* info = inputVector[port]->GetInformationObject(c);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
      info->Remove(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    }
  }
  return 1;
}

bool vtkShrinkWrapFilter::StartSession(vtkInformationVector** inputVector)
{
  vtkPolyData* target = vtkPolyData::GetData(inputVector[0], 0);
  vtkImageData* fieldImage = vtkImageData::GetData(inputVector[1], 0);
  vtkPolyData* initial = vtkPolyData::GetData(inputVector[2], 0);
  auto session = std::make_unique<Session>();
  if (!(this->TimeStep > 0) || !std::isfinite(this->TimeStep))
  {
    vtkErrorMacro("TimeStep (tau) must be positive.");
    return false;
  }
  if (this->SubdivisionLevel < 0 || this->SubdivisionLevel > 8)
  {
    vtkErrorMacro("SubdivisionLevel must be between 0 and 8.");
    return false;
  }
  if (!target || target->GetNumberOfPolys() + target->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("The target has no polygons to wrap.");
    return false;
  }
  const Box targetBox = boundsOf(target);
  if (!targetBox.min.allFinite() || !targetBox.max.allFinite())
  {
    vtkErrorMacro("The target has NaN or infinite coordinates.");
    return false;
  }

  // The distance field: the DistanceField input, or computed here with the same algorithm.
  std::string error;
  vtkSmartPointer<vtkImageData> image = fieldImage;
  if (!fieldImage)
  {
    vtkNew<vtkMeshSignedDistance> sdf;
    vtkNew<vtkPolyData> copy;
    copy->ShallowCopy(target);
    sdf->SetInputData(copy);
    sdf->SetResolution(this->Resolution);
    sdf->Update();
    image = sdf->GetOutput();
  }
  session->field = gridOf(image, error);
  if (session->field.empty())
  {
    vtkErrorMacro("Cannot wrap: " << (fieldImage ? error
      : "the target's distance field could not be computed (see the message above)") << ".");
    return false;
  }

  // The starting surface: the InitialSurface, the offset surface or the icosphere; outward oriented.
  TriangleSurface start;
  const double h = session->field.lattice().spacing.maxCoeff();
  if (initial && !trianglesOf(initial, start))
  {
    vtkErrorMacro("The InitialSurface must be made of triangles only, with finite points and valid point ids.");
    return false;
  }
  if (!initial && this->StartingShape == OFFSET_SURFACE &&
    !offsetSurface(image, session->field.lattice(), this->StartOffset * h, this->StartClosing * h, start, error))
  {
    vtkErrorMacro("Cannot start from the offset surface: " << error << ".");
    return false;
  }
  if (!initial && this->StartingShape == ICOSPHERE)
  {
    start = icosphere(this->SubdivisionLevel, targetBox.center(), 0.5 * 1.05 * targetBox.diagonal());
  }
  // Specks smaller than two cells are noise the field cannot hold (curvature shrinks them away).
  if (const int specks = removeSpecks(start, 2 * h))
  {
    vtkWarningMacro("Left out " << specks << " piece(s) of the starting surface smaller than two cells "
                                "of the distance field.");
  }
  SurfaceMesh mesh;
  if (!SurfaceMesh::build(start.points, start.triangles, mesh, error) || !orientOutwards(mesh, error))
  {
    vtkErrorMacro("The starting surface cannot evolve: " << error << ".");
    return false;
  }
  // A contour's slivers would fail the first step (the icosphere needs no relaxation).
  if (this->StartingShape != ICOSPHERE || initial)
  {
    RelaxSettings relax;
    relax.iterations = this->InitialRelaxation;
    relax.flips.maxDihedral = this->FlipDihedralLimit * M_PI / 180.0;
    SurfaceMesh relaxed;
    if (!relaxTangentially(mesh, relax, relaxed, error))
    {
      vtkErrorMacro("Relaxing the starting surface failed: " << error << ".");
      return false;
    }
    mesh = std::move(relaxed);
    start.points = mesh.initialPoints();
  }
  const Box domain = session->field.lattice().bounds();
  for (const Vec3& p : start.points)
  {
    if (domain.squaredDistance(p) > 0)
    {
      vtkErrorMacro("The distance field does not contain the starting surface; enlarge the field "
                    "(Offset Factor of Mesh Signed Distance) or start from a smaller surface.");
      return false;
    }
  }

  // Section 2.4: scale so that the mean co-volume of the sphere inscribed in the target's box is tau.
  const Vec3 size = targetBox.size();
  const double radius = 0.5 * std::max(size.minCoeff(), 1e-3 * size.maxCoeff());
  const double phi = this->AutomaticScaling
    ? stabilityScale(this->TimeStep, radius, static_cast<long long>(mesh.vertexCount()))
    : 1.0;

  EvolverSettings settings;
  settings.timeStep = this->TimeStep;
  settings.C1 = this->C1;
  settings.C2 = this->C2;
  settings.C = this->C;
  settings.D = this->D;
  settings.redistribution = this->TangentialRedistribution == VOLUME
    ? Redistribution::Volume
    : (this->TangentialRedistribution == ANGLE ? Redistribution::Angle : Redistribution::None);
  settings.omegaAngle = this->OmegaAngle;
  settings.omegaVolume = this->OmegaVolume;
  settings.rhoA = this->RhoA;
  settings.distanceWeight = this->DistanceWeighting;
  settings.edgeFlips = this->EdgeFlips;
  settings.edgeCollapses = this->EdgeCollapses;
  settings.flips.maxDihedral = this->FlipDihedralLimit * M_PI / 180.0;
  settings.solverTolerance = this->SolverTolerance;
  session->evolver =
    std::make_unique<Evolver>(mesh, settings, &session->field, domain, phi, targetBox.center());
  if (!session->evolver->error().empty())
  {
    vtkErrorMacro("Cannot wrap: " << session->evolver->error() << ".");
    return false;
  }
  session->evolverTriangles = std::make_shared<const std::vector<std::array<int, 3>>>(mesh.triangles());
  session->cache[0] = { session->evolver->state(), std::vector<Vec3>(start.points.size(), Vec3::Zero()),
    session->evolverTriangles };
  this->Current = std::move(session);
  return true;
}

int vtkShrinkWrapFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  output->Initialize();
  try // memory can run out below any estimate (a process limit, a job's cap)
  {
    this->Execute(inputVector, outInfo, output);
  }
  catch (const std::bad_alloc&)
  {
    output->Initialize();
    this->Current.reset(); // a half-made step is not kept; the next update starts over
    vtkErrorMacro("Out of memory: lower Subdivision Level, Resolution or Cache Memory Limit.");
  }
  catch (const std::exception& e) // e.g. threads that cannot start under the same limits
  {
    output->Initialize();
    this->Current.reset();
    vtkErrorMacro("Shrink Wrap failed: " << e.what() << ".");
  }
  return 1;
}

void vtkShrinkWrapFilter::Execute(vtkInformationVector** inputVector, vtkInformation* outInfo, vtkPolyData* output)
{
  // One surface, not split: under MPI, piece 0 holds it and the other pieces are empty.
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
  {
    return;
  }

  // Any change of an input or a property starts a new session (and drops the cache).
  auto sessionKey = [this] {
    vtkMTimeType key = this->GetMTime();
    for (int port = 0; port < 3; ++port)
    {
      if (vtkDataObject* data = this->GetInputDataObject(port, 0))
      {
        key = std::max(key, data->GetMTime());
      }
    }
    return key;
  };
  const vtkMTimeType key = sessionKey();
  if (!this->Current || this->Current->key != key)
  {
    this->Current.reset();
    bool started = false;
    onAllCores([&] { started = this->StartSession(inputVector); });
    if (!started)
    {
      return;
    }
    this->Current->key = key;
  }
  Session& s = *this->Current;

  // The step asked for: the requested time snapped to a step (clamped to the steps there are, before
  // rounding: a time far past the end is the last step), else the last step; NaN asks for no time.
  const int last = this->NumberOfSteps;
  if (last == 0)
  {
    vtkWarningMacro("NumberOfSteps is 0: showing the starting surface.");
  }
  int wanted = last;
  const double asked = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()) / this->TimeStep
    : std::nan("");
  if (!std::isnan(asked))
  {
    wanted = asked <= 0 ? 0 : (asked >= last ? last : static_cast<int>(std::lround(asked)));
  }
  const int shown = s.lastGood >= 0 ? std::min(wanted, s.lastGood) : wanted;

  // Compute what is missing, from the nearest cached step before it.
  if (!s.cache.count(shown))
  {
    auto base = std::prev(s.cache.upper_bound(shown));
    if (s.evolver->steps() != base->first)
    {
      // Cached triangles were the evolver's own, so they always form a closed surface again.
      const bool reconnect = base->second.triangles != s.evolverTriangles;
      if (s.evolver->restart(base->second.state, reconnect ? base->second.triangles.get() : nullptr, base->first) &&
        reconnect)
      {
        s.evolverTriangles = base->second.triangles;
      }
    }
    const int first = base->first;
    bool aborted = false;
    onAllCores([&] {
      for (int k = first + 1; k <= shown; ++k)
      {
        const StepReport report = s.evolver->step();
        ++s.computed;
        if (!report.ok())
        {
          s.lastGood = k - 1;
          s.failure = report.message;
          break;
        }
        if (report.flips > 0 || report.collapses > 0)
        {
          s.evolverTriangles =
            std::make_shared<const std::vector<std::array<int, 3>>>(s.evolver->mesh().triangles());
        }
        s.cache[k] = { s.evolver->state(), s.evolver->tangentialVelocity(), s.evolverTriangles };
        s.newest = std::max(s.newest, k);
        this->UpdateProgress(static_cast<double>(k - first) / (shown - first));
        if (this->GetAbortExecute())
        {
          aborted = true;
          break;
        }
      }
    });
    // An abort ends this run: the empty output stands until a property, an input or the time asked
    // for changes (then the run resumes from the cache, or starts over).
    if (aborted)
    {
      this->AbortExecute = 0; // honoured; a set flag would stop every later run at its first step
      vtkWarningMacro("Shrink Wrap was aborted; the output is empty (computed steps stay cached).");
      return;
    }
    if (s.lastGood >= 0)
    {
      vtkWarningMacro("The evolution failed: " << s.failure << "; later times show step " << s.lastGood << ".");
    }
    // Keep the cache under its memory limit: drop every other step, keeping step 0, the newest and the
    // one asked for. Once the stride passes the newest step only those three are left, however little
    // memory is allowed.
    while (s.stride <= s.newest && s.cacheBytes() > this->CacheMemoryLimit * 1024 * 1024)
    {
      s.stride *= 2;
      for (auto it = s.cache.begin(); it != s.cache.end();)
      {
        const bool kept = it->first % s.stride == 0 || it->first == s.newest || it->first == shown;
        it = kept ? std::next(it) : s.cache.erase(it);
      }
    }
  }
  const int step = s.lastGood >= 0 ? std::min(wanted, s.lastGood) : wanted;
  const auto found = s.cache.find(step) != s.cache.end() ? s.cache.find(step) : std::prev(s.cache.upper_bound(step));
  const Session::Step& entry = found->second;

  // The surface and its arrays.
  const std::vector<Vec3> x = s.evolver->positionsOf(entry.state);
  const int nv = static_cast<int>(x.size());
  SurfaceMesh mesh;
  std::string error;
  if (!SurfaceMesh::build(x, *entry.triangles, mesh, error))
  {
    vtkErrorMacro("Internal error: step " << found->first << " is not a closed surface: " << error << ".");
    return;
  }
  SurfaceGeometry g;
  computeGeometry(mesh, x, g);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nv);
  auto named = [](auto array, const char* name, int components, vtkIdType tuples) {
    array->SetName(name);
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(tuples);
    return array;
  };
  vtkNew<vtkFloatArray> distance, alignment, curvature, coVolume, normals, tangential;
  named(distance.Get(), "Distance", 1, nv);
  named(alignment.Get(), "AdvectionAlignment", 1, nv);
  named(curvature.Get(), "MeanCurvature", 1, nv);
  named(coVolume.Get(), "CoVolume", 1, nv);
  named(normals.Get(), "Normals", 3, nv);
  named(tangential.Get(), "TangentialVelocity", 3, nv);
  for (int i = 0; i < nv; ++i)
  {
    points->SetPoint(i, x[i].data());
    const DistanceSample d = s.field.sample(x[i]);
    distance->SetValue(i, static_cast<float>(d.value));
    alignment->SetValue(i, static_cast<float>(-d.gradient.dot(g.normal[i])));
    curvature->SetValue(i, static_cast<float>(-g.curvature[i].dot(g.normal[i]))); // h = -H N
    coVolume->SetValue(i, static_cast<float>(g.coVolume[i]));
    normals->SetTuple3(i, g.normal[i].x(), g.normal[i].y(), g.normal[i].z());
    const Vec3& v = entry.tangentialVelocity[i];
    tangential->SetTuple3(i, v.x(), v.y(), v.z());
  }
  const int nt = mesh.triangleCount();
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkFloatArray> minAngle, maxAngle, jacobian;
  named(minAngle.Get(), "MinAngle", 1, nt);
  named(maxAngle.Get(), "MaxAngle", 1, nt);
  named(jacobian.Get(), "JacobianCondition", 1, nt);
  for (int t = 0; t < nt; ++t)
  {
    const auto& tri = mesh.triangles()[t];
    const vtkIdType ids[3] = { tri[0], tri[1], tri[2] };
    triangles->InsertNextCell(3, ids);
    const TriangleQuality q = triangleQuality(x[tri[0]], x[tri[1]], x[tri[2]]);
    minAngle->SetValue(t, static_cast<float>(q.minAngle));
    maxAngle->SetValue(t, static_cast<float>(q.maxAngle));
    jacobian->SetValue(t, static_cast<float>(q.jacobianCondition));
  }
  output->SetPoints(points);
  output->SetPolys(triangles);
  for (vtkDataArray* a : { distance.Get(), alignment.Get(), curvature.Get(), coVolume.Get(), tangential.Get() })
  {
    output->GetPointData()->AddArray(a);
  }
  output->GetPointData()->SetNormals(normals);
  output->GetPointData()->SetActiveScalars("Distance");
  for (vtkDataArray* a : { minAngle.Get(), maxAngle.Get(), jacobian.Get() })
  {
    output->GetCellData()->AddArray(a);
  }

  vtkNew<vtkIntArray> stepIndex;
  stepIndex->SetName("StepIndex");
  stepIndex->InsertNextValue(found->first);
  vtkNew<vtkDoubleArray> time;
  time->SetName("Time");
  time->InsertNextValue(found->first * this->TimeStep);
  vtkNew<vtkStringArray> status;
  status->SetName("Status");
  status->InsertNextValue(s.lastGood >= 0 && wanted > s.lastGood ? "failed: " + s.failure : std::string("ok"));
  output->GetFieldData()->AddArray(stepIndex);
  output->GetFieldData()->AddArray(time);
  output->GetFieldData()->AddArray(status);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), found->first * this->TimeStep);
  // The pipeline takes an execution as up to date even when a property changed while it ran (a panel
  // edit, a script's callback): RunAgain makes the next request run again, with the new values.
  if (sessionKey() != key)
  {
    this->RunAgain = true;
    vtkWarningMacro("Properties or inputs changed during the run; they apply from the next update.");
  }
}

void vtkShrinkWrapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TimeStep: " << this->TimeStep << "\n";
  os << indent << "NumberOfSteps: " << this->NumberOfSteps << "\n";
  os << indent << "SubdivisionLevel: " << this->SubdivisionLevel << "\n";
  os << indent << "C1: " << this->C1 << "\n";
  os << indent << "C2: " << this->C2 << "\n";
  os << indent << "C: " << this->C << "\n";
  os << indent << "D: " << this->D << "\n";
  os << indent << "TangentialRedistribution: " << this->TangentialRedistribution << "\n";
  os << indent << "OmegaAngle: " << this->OmegaAngle << "\n";
  os << indent << "OmegaVolume: " << this->OmegaVolume << "\n";
  os << indent << "RhoA: " << this->RhoA << "\n";
  os << indent << "DistanceWeighting: " << this->DistanceWeighting << "\n";
  os << indent << "EdgeFlips: " << this->EdgeFlips << "\n";
  os << indent << "EdgeCollapses: " << this->EdgeCollapses << "\n";
  os << indent << "FlipDihedralLimit: " << this->FlipDihedralLimit << "\n";
  os << indent << "StartingShape: " << (this->StartingShape == ICOSPHERE ? "Icosphere" : "Offset Surface") << "\n";
  os << indent << "StartOffset: " << this->StartOffset << "\n";
  os << indent << "StartClosing: " << this->StartClosing << "\n";
  os << indent << "InitialRelaxation: " << this->InitialRelaxation << "\n";
  os << indent << "AutomaticScaling: " << this->AutomaticScaling << "\n";
  os << indent << "SolverTolerance: " << this->SolverTolerance << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "CacheMemoryLimit: " << this->CacheMemoryLimit << " MiB\n";
}
