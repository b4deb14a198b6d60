/**
 * @class   vtkShrinkWrapFilter
 * @brief   Wraps a polygon mesh or a point cloud in a watertight triangle surface (time aware).
 *
 * Algorithm 3 of "Advection-Driven Shrink-Wrapping of Triangulated Surfaces": a starting surface
 * evolves by eq. (2), dF/dt = eps(d) Laplace-Beltrami(F) + eta(d) N + v_T, towards the target's
 * distance d, remeshed after every step. Every step is a time step of the output: the filter
 * advertises the times {0, tau, ..., N_t tau} and returns the surface at the time asked (the last
 * one when none is asked); a target with times of its own is followed instead (below). Computed
 * steps are cached: going back is instant, going forward resumes from the newest cached step; a
 * change of an input or a property drops the cache. An aborted run leaves an empty output and its
 * steps cached.
 *
 * Inputs: port 0, the target: polygons, or any dataset with cells (its outer surface), or points
 * (InputGeometry); it may also hold the target's distance field (an image with SignedDistance, as
 * when both are selected as ParaView creates the filter). Port 1 (optional): the DistanceField, an
 * image with the point array "SignedDistance" (Mesh Signed Distance's output). Port 2 (optional):
 * the InitialSurface, a closed triangle surface to start from. A composite target is wrapped block
 * by block (WrapPerBlock), under MPI the blocks shared out among the ranks; a target that arrives
 * distributed is gathered first. Every rank of the Controller must update the filter together.
 *
 * Output: the surface in the target's coordinates, with point data Distance, AdvectionAlignment,
 * MeanCurvature, CoVolume, Normals and TangentialVelocity, cell data MinAngle, MaxAngle,
 * JacobianCondition and SelfIntersecting, and field data StepIndex, Time, Status ("ok", or why not:
 * "failed: ...", "self-intersecting: ...", "not landed: ...", "left out: N of the target's M parts
 * ...") and the run's summary (Summary, DistancePercentiles, FieldCellSize, GapSize,
 * TargetEdgeLength, LeftOutParts, SampledDistances, ...). With PassTargetArrays, the target's own
 * point arrays read at each vertex's closest point on the target (barycentric on its triangle; for
 * points, weighted as the fit that placed the vertex), its cell arrays from the closest cell, and
 * its field data; names the wrap has already get " (target)".
 *
 * Output port 1, the target as measured: the target (a mesh as it is, other data by its outer
 * surface; a composite leaf by leaf) with point array DistanceToWrap (signed: > 0 outside the
 * wrap, < 0 inside), cell array FarFromWrap (the share of the cell farther than the Gap Size
 * from the wrap: what the wrap bridged or cut off) and, at the last step, field data
 * LargestDistanceToWrap (over the whole surface: inside a large triangle it exceeds the largest at
 * the points).
 *
 * Time (TimeMode): a target with time steps is followed by default: the output's times are the
 * target's, frame k's wrap starts from frame k - 1's carried with the target (where its triangles
 * stay the same) and evolves until it lands, and the output gets point arrays TrackId (a vertex
 * keeps its id from frame to frame; a split makes a new one), Displacement (since the previous
 * frame, target units) and Velocity (Displacement over the frames' time difference). A frame the
 * carried wrap cannot follow starts afresh (Status "started afresh: ..."). The frames up to the one
 * asked for are computed in order (the pipeline runs once per frame: CONTINUE_EXECUTING) and
 * cached within Cache Memory; a property change starts the series over.
 *
 * The properties are those of the panel, whose documentation (Plugin/ShrinkWrap.xml) is the
 * reference: the defaults come from the core's settings (Wrap/WrapSettings.h), where they are
 * stated once; CoreSettings() gives them for a wrap through the core alone (Wrap/Wrap.h).
 */
#ifndef vtkShrinkWrapFilter_h
#define vtkShrinkWrapFilter_h

#include "ShrinkWrapFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include "vtkInputGeometry.h" // for InputGeometry's values

#include <functional> // for the measures
#include <memory>     // for the internals
#include <optional>   // for a field's lattice
#include <vector>     // for the inputs

