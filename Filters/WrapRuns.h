// What Shrink Wrap keeps between its pipeline's requests: its target as the core takes it, the plan
// made for it, and the runs that compute the wrap's steps (one for a whole target, one per block of
// a composite wrapped block by block). Each is kept while the inputs and properties stay as they
// were (a key: their newest modification time).
#ifndef ShrinkWrap_WrapRuns_h
#define ShrinkWrap_WrapRuns_h

#include "Common/Notes.h"
#include "Common/Status.h"
#include "TargetData.h"
#include "Wrap/Closeness.h"
#include "Wrap/FollowedFrames.h"
#include "Wrap/WrapPlan.h"
#include "Wrap/WrapSession.h"

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkDataSet;
class vtkInformationVector;
class vtkImageData;
class vtkInformation;
class vtkPolyData;

namespace shrinkwrap
{
namespace convert
{

// A wrap's inputs as the pipeline gives them.
struct WrapInputs
{
  vtkDataObject* target = nullptr; // a dataset, or a composite wrapped as its blocks appended
  vtkImageData* field = nullptr;   // a distance field given beside it (optional)
  vtkPolyData* start = nullptr;    // a surface to start from (optional)
};

// The wrap's inputs on the filter's ports. Port 0 may hold the target and its distance field
// together (ParaView connects both there when both are selected as Shrink Wrap is created): an
// image with a SignedDistance point array is then the field, unless port 1 has one. `fieldLattice`
// is the field's as the pipeline information gives it (RequestInformation comes before the field is
// computed). Failure when port 0 holds more than one target.
Status wrapInputs(
  vtkInformationVector** inputVector, WrapInputs& inputs, std::optional<GridLattice>& fieldLattice);

// The wrap's times: step k at k `timeStep` (0 counts as 1), for `steps` steps, as the output's time
// steps and range; and the step a request asks for: its time snapped to a step (clamped to the
// steps there are before rounding: a time far past the end is the last step), else (no time, NaN)
// the last.
void advertiseSteps(vtkInformation* outInfo, int steps, double timeStep);
int stepAsked(vtkInformation* outInfo, int steps, double timeStep);

// The piece that wraps each block (shareOut), by the wrap's expected vertex count: the block's area
// over L^2 (L as with Remeshing); 1 for a block without polygons (points: no area to go by).
std::vector<int> piecesOfBlocks(
  const std::vector<vtkDataSet*>& targets, int pieces, WrapSettings settings);

class WrapRuns
{
public:
  struct Run
  {
    std::unique_ptr<WrapSession> session;
    vtkMTimeType key = 0;
    double seconds = 0; // computing: fields, start and steps
    // The target as wrapped: its triangles, or its points wrapped alone (cloud); how its data is
    // read on the wrap, made when first needed (TargetData.h); the session's distance to it, held
    // until the last step's closeness is measured (kept in `closeness`).
    std::shared_ptr<const TriangleSoup> polygons;
    std::shared_ptr<const PointCloud> cloud;
    std::unique_ptr<TargetCarrier> carrier;
    std::shared_ptr<const DistanceSource> measuredOn;
    std::optional<Closeness> closeness;
    // A followed series (Time Mode): each frame's wrap as written (without the target's arrays)
    // and its target as measured; the newest frame's wrap, which the next frame starts from; the
    // sizes of the series' first frame, which every frame keeps (the same edges, the same gaps).
    struct Frame
    {
      vtkSmartPointer<vtkPolyData> wrap;
      vtkSmartPointer<vtkDataObject> measured;
    };
    struct Series
    {
      std::map<int, Frame> frames;
      std::optional<FollowedWrap> newest;
      int newestFrame = -1;
      std::optional<WrapSizes> sizes;
    } series;
  };
  // The key of a filter's properties and inputs: its modification time and what its inputs on its
  // first `ports` ports hold (their content: an input that runs again to the same data keeps the
  // runs), read again only where an input's modification time changed.
  vtkMTimeType keyOf(vtkAlgorithm* filter, int ports);

