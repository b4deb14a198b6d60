/**
 * @class   vtkMeshSignedDistance
 * @brief   Signed distance field of a polygon mesh on a regular grid.
 *
 * Computes, at every node of a regular grid, the Euclidean distance to the nearest triangle of the
 * input mesh: negative inside, positive outside. This is Algorithm 1 of "Advection-Driven
 * Shrink-Wrapping of Triangulated Surfaces" (Section 2.1): a triangle soup, an AABB tree split by
 * the surface-area heuristic with adaptive resampling, the octree voxel outline (Algorithm 2),
 * exact distances on a band of nodes around the surface, fast sweeping for the rest, and a flood
 * fill for the sign. Band nodes are signed by angle-weighted pseudonormals.
 *
 * Input: vtkPolyData, any other vtkDataSet with cells (its outer surface, as
 * vtkDataSetSurfaceFilter gives it), or a composite dataset of them (one field of all its meshes).
 * Polygons of any size and triangle strips are triangulated; non-manifold meshes and duplicated
 * points are accepted. Lines and vertices are ignored (with a warning). Coordinates beyond +-1e30
 * are refused: a float field cannot hold their distances. An input without polygons or 3-D cells (a
 * point cloud, vertices, the points of lines) is measured by its points: the unsigned distance to
 * the nearest of them. InputGeometry chooses otherwise for an input that has both (a mesh with
 * loose points, a scan beside a model).
 *
 * Output: vtkImageData with the point array "SignedDistance" (float). Field data: "Signed" (1 when
 * the field is signed, 0 when it is unsigned) and "DistanceStatus" (a sentence saying why). A mesh
 * with holes through which the outside reaches the inside is signed by its generalized winding
 * number (inside where it exceeds 1/2); a sheet that encloses nothing stays unsigned, with a
 * warning.
 * With FieldPerBlock and a composite input: a composite of the same kind with such an image per
 * block.
 *
 * Grid (the paper's Section 4.1): the input bounds are scaled by BoxScale (phi) about their centre,
 * then grown on every side by OffsetFactor times the largest side of the scaled box (the offset o).
 * Resolution is the number of cells along the longest axis of the whole grid ("240^3" in Table 1 is
 * Resolution 240); CellSize > 0 overrides it. Spacing is equal on all axes. Alternatively,
 * UseExplicitGrid takes OutputBounds and OutputDimensions, as Resample To Image does.
 *
 * Under MPI (pvbatch or pvserver on N ranks, one piece per rank), the filter asks for pieces that
 * are slabs of planes and each rank computes only its own, with the other ranks (SlabDistance.h): a
 * rank's memory and time for the field follow its share of the grid (every rank holds the whole
 * mesh), and the field equals the serial field at every node. Pieces of other shapes are computed
 * as even slabs and handed round. Every rank needs the whole input: the filter asks its input for
 * all of it, and an input that arrives distributed all the same (each rank holding a part whatever
 * piece is asked for, as an in-situ adaptor's or a script's source gives it) is gathered, the parts
 * appended on every rank; ranks with different grid settings get an error, not a hang. Every rank
 * of the Controller must update the filter at the same time. Ghost layers are marked (vtkGhostType)
 * when a downstream filter asks for them.
 *
 * Work runs on all cores through vtkSMPTools (a scoped STDThread backend unless the environment
 * variable VTK_SMP_BACKEND_IN_USE chooses one); progress is reported per stage and AbortExecute
 * stops the computation soon, leaving an empty output.
 */
#ifndef vtkMeshSignedDistance_h
#define vtkMeshSignedDistance_h

#include "ShrinkWrapFiltersModule.h" // for export macro
#include "vtkImageAlgorithm.h"
#include "vtkInputGeometry.h" // for InputGeometry's values

#include <memory> // for the gathered input
#include <vector> // for the notes

