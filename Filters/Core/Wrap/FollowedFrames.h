// A wrap that follows a target through time: frame k's wrap starts from frame k - 1's, carried with
// the target's own motion where its triangles correspond (the same triangles on points that moved)
// and projected onto the frame's target, and evolves until it lands; the first frame, and a frame
// the carried wrap cannot follow, start as a single wrap does. Every vertex keeps a track id from
// frame to frame (a split makes a new one, a collapse keeps the survivor's), and the place it was
// carried from, so that its displacement since the previous frame is its own motion plus the
// remeshing's slide along the surface.
#ifndef ShrinkWrap_FollowedFrames_h
#define ShrinkWrap_FollowedFrames_h

#include "Common/Notes.h"
#include "Common/Progress.h"
#include "Common/Status.h"
#include "Common/TriangleSoup.h"
#include "Distance/ContourTopology.h"
#include "Surface/SurfaceMesh.h"
#include "Wrap/WrapPlan.h"
#include "Wrap/WrapSession.h"

#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace shrinkwrap
{

// A vertex's track across frames; -1 until numbered (numberTracks).
struct TrackId
{
  std::int64_t id = -1;
};
// The track of a vertex made by a split between a and b: a new one.
inline TrackId between(const TrackId&, const TrackId&, double)
{
  return {};
}

// The property names on a followed wrap's mesh: its track, and where it stood at the previous
// frame (target units).
inline const char* const kTrackProperty = "v:track";
inline const char* const kOriginProperty = "v:origin";

// The wrap of one frame as the next one takes it.
struct FollowedWrap
{
  SurfaceMesh mesh; // target units, with kTrackProperty and kOriginProperty
  std::shared_ptr<const TriangleSoup> target; // the frame's triangles (none: points)
  // The same triangles as the frame's session measured them (null: not kept): its tree finds the
  // wrap's feet on them when the next frame carries it.
  std::shared_ptr<const TriangleSource> measured;
  std::int64_t nextTrack = 0; // the first id not yet given
  // Per vertex: how far it moved since the previous frame (from where it was carried from; zero
  // on a frame started afresh), target units.
  std::vector<Vec3> displacement;
};

// Which frame of a followed series the pipeline asks the target for, so that the frame wanted is
// computed after every frame before it, in order. Frames are the target's times; a time asked
// for gives the frame at or before it, as ParaView's readers do (the first before the first).
class FrameSchedule
{
public:
  // A series of `times` (ascending); the frames done so far are forgotten when they change (then
  // true).
  bool follow(const std::vector<double>& times);
  const std::vector<double>& times() const { return this->Times; }
  int frameAt(double time) const; // NaN: the last
  // The frame to compute (or give from the cache) next on the way to `wanted`: itself when done,
  // else the one after the newest done before it, else the first (the series starts over).
  int next(int wanted) const;
  bool done(int frame) const { return this->Done.count(frame) > 0; }
  // Frame `frame` computed; a frame that is not the one after the newest starts the series over.
  void markDone(int frame);
  void forget(int frame) { this->Done.erase(frame); } // its output dropped (memory)
  void clear();

private:
  std::vector<double> Times;
  std::set<int> Done;
  int Newest = -1; // the frame whose wrap the next one starts from
};

struct FollowSettings
{
  // A carried start takes no step when 95% of its vertices lie this near the target, in cells of
  // the field (a fresh wrap's lie within about 0.05).
  double carriedCells = 0.1;
  // Newton steps x -= d grad d that bring the carried start onto the frame's target first.
  int projections = 2;
  // ... and the carry kept its edges within this ratio of their lengths.
  double stretch = 1.2;
  // A carried wrap that lands with a vertex farther than this from the target closed over its
  // gaps, in cells, does not fit the frame (parts came apart, a hole opened): the frame starts
  // afresh.
  double fitCells = 1.5;
  // A carried frame's steps end, after at least minSteps and at most the wrap's Number Of Steps,
  // when a step moved the surface less than stillCells cells on average (WrapSession::meanMotion)
  // and every vertex lies within landedCells cells of the target closed over its gaps, or the
  // farthest came no nearer than `stall` times its distance.
  double stillCells = 0.02;
  double landedCells = 0.5;
  double stall = 0.95;
  int minSteps = 6;
};

// How a frame was wrapped.
struct FrameReport
{
  bool carried = false; // from the previous frame's wrap (false: started as a single wrap)
  int steps = 0;        // evolution steps of this frame
  std::string fresh;    // why a frame after the first started as a single wrap, if it did
};

// Moves `points` (near `before`) with the target from `before` to `after`, which must have the
// same triangles on the same number of points: each point keeps the barycentric place of its
// closest point on its triangle, and its offset along that triangle's normal. False (nothing
// moved) when the two do not correspond. `measured`, if given, is `before` as a distance source
// (else one is made of it).
bool carryWithTarget(const TriangleSoup& before, const TriangleSoup& after,
  std::vector<Vec3>& points, const TriangleSource* measured = nullptr);

// The session of frame `target` (planned as `plan`): started from `previous` carried when there is
// one and it fits the field, else as startWrap does. Then advanced: a carried start until it lands,
// a fresh one through the plan's steps.
Status wrapFrame(const WrapTarget& target, const WrapPlan& plan, const FollowedWrap* previous,
  const FollowSettings& follow, const Contour& contour, const Progress& progress, Notes& notes,
  std::unique_ptr<WrapSession>& session, FrameReport& report);

// The wrap of the session's last computed step as the next frame takes it: tracks kept from the
// session's mesh (new vertices numbered from `nextTrack`), origins at the points.
FollowedWrap followedWrap(const WrapSession& session, int step,
  std::shared_ptr<const TriangleSoup> target, std::int64_t nextTrack);

} // namespace shrinkwrap

#endif