class vtkCompositeDataSet;
class vtkDataSet;
class vtkImageData;
class vtkMultiProcessController;
namespace shrinkwrap
{
namespace convert
{
struct PropertyInfo;
struct GatheredInput;
struct WrapInputs;
class WrapRuns;
}
class DistanceSource;
class TriangleSource;
struct Closeness;
struct GridLattice;
struct TriangleSoup;
struct Note;
class Progress;
class Status;
struct WrapPlan;
struct WrapSettings;
struct WrapSizes;
class WrapSession;
}

class SHRINKWRAPFILTERS_EXPORT vtkShrinkWrapFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkShrinkWrapFilter* New();
  vtkTypeMacro(vtkShrinkWrapFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  /// Every property as the panel shows it (name, label, unit, range): what the panel's XML must
  /// say.
  static std::vector<shrinkwrap::convert::PropertyInfo> DescribeProperties();

  enum Redistributions
  {
    NONE = 0,
    ANGLE = 1,
    VOLUME = 2
  };

  enum StartingShapes
  {
    ICOSPHERE = 0,
    OFFSET_SURFACE = 1
  };

  /// Port 1: an image with "SignedDistance" (optional).
  void SetDistanceFieldConnection(vtkAlgorithmOutput* output)
  {
    this->SetInputConnection(1, output);
  }
  /// Port 2: a closed triangle surface to start from (optional).
  void SetInitialSurfaceConnection(vtkAlgorithmOutput* output)
  {
    this->SetInputConnection(2, output);
  }

  /// What of the target is wrapped (vtkInputGeometry). Default AUTOMATIC.
  vtkSetMacro(InputGeometry, int);
  vtkGetMacro(InputGeometry, int);

  /// The three sizes most wraps set, in the target's units; 0: automatic (Chosen* tell the values).
  /// Target Edge Length: the wrap's triangles' edge length L.
  vtkSetMacro(TargetEdgeLength, double);
  vtkGetMacro(TargetEdgeLength, double);
  /// Gap Size: the narrowest gap or hole that stays open; narrower ones are bridged.
  vtkSetMacro(GapSize, double);
  vtkGetMacro(GapSize, double);
  /// Number Of Steps: evolution steps N_t, at most kMaxSteps. Default 25.
  static constexpr int kMaxSteps = 10000;
  /// The share of the progress a run's setup (its fields and start) reports before its steps.
  static constexpr double kSetupShare = 0.3;
  vtkSetMacro(NumberOfSteps, int);
  vtkGetMacro(NumberOfSteps, int);

  /// Close Holes: an open target's holes closed by its generalized winding number. Default off.
  vtkSetMacro(CloseHoles, bool);
  vtkGetMacro(CloseHoles, bool);
  vtkBooleanMacro(CloseHoles, bool);
  /// Adaptive edge lengths between EdgeLengthRange[0] L and EdgeLengthRange[1] L. Default 1 1.
  vtkSetVector2Macro(EdgeLengthRange, double);
  vtkGetVector2Macro(EdgeLengthRange, double);
  /// Remesh after every step towards L. Default on; off keeps the vertex count (the paper's
  /// scheme).
  vtkSetMacro(Remeshing, bool);
  vtkGetMacro(Remeshing, bool);
  vtkBooleanMacro(Remeshing, bool);
  /// Cells along the longest side of the internal distance field (no DistanceField). Default 80.
  vtkSetMacro(Resolution, int);
  vtkGetMacro(Resolution, int);

  /// The start without an InitialSurface: OFFSET_SURFACE (default; StartOffset cells out, at most
  /// 0.4 Gap Size) or ICOSPHERE (SubdivisionLevel 0-8, default 3).
  vtkSetMacro(StartingShape, int);
  vtkGetMacro(StartingShape, int);
  vtkSetMacro(StartOffsetInCells, double);
  vtkGetMacro(StartOffsetInCells, double);
  vtkSetMacro(SubdivisionLevel, int);
  vtkGetMacro(SubdivisionLevel, int);
  /// Tangential relaxation iterations of a contour or given start. Default 10.
  vtkSetMacro(InitialRelaxation, int);
  vtkGetMacro(InitialRelaxation, int);

  /// Time Per Step: the evolution time a step advances (tau of eq. (5)); step k is at time k tau.
  /// Default 0.015.
  vtkSetMacro(TimePerStep, double);
  vtkGetMacro(TimePerStep, double);
  /// Smoothing C1 and Smoothing Falloff C2 of eps(d) = C1 (1 - exp(-d^2 / C2)), eq. (3). Defaults
  /// 1, 1.
  vtkSetMacro(Smoothing, double);
  vtkGetMacro(Smoothing, double);
  vtkSetMacro(SmoothingFalloff, double);
  vtkGetMacro(SmoothingFalloff, double);
  /// Advection Speed C and Concavity Push D of eta(d) = C d ((-grad d . N) - D sqrt(1 - (grad d .
  /// N)^2)), eq. (4). Defaults 12, 0.5.
  vtkSetMacro(AdvectionSpeed, double);
  vtkGetMacro(AdvectionSpeed, double);
  vtkSetMacro(ConcavityPush, double);
  vtkGetMacro(ConcavityPush, double);
  /// Tangential redistribution (Section 2.3): NONE, ANGLE (default) or VOLUME, with the Angle
  /// Weight omega_angle (0.5), the Volume Weight omega_vol (1), and, with DistanceWeighting (off),
  /// rho(d) = A (1 - exp(-d^2)) of eq. (10), A the Distance Weight Amplitude (1).
  vtkSetMacro(TangentialRedistribution, int);
  vtkGetMacro(TangentialRedistribution, int);
  vtkSetMacro(AngleWeight, double);
  vtkGetMacro(AngleWeight, double);
  vtkSetMacro(VolumeWeight, double);
  vtkGetMacro(VolumeWeight, double);
  vtkSetMacro(DistanceWeighting, bool);
  vtkGetMacro(DistanceWeighting, bool);
  vtkBooleanMacro(DistanceWeighting, bool);
  vtkSetMacro(DistanceWeightAmplitude, double);
  vtkGetMacro(DistanceWeightAmplitude, double);
  /// phi of Section 2.4. Default on.
  vtkSetMacro(AutomaticScaling, bool);
  vtkGetMacro(AutomaticScaling, bool);
  vtkBooleanMacro(AutomaticScaling, bool);
  /// Relative residual of the linear solves. Default 1e-6.
  vtkSetMacro(SolverTolerance, double);
  vtkGetMacro(SolverTolerance, double);

  /// The connectivity edits after each step: flips (within FlipDihedralLimit degrees, default 60)
  /// and collapses of degenerating triangles. Both on by default.
  vtkSetMacro(EdgeFlips, bool);
  vtkGetMacro(EdgeFlips, bool);
  vtkBooleanMacro(EdgeFlips, bool);
  vtkSetMacro(FlipDihedralLimit, double);
  vtkGetMacro(FlipDihedralLimit, double);
  vtkSetMacro(EdgeCollapses, bool);
  vtkGetMacro(EdgeCollapses, bool);
  vtkBooleanMacro(EdgeCollapses, bool);
  /// Keep an open target's rims inside the wrap, and with CreaseAngle below 180 degrees its sharp
  /// creases too. Defaults on, 180.
  vtkSetMacro(CoverRims, bool);
  vtkGetMacro(CoverRims, bool);
  vtkBooleanMacro(CoverRims, bool);
  vtkSetMacro(CreaseAngle, double);
  vtkGetMacro(CreaseAngle, double);
  /// Land the vertices an edge's sagitta off the target so the facets straddle it. Default on.
  vtkSetMacro(FitFacets, bool);
  vtkGetMacro(FitFacets, bool);
  vtkBooleanMacro(FitFacets, bool);

  /// Cache Memory (MiB): memory for cached steps. Default 512.
  vtkSetMacro(CacheMemoryMiB, double);
  vtkGetMacro(CacheMemoryMiB, double);
  /// Wrap each block of a composite target on its own (default on); off, all blocks as one target.
  vtkSetMacro(WrapPerBlock, bool);
  vtkGetMacro(WrapPerBlock, bool);
  vtkBooleanMacro(WrapPerBlock, bool);
  /// Pass Target Arrays: the target's point, cell and field arrays on the wrap (default on).
  /// Switching it keeps the computed steps.
  void SetPassTargetArrays(bool pass);
  vtkGetMacro(PassTargetArrays, bool);
  vtkBooleanMacro(PassTargetArrays, bool);
  /// Time Mode: what the output's times are. Automatic (default): Follow Target Time when the
  /// target has time steps, else Evolution Steps. Evolution Steps: every evolution step is a time
  /// (the target read at one time). Follow Target Time: the target's own times; the wrap of each
  /// frame starts from the previous frame's, carried with the target's motion, and evolves until
  /// it lands; a time asked for gives the frame at or before it (the first before the first).
  enum TimeModes
  {
    TIME_AUTOMATIC = 0,
    TIME_EVOLUTION_STEPS = 1,
    TIME_FOLLOW_TARGET = 2
  };
  vtkSetMacro(TimeMode, int);
  vtkGetMacro(TimeMode, int);
  /// 1 when the output follows the target's times (Time Mode, as the last information pass found).
  vtkGetMacro(FollowsTarget, int);
  /// The MPI ranks that share a composite's blocks and gather a distributed target. Default: the
  /// global controller; set none to wrap in one process alone.
  void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);

  /// The sizes the wrap runs with, in the target's units: the field's cell, and the Gap Size and
  /// Target Edge Length with the automatic ones chosen (0 for L with Remeshing off). Planned when
  /// the pipeline's information is updated, the run's once it ran; 0 before the target is computed
  /// and for a composite wrapped block by block.
  vtkGetMacro(FieldCellSize, double);
  vtkGetMacro(ChosenGapSize, double);
  vtkGetMacro(ChosenEdgeLength, double);
  /// Evolution steps computed since the cache was last dropped (over a composite's blocks).
  int GetNumberOfComputedSteps() const;
  /// 1 when a distance field is connected (port 1, or beside the target on port 0).
  int GetHasDistanceField()
  {
    return this->GetNumberOfInputConnections(1) > 0 || this->GetNumberOfInputConnections(0) > 1;
  }

  /// The properties as the core's settings (Wrap/WrapSettings.h): what the filter wraps with, for a
  /// wrap through the core alone (Wrap/Wrap.h).
  shrinkwrap::WrapSettings CoreSettings() const;

  // An abort is no change of the wrap: unlike vtkAlgorithm's setter it leaves the modification time
  // alone, so the computed steps stay cached and the next request resumes from them.
  void SetAbortExecute(vtkTypeBool abort) override { this->AbortExecute = abort; }

