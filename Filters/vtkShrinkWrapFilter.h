/**
 * @class   vtkShrinkWrapFilter
 * @brief   Wraps a polygon mesh in a watertight triangle surface by Lagrangian evolution (time aware).
 *
 * Algorithm 3 of "Advection-Driven Shrink-Wrapping of Triangulated Surfaces": a starting surface
 * evolves by eq. (2), dF/dt = eps(d) Laplace-Beltrami(F) + eta(d) N + v_T, towards the target's signed
 * distance d. Every time step is a time step of the output: the filter advertises the times
 * {0, tau, ..., N_t tau} and returns the surface at the requested time (the last one when no time is
 * requested or the time is past the end). Computed steps are cached: going back is instant, going
 * forward resumes from the newest cached step; changing an input or a property drops the cache. A run
 * whose properties changed while it ran runs again at the next request. An aborted run leaves an empty
 * output and its steps cached; it does not run again by itself, and a request for another time
 * resumes from the cache.
 *
 * Inputs: port 0, the target (vtkPolyData with polygons, or any vtkDataSet with cells, wrapped by its
 * outer surface as vtkDataSetSurfaceFilter gives it; without polygons or 3-D cells, or with
 * InputGeometry POINTS, its points are wrapped: a scan, sampled points, vertices, issue #13; with
 * POLYGONS_AND_POINTS, both); it may also hold the target's distance field (an
 * image with SignedDistance, as when both are selected as the filter is created in ParaView), which
 * then counts as port 1's. Port 1 (optional), "DistanceField": a
 * vtkImageData with a point array "SignedDistance", e.g. from Mesh Signed Distance; otherwise one is
 * computed with Resolution. Port 2 (optional), "InitialSurface": a closed 2-manifold triangle surface to
 * start from (e.g. a contour of the distance field), first relaxed tangentially for InitialRelaxation
 * iterations; otherwise the StartingShape: a geodesic icosphere of SubdivisionLevel around the target,
 * or an offset surface of the target (the paper's Section 5).
 *
 * Output: the surface in the target's coordinates. Point data: Distance (d), AdvectionAlignment
 * (-grad d . N), MeanCurvature (H, positive where convex), CoVolume (|V_i|), Normals, and
 * TangentialVelocity (v_T of the step that produced the surface). Cell data: MinAngle, MaxAngle (degrees)
 * and JacobianCondition (Knupp). Field data: StepIndex, Time and Status ("ok", or the failure and its
 * step; later times then show the last good surface), and a run summary from these arrays: Summary (one
 * line, also sent to the output window at the end of a run), DistancePercentiles and
 * DistancePercentilesInCells (median, 95th percentile and largest |Distance| at the vertices),
 * FieldCellSize, GapSize and TargetEdgeLength (as used, automatic ones resolved), SmallAngleShare
 * (triangles with MinAngle under 20 degrees), SelfIntersections and ComputeSeconds. Under MPI the
 * surface is piece 0; other pieces are empty.
 *
 * A composite target (multiblock, partitioned) is wrapped block by block, each block as if alone, with
 * a session and a step cache of its own (time moves every block; CacheMemoryLimit applies per block);
 * the output is a composite of the same shape with a surface per block. Its blocks take no
 * DistanceField or InitialSurface (each is computed from its block). Under MPI, each block is wrapped
 * on one piece and left empty on the others, the blocks shared out by their expected cost (area over
 * the Target Edge Length squared, largest first to the least loaded piece): the ranks wrap the blocks
 * in parallel. A composite that arrives distributed (each rank holding some blocks) is wrapped where
 * its blocks are. WrapBlocksTogether wraps all blocks as one target instead (output: one surface).
 *
 * Under MPI a target that arrives distributed (each rank holding a part whatever piece is asked for,
 * as an in-situ adaptor's or a script's source gives it) is gathered first, the parts appended on
 * every rank. Every rank of the Controller must update the filter at the same time.
 *
 * Parameters (paper symbols; defaults of Fig. 11 where it gives them): TimeStep tau = 0.015,
 * NumberOfSteps N_t = 25 (Fig. 11: 200), SubdivisionLevel s = 3, C1 = 1 and C2 = 1 (eq. (3)), C = 12 and
 * D = 0.5 (eq. (4); Fig. 11: 1 and 0), FitFacets on (the paper: off, the vertices on the target), TangentialRedistribution (None, Angle = default, Volume), OmegaAngle = 0.5, OmegaVolume = 1,
 * DistanceWeighting off (rho(d) of eq. (10)) with RhoA = 1 (its A), EdgeFlips on with FlipDihedralLimit
 * 60 degrees (flips change the triangles from step to step, never the vertices), EdgeCollapses on
 * (a collapse removes a vertex), CoverRims on with CreaseAngle 180 degrees (rims only), StartingShape
 * OFFSET_SURFACE with StartOffset 3 cells (or ICOSPHERE), GapSize automatic (diagonal / 50), CloseHoles off, Remeshing
 * on with TargetEdgeLength automatic (diagonal / 50), InitialRelaxation 10,
 * AutomaticScaling on (phi of Section 2.4: the evolution runs in coordinates scaled so that the mean
 * co-volume of the sphere inscribed in the target's box is tau), SolverTolerance 1e-6, Resolution 80
 * (of the internal distance field), CacheMemoryLimit 512 MiB.
 */