  // The run of a slot: 0 the whole target, 1 + flat index a block of a composite.
  Run& run(unsigned int slot) { return this->Runs[slot]; }
  // Forgets the blocks' runs and shares when `key` is not the one they were made for.
  void keepBlocksFor(vtkMTimeType key);
  void clear();
  int computedSteps() const; // over all runs

  // The plan for `target` as it is, with a field of `field`'s lattice and a given start or not,
  // made once while `key` stays; null when none can be made (`status()` says why). Its target's
  // notes (what of it is wrapped) are in `targetNotes()`.
  const WrapPlan* plan(vtkDataObject* target, const std::optional<GridLattice>& field,
    bool givenStart, vtkMTimeType key, int inputGeometry, const WrapSettings& settings);
  const Status& status() const { return this->Planned.status; }
  // The target as the core takes it (converted once while the data and Input Geometry stay); null
  // when it cannot be wrapped.
  const WrapTarget* converted(vtkDataObject* data, int inputGeometry)
  {
    const ConvertedTarget& c = this->TargetOf(data, inputGeometry);
    return c.status ? &c.target : nullptr;
  }
  const Notes& targetNotes() const { return this->Converted.notes; }

  // Starts `run` on `inputs` (Wrap.h: the plan, then its fields, start and session); false, with
  // `status`, when it cannot ("aborted" when `progress` asked to stop). Notes: what the user
  // should know.
  bool start(Run& run, const WrapInputs& inputs, vtkMTimeType key, int inputGeometry,
    const WrapSettings& settings, const Progress& progress, Notes& notes, Status& status);

  // Wraps frame `frame` of a followed series into `run` (FollowedFrames.h: from the run's newest
  // frame when it is the one before, else afresh); false, with `status`, when it cannot.
  bool startFrame(Run& run, int frame, const WrapInputs& inputs, vtkMTimeType key,
    int inputGeometry, WrapSettings settings, const Progress& progress, Notes& notes,
    Status& status, FrameReport& report);
  // The followed series' frames, and the key of the properties and pipeline they were made with.
  FrameSchedule& frames() { return this->Frames; }
  // Forgets every run's frames when `key` is not the one they were made for.
  void keepFramesFor(vtkMTimeType key);
  // Follows the target's `times`; every run's frames are forgotten when they change.
  void followTimes(const std::vector<double>& times);

  // The piece that wraps each block, as `share()` gives it, made once per key and piece count.
  template <typename Share>
  const std::vector<int>& blockPieces(int pieces, Share&& share)
  {
    if (this->Shares.empty() || this->SharesOf != pieces)
    {
      this->Shares = share();
      this->SharesOf = pieces;
    }
    return this->Shares;
  }

private:
  // The target as the core takes it, converted once while the data and Input Geometry stay.
  struct ConvertedTarget
  {
    const vtkDataObject* data = nullptr;
    vtkMTimeType key = 0; // the data's
    int geometry = 0;
    Status status;
    WrapTarget target;
    Notes notes;
  } Converted;
  const ConvertedTarget& TargetOf(vtkDataObject* data, int inputGeometry);

  struct PlannedWrap
  {
    vtkMTimeType key = 0;
    const vtkDataObject* data = nullptr;
    std::optional<GridLattice> field;
    bool givenStart = false;
    Status status;
    WrapPlan plan;
  } Planned;

  struct InputDigest
  {
    const vtkDataObject* data;
    vtkMTimeType time;
    std::uint64_t digest;
  };
  FrameSchedule Frames;
  vtkMTimeType FramesKey = 0;
  std::vector<InputDigest> Digests;
  std::map<unsigned int, Run> Runs;
  vtkMTimeType BlocksKey = 0;
  std::vector<int> Shares;
  int SharesOf = 0;
};

} // namespace convert
} // namespace shrinkwrap

#endif