protected:
  vtkShrinkWrapFilter();
  ~vtkShrinkWrapFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int ComputePipelineMTime(vtkInformation* request, vtkInformationVector** inInfoVec,
    vtkInformationVector* outInfoVec, int requestFromOutputPort, vtkMTimeType* mtime) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  void ExecuteBlocks(vtkCompositeDataSet* blocks, vtkInformationVector** inputVector,
    vtkInformation* outInfo, vtkCompositeDataSet* output, vtkDataObject* measured);
  void SetProperties(const shrinkwrap::WrapSettings& settings); // the defaults are stated there
  /// Why a property is outside the panel's range, naming its label and the range; ok when none is.
  shrinkwrap::Status CheckProperties() const;
  template <typename Filter, typename Settings, typename Bind>
  static void BindProperties(Filter& filter, Settings& settings, Bind&& bind);

  int InputGeometry = vtkInputGeometry::AUTOMATIC;
  double TimePerStep;
  int NumberOfSteps;
  int SubdivisionLevel;
  double Smoothing;
  double SmoothingFalloff;
  double AdvectionSpeed;
  double ConcavityPush;
  int TangentialRedistribution;
  double AngleWeight;
  double VolumeWeight;
  double DistanceWeightAmplitude;
  bool DistanceWeighting;
  bool EdgeFlips;
  bool EdgeCollapses;
  bool CoverRims;
  bool FitFacets;
  double CreaseAngle;
  double FlipDihedralLimit;
  int StartingShape;
  double StartOffsetInCells;
  double GapSize;
  bool CloseHoles;
  bool Remeshing;
  double TargetEdgeLength;
  double EdgeLengthRange[2];
  int InitialRelaxation;
  bool AutomaticScaling;
  double SolverTolerance;
  int Resolution;
  double CacheMemoryMiB;
  bool WrapPerBlock = true;
  bool PassTargetArrays = true;
  int TimeMode = TIME_AUTOMATIC;
  vtkMultiProcessController* Controller = nullptr;