#ifndef vtkShrinkWrapFilter_h
#define vtkShrinkWrapFilter_h

#include "ShrinkWrapFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include "vtkInputGeometry.h" // for InputGeometry's values

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
struct GatheredInput;
struct WrapInputs;
class WrapRuns;
}
struct GridLattice;
struct Note;
class Progress;
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
  void SetDistanceFieldConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  /// Port 2: a closed triangle surface to start from (optional).
  void SetInitialSurfaceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(2, output); }

  ///@{
  /// What of the target is wrapped: AUTOMATIC (default), POLYGONS, POINTS or POLYGONS_AND_POINTS
  /// (vtkInputGeometry). POINTS wraps a mesh whose polygons are not to be trusted (a scanner's
  /// triangles) as a cloud; POLYGONS_AND_POINTS wraps a model and a scan (its vertices) together, the
  /// automatic sizes following the points' spacing.
  vtkSetClampMacro(
    InputGeometry, int, vtkInputGeometry::AUTOMATIC, vtkInputGeometry::POLYGONS_AND_POINTS);
  vtkGetMacro(InputGeometry, int);
  ///@}

  ///@{
  /// tau, the time step. Default 0.015.
  vtkSetMacro(TimeStep, double);
  vtkGetMacro(TimeStep, double);
  ///@}
  ///@{
  /// N_t, the number of time steps. Default 25 (the paper's Fig. 11: 200 from an icosphere), which
  /// land the default offset start on the target. At most kMaxSteps: far more than the paper's
  /// 200-600, and 10,001 frames are still an animation a timeline can hold.
  static constexpr int kMaxSteps = 10000;
  vtkSetClampMacro(NumberOfSteps, int, 0, kMaxSteps);
  vtkGetMacro(NumberOfSteps, int);
  ///@}
  ///@{
  /// s, the subdivision level of the starting icosphere. Default 3 (642 vertices).
  vtkSetMacro(SubdivisionLevel, int);
  vtkGetMacro(SubdivisionLevel, int);
  ///@}
  ///@{
  /// C1 and C2 of eps(d) = C1 (1 - exp(-d^2 / C2)), eq. (3). Defaults 1 and 1; C2 = 0 gives eps = C1.
  vtkSetMacro(C1, double);
  vtkGetMacro(C1, double);
  vtkSetMacro(C2, double);
  vtkGetMacro(C2, double);
  ///@}
  ///@{
  /// C and D of eta(d) = C d ((-grad d . N) - D sqrt(1 - (grad d . N)^2)), eq. (4). Defaults 1 and 0.
  vtkSetMacro(C, double);
  vtkGetMacro(C, double);
  vtkSetMacro(D, double);
  vtkGetMacro(D, double);
  ///@}
  ///@{
  /// Tangential redistribution: NONE, ANGLE (default) or VOLUME, with omega_angle (0.5), omega_vol (1)
  /// and A of rho(d) = A (1 - exp(-d^2)), eq. (10) (1).
  vtkSetClampMacro(TangentialRedistribution, int, NONE, VOLUME);
  vtkGetMacro(TangentialRedistribution, int);
  vtkSetMacro(OmegaAngle, double);
  vtkGetMacro(OmegaAngle, double);
  vtkSetMacro(OmegaVolume, double);
  vtkGetMacro(OmegaVolume, double);
  vtkSetMacro(RhoA, double);
  vtkGetMacro(RhoA, double);
  ///@}
  ///@{
  /// Weight omega_angle by rho(d) of eq. (10). Default off: rho vanishes on the target, where angles
  /// matter most, and with edge flips the full weight is stable.
  vtkSetMacro(DistanceWeighting, bool);
  vtkGetMacro(DistanceWeighting, bool);
  vtkBooleanMacro(DistanceWeighting, bool);
  ///@}
  ///@{
  /// Flip edges after each step where that raises the smallest angle of the two triangles (the
  /// connectivity adjustment of the paper's Section 5; the vertices stay). Default on.
  vtkSetMacro(EdgeFlips, bool);
  vtkGetMacro(EdgeFlips, bool);
  vtkBooleanMacro(EdgeFlips, bool);
  ///@}
  ///@{
  /// Collapse the shortest edge of a triangle whose smallest angle falls below about 6 degrees (where
  /// flips cannot help: the surface is compressed, e.g. sinking into a pocket). A collapse removes a
  /// vertex, so the vertex count may drop from step to step. Default on.
  vtkSetMacro(EdgeCollapses, bool);
  vtkGetMacro(EdgeCollapses, bool);
  vtkBooleanMacro(EdgeCollapses, bool);
  ///@}
  ///@{
  /// Land the vertices off the target by their edges' sagitta, outside where the wrap is convex and
  /// inside where it is concave (a quarter of a vertex's height over its neighbours' centroid), so
  /// that the triangles between them straddle the target instead of cutting inside its convex parts
  /// and bulging out of its concave ones. A landing is at most an eighth of the vertex's edges, and
  /// none where a vertex holds a rim (Cover Rims) or without Remeshing (irregular rings). The mean
  /// distances both ways fall by up to a third on CGAL meshes and their points (RESULTS.md,
  /// 2026-11-29); the Distance array then shows that sagitta at the vertices. Default on; off, the
  /// vertices land on the target (the paper's eq. (4)).
  vtkSetMacro(FitFacets, bool);
  vtkGetMacro(FitFacets, bool);
  vtkBooleanMacro(FitFacets, bool);
  ///@}
  ///@{
  /// Keep the rims of an open target (a hole's edge, an open sheet's edge, a fin) inside the wrap: after
  /// each step, rim points outside the surface pull the nearest triangle onto them. The wrap folds
  /// around such a rim, and without this the fold creeps back along the sheet (nothing in eq. (4) pulls
  /// it out), so the rim pokes out. On points, the rims are the points whose neighbours lie to one
  /// side (a sheet's edge, a thin part's tip), taken on the plane fitted through them (so noisy points
  /// have rims too). Needs Remeshing and the exact near field; a closed target has no rims. Default on.
  vtkSetMacro(CoverRims, bool);
  vtkGetMacro(CoverRims, bool);
  vtkBooleanMacro(CoverRims, bool);
  ///@}
  ///@{
  /// With CoverRims, the target's sharp creases count as rims too: edges where its faces turn by more
  /// than this angle (degrees) pull the wrap onto them, so that it keeps a CAD part's edges and corners
  /// instead of cutting them. Default 180 (none): on the fandisk 45 brings the mean distance from the
  /// target from 0.042% to 0.028% of the diagonal, with 6% more vertices (Testing/Benchmarks/RESULTS.md).
  vtkSetClampMacro(CreaseAngle, double, 0.0, 180.0);
  vtkGetMacro(CreaseAngle, double);
  ///@}
  ///@{
  /// The largest angle (degrees) between the normals of two triangles whose edge may flip, so that
  /// flips never cut across a ridge. Default 60.
  vtkSetClampMacro(FlipDihedralLimit, double, 0.0, 180.0);
  vtkGetMacro(FlipDihedralLimit, double);
  ///@}
  ///@{
  /// The starting surface when no InitialSurface is connected: OFFSET_SURFACE (default), a contour at
  /// StartOffset cells (default 3, at most 0.4 GapSize and at least one cell) of the field outside the
  /// target closed over gaps narrower than GapSize (the paper's Section 5), which starts close, wraps concave parts and keeps wider holes
  /// open (where that contour joins two parts across a slot the closing keeps, a handle, the highest
  /// lower offset, to half a cell, without the join is taken) (with Remeshing on, coarsened to TargetEdgeLength by collapses that do not make it cross
  /// itself, so the first steps do not carry the contour's fine vertices); or ICOSPHERE, a geodesic icosphere of SubdivisionLevel around the target (the paper's
  /// Algorithm 3 and Fig. 11), which spans concave parts and holes like a membrane.
  vtkSetClampMacro(StartingShape, int, ICOSPHERE, OFFSET_SURFACE);
  vtkGetMacro(StartingShape, int);
  vtkSetClampMacro(StartOffset, double, 0.5, 1000.0);
  vtkGetMacro(StartOffset, double);
  ///@}
  ///@{
  /// The narrowest gap or hole that stays open, in the target's units: narrower ones are bridged (the
  /// wrap moves on the distance to the target's morphological closing by a ball of GapSize / 2).
  /// Default 0: automatic, the target's bounding-box diagonal / 50; for points, 8 median
  /// nearest-neighbour distances (of their sparsest part where their density varies: a scan's far
  /// side) and at least 1.5 cells of the field (for a dense cloud the field is
  /// made finer, see Resolution). A value below half a cell of the distance field bridges nothing.
  /// ChosenGapSize reports the value used.
  vtkSetClampMacro(GapSize, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(GapSize, double);
  ///@}
  ///@{
  /// For a target that is open or crosses itself (its distance field computed here): on, its holes are
  /// closed, inside being where its generalized winding number exceeds 1/2 (a scan with missing
  /// patches); off (default), holes wider than GapSize stay open and the wrap enters them, wrapping
  /// open sheets from both sides.
  vtkSetMacro(CloseHoles, bool);
  vtkGetMacro(CloseHoles, bool);
  vtkBooleanMacro(CloseHoles, bool);
  ///@}
  ///@{
  /// Remeshing after every step towards TargetEdgeLength L (splits above 4/3 L, collapses below 4/5 L,
  /// flips towards valence 6, tangential relaxation), so the vertex count follows the surface and
  /// the triangles stay near equilateral as it moves into concavities and along thin parts; the
  /// stability scale phi (Section 2.4) then follows L. Default on; off keeps the vertex count (the
  /// paper's scheme, with SubdivisionLevel fixing it).
  vtkSetMacro(Remeshing, bool);
  vtkGetMacro(Remeshing, bool);
  vtkBooleanMacro(Remeshing, bool);
  /// L in the target's units. Default 0: automatic, the target's bounding-box diagonal / 50; for
  /// points, 10 median nearest-neighbour distances, between diagonal / 200 and diagonal / 50, or on a
  /// noisy cloud up to 16 times its noise (the RMS height of the points over their fitted surface),
  /// at most diagonal / 30. ChosenTargetEdgeLength reports the value used.
  vtkSetClampMacro(TargetEdgeLength, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(TargetEdgeLength, double);
  /// Adaptive edge length, in units of TargetEdgeLength L: the edges may shorten to
  /// EdgeLengthRange[0] * L where the surface curves (so that a chord stays within 0.12 L of the
  /// surface: sharp edges, corners, tips) and lengthen to EdgeLengthRange[1] * L where it is flat,
  /// with neighbouring lengths graded. Default 1 1: L everywhere. 0.6 1.6 follows sharp features
  /// closer with about as many vertices (RESULTS.md, "Adaptive edge length"). From 0.1 to 1, and from 1
  /// to 4; other values are refused.
  vtkSetVector2Macro(EdgeLengthRange, double);
  vtkGetVector2Macro(EdgeLengthRange, double);
  ///@}
  ///@{
  /// Iterations of tangential relaxation (with edge flips) applied to an InitialSurface or the offset
  /// surface before it evolves: a contour's slivers would otherwise fail the first step. Default 10;
  /// 0 keeps it as given.
  vtkSetClampMacro(InitialRelaxation, int, 0, 1000);
  vtkGetMacro(InitialRelaxation, int);
  ///@}
  ///@{
  /// Scale the evolution for stability (Section 2.4). Default on.
  vtkSetMacro(AutomaticScaling, bool);
  vtkGetMacro(AutomaticScaling, bool);
  vtkBooleanMacro(AutomaticScaling, bool);
  ///@}
  ///@{
  /// Relative residual of the linear solves. Default 1e-6 (positions to about 1e-6 of the scaled size).
  vtkSetMacro(SolverTolerance, double);
  vtkGetMacro(SolverTolerance, double);
  ///@}
  ///@{
  /// Cells along the longest axis of the internal distance field (no DistanceField input). Default 80.
  /// For a point cloud with the automatic GapSize, up to 1.5 times more where 1.5 cells would exceed
  /// 11 median nearest-neighbour distances (about 200,000 points on a CGAL mesh), or, on a clean
  /// cloud, where 8 of them would span under 2.5 cells (the camel's 20,000 points), so that the grid
  /// does not bridge what the points keep apart (FieldCellSize reports the cell used).
  vtkSetMacro(Resolution, int);
  vtkGetMacro(Resolution, int);
  ///@}
  ///@{
  /// Memory for cached steps, in MiB; beyond it every other cached step is dropped. Default 512.
  vtkSetMacro(CacheMemoryLimit, double);
  vtkGetMacro(CacheMemoryLimit, double);
  ///@}

  /// The cell size of the distance field the wrap moves on (its own, as placed for the target and the
  /// settings, or the connected one), in the target's units: planned when the pipeline's information
  /// is updated (0 while the target has not been computed, and for a composite target wrapped block
  /// by block: each block has a field of its own), and the run's once it ran. Shown in the panel
  /// (Field Cell Size).
  vtkGetMacro(FieldCellSize, double);
  /// The Gap Size and the Target Edge Length the wrap runs with: the properties' values, or where they
  /// are 0 the automatic ones (for a point cloud from its spacing), planned and then the run's as
  /// FieldCellSize is; 0 for a composite target wrapped block by block. Shown in the panel (Chosen
  /// Gap Size, Chosen Edge Length; pvpython: ChosenGapSize, ChosenEdgeLength, the run's after
  /// UpdatePropertyInformation()), a start for setting either by hand. The edge length is 0 when
  /// Remeshing is off: no L is used then.
  vtkGetMacro(ChosenGapSize, double);
  vtkGetMacro(ChosenTargetEdgeLength, double);

  ///@{
  /// Wrap a composite target's blocks together, as one target (one surface of all of them, as after
  /// Merge Blocks), instead of each on its own. Default off.
  vtkSetMacro(WrapBlocksTogether, bool);
  vtkGetMacro(WrapBlocksTogether, bool);
  vtkBooleanMacro(WrapBlocksTogether, bool);
  ///@}

  ///@{
  /// The MPI ranks that share a composite target's blocks and gather a target that arrives
  /// distributed. Default: the global controller (ParaView's MPI engine). Under MPI every rank of it
  /// must update the filter at the same time; set none to wrap in one process alone.
  void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  /// Evolution steps computed since the cache was last dropped (for tests and diagnostics); for a
  /// composite target wrapped block by block, the sum over the blocks wrapped in this process.
  int GetNumberOfComputedSteps() const;
  /// 1 when a distance field is connected (port 1, or beside the target on port 0): the panel then
  /// hides Resolution.
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
  void ExecuteBlocks(vtkCompositeDataSet* blocks, vtkInformationVector** inputVector, vtkInformation* outInfo,
    vtkCompositeDataSet* output);
  void SetProperties(const shrinkwrap::WrapSettings& settings); // the defaults are stated there
  template <typename Filter, typename Settings, typename Bind>
  static void BindProperties(Filter& filter, Settings& settings, Bind&& bind);

  int InputGeometry = vtkInputGeometry::AUTOMATIC;
  double TimeStep;
  int NumberOfSteps;
  int SubdivisionLevel;
  double C1;
  double C2;
  double C;
  double D;
  int TangentialRedistribution;
  double OmegaAngle;
  double OmegaVolume;
  double RhoA;
  bool DistanceWeighting;
  bool EdgeFlips;
  bool EdgeCollapses;
  bool CoverRims;
  bool FitFacets;
  double CreaseAngle;
  double FlipDihedralLimit;
  int StartingShape;
  double StartOffset;
  double GapSize;
  bool CloseHoles;
  bool Remeshing;
  double TargetEdgeLength;
  double EdgeLengthRange[2];
  int InitialRelaxation;
  bool AutomaticScaling;
  double SolverTolerance;
  int Resolution;
  double CacheMemoryLimit;
  bool WrapBlocksTogether = false;
  vtkMultiProcessController* Controller = nullptr;

private:
  vtkShrinkWrapFilter(const vtkShrinkWrapFilter&) = delete;
  void operator=(const vtkShrinkWrapFilter&) = delete;

  // Set when a run's properties changed while it ran: the next request runs again
  // (ComputePipelineMTime), without touching the MTime that keys the cache.
  bool RunAgain = false;
  vtkTimeStamp RunAgainTime;
  double FieldCellSize = 0; // planned in RequestInformation, the run's in RequestData; as are
  double ChosenGapSize = 0; // these two
  double ChosenTargetEdgeLength = 0;
  // The converted target, the plan, the runs: everything derived from the inputs and properties.
  std::unique_ptr<shrinkwrap::convert::WrapRuns> Runs;
  // A distributed target as gathered on this rank (convert::wholeInput).
  std::unique_ptr<shrinkwrap::convert::GatheredInput> Gathered;

  vtkMTimeType SessionKey(); // the newest modification of the filter and its inputs
  // One surface: of the target, or of all a composite target's blocks together.
  void ExecuteWhole(vtkInformationVector** inputVector, vtkInformation* outInfo, vtkPolyData* output);
  void Execute(unsigned int slot, const shrinkwrap::convert::WrapInputs& inputs,
    vtkInformation* outInfo, vtkPolyData* output);
  void ShowSizes(const shrinkwrap::WrapSizes& sizes);
  shrinkwrap::Progress ProgressOf(double begin, double end);
  bool Advance(shrinkwrap::WrapSession& session, int step);
};

#endif