class vtkCompositeDataSet;
class vtkFloatArray;
class vtkMultiProcessController;
namespace shrinkwrap
{
namespace convert
{
struct PropertyInfo;
struct GatheredInput;
struct MeasuredInput;
}
class Progress;
struct Box;
struct GridLattice;
struct Note;
struct TriangleSoup;
struct SignedDistanceResult;
struct SignedDistanceSettings;
class SlabExchange;
class Status;
}

class SHRINKWRAPFILTERS_EXPORT vtkMeshSignedDistance : public vtkImageAlgorithm
{
public:
  static vtkMeshSignedDistance* New();
  vtkTypeMacro(vtkMeshSignedDistance, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  /// Every property as the panel shows it (name, label, unit, range): what the panel's XML must
  /// say.
  static std::vector<shrinkwrap::convert::PropertyInfo> DescribeProperties();

  enum SweepMethods
  {
    CLOSEST_POINT = 0, ///< propagate closest surface points (default; more exact at the same speed)
    EIKONAL = 1        ///< the paper's fast sweeping of |grad d| = 1 (Zhao 2005)
  };

  ///@{
  /**
   * What of the input the distances are measured to: AUTOMATIC (default), POLYGONS, POINTS or
   * POLYGONS_AND_POINTS (vtkInputGeometry). A field from points is unsigned: points have no inside.
   */
  vtkSetMacro(InputGeometry, int);
  vtkGetMacro(InputGeometry, int);
  ///@}

  ///@{
  /**
   * phi: factor by which the input bounds are scaled about their centre. Default 1.1 (paper 4.1).
   */
  vtkSetMacro(BoxScale, double);
  vtkGetMacro(BoxScale, double);
  ///@}

  ///@{
  /**
   * The offset o as a multiple of the largest side of the scaled box, added on every side.
   * Default 0.15: the box is 1.43 times the object, the cells are spent on it, and a Shrink Wrap
   * reusing the field has room for its offset start. The paper's o (4.1: o = max side) is 1.0, a
   * box 3.3 times the object, which an icosphere start needs.
   */
  vtkSetMacro(OffsetFactor, double);
  vtkGetMacro(OffsetFactor, double);
  ///@}

  ///@{
  /**
   * Number of cells along the longest axis of the output grid. Default 120.
   */
  vtkSetMacro(Resolution, int);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * Cell size h; when positive it overrides Resolution. Default 0.
   */
  vtkSetMacro(CellSize, double);
  vtkGetMacro(CellSize, double);
  ///@}

  ///@{
  /**
   * Use OutputBounds and OutputDimensions instead of the grid placed around the input. Default off.
   */
  vtkSetMacro(UseExplicitGrid, bool);
  vtkGetMacro(UseExplicitGrid, bool);
  vtkBooleanMacro(UseExplicitGrid, bool);
  vtkSetVector6Macro(OutputBounds, double);
  vtkGetVector6Macro(OutputBounds, double);
  vtkSetVector3Macro(OutputDimensions, int);
  vtkGetVector3Macro(OutputDimensions, int);
  ///@}

  /**
   * The cell size h of the grid as placed for the current input and settings, in the input's units
   * (0 when there is no grid); known once the pipeline's information is updated. Shown in the panel
   * (Grid Cell Size).
   */
  vtkGetMacro(GridCellSize, double);

  ///@{
  /**
   * How the far field is filled: CLOSEST_POINT (default) or EIKONAL (the paper's scheme).
   */
  vtkSetMacro(SweepMethod, int);
  vtkGetMacro(SweepMethod, int);
  ///@}

  ///@{
  /**
   * Extra layers of nodes with exact distances around the nodes of the cells the surface touches.
   * Default 1.
   */
  vtkSetMacro(BandLayers, int);
  vtkGetMacro(BandLayers, int);
  ///@}

  ///@{
  /**
   * Compute the sign (flood fill). When off, the field is the unsigned distance. Default on.
   */
  vtkSetMacro(ComputeSign, bool);
  vtkGetMacro(ComputeSign, bool);
  vtkBooleanMacro(ComputeSign, bool);
  ///@}

  ///@{
  /**
   * For a composite input (multiblock, partitioned): off (default), one field of all its blocks
   * together; on, a field per block, each on a grid placed around its block (or the explicit grid),
   * in a composite of the input's shape. Under MPI the blocks' fields are shared out among the
   * ranks (each computed whole on one rank, by the nodes of its grid), or computed where the blocks
   * are when the composite arrives distributed.
   */
  vtkSetMacro(FieldPerBlock, bool);
  vtkGetMacro(FieldPerBlock, bool);
  vtkBooleanMacro(FieldPerBlock, bool);
  ///@}

  ///@{
  /**
   * The MPI ranks that compute the field together (and gather a distributed input). Default: the
   * global controller (ParaView's MPI engine). Under MPI every rank of it must update the filter at
   * the same time; set none to compute a whole field in one process alone.
   */
  void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkMeshSignedDistance();
  ~vtkMeshSignedDistance() override;
  /// Why a property is outside the panel's range, naming its label and the range; ok when none is.
  shrinkwrap::Status CheckProperties() const;

  // The pipeline's passes (ProcessRequest also makes the output object), then the ports.
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;

  int InputGeometry = vtkInputGeometry::AUTOMATIC;
  // Defaults: the constructor takes them from the core's settings structs, where they are stated
  // once.
  double BoxScale;
  double OffsetFactor;
  int Resolution;
  double CellSize;
  bool UseExplicitGrid = false;
  double OutputBounds[6] = { -1, 1, -1, 1, -1, 1 };
  int OutputDimensions[3] = { 64, 64, 64 };
  int SweepMethod;
  int BandLayers;
  bool ComputeSign;
  double GridCellSize = 0; // of the grid placed in RequestInformation
  bool FieldPerBlock = false;
  vtkMultiProcessController* Controller = nullptr;

private:
  // A distributed input as gathered on this rank (convert::wholeInput).
  std::unique_ptr<shrinkwrap::convert::GatheredInput> Gathered;
  // The output lattice: explicit, or placed around the bounds of the input's surface.
  shrinkwrap::Status ComputeLattice(
    const shrinkwrap::Box& surfaceBounds, shrinkwrap::GridLattice& lattice) const;
  struct FieldSettings; // the core's settings of the field (placement, distances)
  FieldSettings CoreSettings() const;
  template <typename Filter, typename Settings, typename Bind>
  static void BindProperties(Filter& filter, Settings& settings, Bind&& bind);
  // What InputGeometry measures of the input: its triangles (`soup`) and points (`cloud`, points
  // only), either empty when not measured, with the bounds of both; false (reported) if nothing.
  bool ReadInput(vtkDataObject* input, shrinkwrap::TriangleSoup& soup,
    shrinkwrap::TriangleSoup& cloud, shrinkwrap::Box& bounds);
  using Measured = shrinkwrap::convert::MeasuredInput;
  bool Measure(vtkDataObject* input, Measured& measured); // false (reported) if it cannot
  bool ByPieces(vtkInformation* outInfo) const;
  bool Compute(const Measured& measured, int first, int last, vtkFloatArray* values,
    shrinkwrap::SignedDistanceResult& result);
  bool Computed(const shrinkwrap::Status& status, const shrinkwrap::SignedDistanceResult& result);
  shrinkwrap::Progress ProgressOf();
  // The whole field of `input` in this process alone, as `output` (empty when it cannot be
  // computed); false when the run was aborted or ran out of memory.
  bool FieldOf(vtkDataObject* input, vtkImageData* output);
  // FieldPerBlock: a field per block of `input` into `output`.
  void ExecuteBlocks(
    vtkCompositeDataSet* input, vtkInformation* outInfo, vtkCompositeDataSet* output);

  vtkMeshSignedDistance(const vtkMeshSignedDistance&) = delete;
  void operator=(const vtkMeshSignedDistance&) = delete;
};

#endif