private:
  vtkShrinkWrapFilter(const vtkShrinkWrapFilter&) = delete;
  void operator=(const vtkShrinkWrapFilter&) = delete;

  // Set when a run's properties changed while it ran: the next request runs again
  // (ComputePipelineMTime), without touching the MTime that keys the cache.
  bool RunAgain = false;
  vtkTimeStamp RunAgainTime;

  // A followed series (Time Mode): whether the output follows the target's times; in an update,
  // the frame asked of the target now, the one wanted, the first computed by this update (the
  // pipeline runs RequestData once per frame, CONTINUE_EXECUTING); the pipeline's modification
  // time, which keys the frames.
  int FollowsTarget = 0;
  int FrameAsked = -1;
  int FrameWanted = -1;
  int FrameFirst = -1;
  bool FrameStopped = false;      // aborted or failed: the update ends
  bool FrameContinues = false;    // the pipeline runs again for the next frame
  vtkMTimeType FrameLoopTime = 0; // the filter's modification time when the update began
  vtkMTimeType PipelineTime = 0;

  double FieldCellSize = 0; // planned in RequestInformation, the run's in RequestData; as are
  double ChosenGapSize = 0; // these two
  double ChosenEdgeLength = 0;
  // The converted target, the plan, the runs: everything derived from the inputs and properties.
  std::unique_ptr<shrinkwrap::convert::WrapRuns> Runs;
  // A distributed target as gathered on this rank (convert::wholeInput).
  std::unique_ptr<shrinkwrap::convert::GatheredInput> Gathered;

  vtkMTimeType SessionKey(); // the newest modification of the filter and its inputs
  // One surface: of the target, or of all a composite target's blocks together.
  void ExecuteWhole(vtkInformationVector** inputVector, vtkInformation* outInfo,
    vtkPolyData* output, vtkDataObject* measured);
  // `measured`: output port 1's object for this target (a surface, or a composite for one).
  void Execute(unsigned int slot, const shrinkwrap::convert::WrapInputs& inputs,
    vtkInformation* outInfo, vtkPolyData* output, vtkDataObject* measured);
  // Frame FrameAsked of a followed series into `output` and `measured`: from the cache, else
  // wrapped from the frame before (FollowedFrames.h) with TrackId, Displacement and Velocity.
  void ExecuteFrame(unsigned int slot, const shrinkwrap::convert::WrapInputs& inputs,
    vtkPolyData* output, vtkDataObject* measured);
  // Keeps the frames' outputs of `slot` within Cache Memory (MiB).
  void ThinFrames(unsigned int slot);
  // After a frame: the next one asked of the pipeline, or the update's end.
  void NextFrame(vtkInformation* request, vtkInformationVector* outputVector);
  // The target's arrays onto the written wrap, and the target measured against it (port 1).
  // `whole`: the target as one dataset (convert::wholeTarget) when its arrays are to be passed;
  // `last`: the run's last step (its largest distance is measured).
  void CarryAndMeasure(unsigned int slot, vtkDataObject* target, vtkDataObject* whole,
    const shrinkwrap::DistanceSource& wrap, bool last, bool finished, vtkPolyData* output,
    vtkDataObject* measured, std::vector<shrinkwrap::Note>& notes);
  // What writing the wrap measures on it (WrapOutput.h): the wrap as a distance source into `wrap`,
  // and with `closeness` the summary's sampled distances.
  std::function<std::optional<shrinkwrap::Closeness>(const shrinkwrap::TriangleSoup&)> MeasureWrap(
    unsigned int slot, bool closeness, std::unique_ptr<shrinkwrap::TriangleSource>& wrap);
  // The summary's sampled distances of the run's last step (measured once per run).
  shrinkwrap::Closeness LastCloseness(unsigned int slot, const shrinkwrap::TriangleSoup& surface,
    const shrinkwrap::DistanceSource& wrap);
  void ShowSizes(const shrinkwrap::WrapSizes& sizes);
  shrinkwrap::Progress ProgressOf(double begin, double end);
  // progressFrom: where the steps' progress begins (after a setup's, kSetupShare).
  bool Advance(shrinkwrap::WrapSession& session, int step, double progressFrom);
};

#endif
