// One shrink-wrap run (Algorithm 3) as a session the filter keeps while its inputs and properties
// stay: the fields, the evolver, and the cache of computed steps. Asking for a step computes what
// is missing from the nearest cached step before it.
#ifndef ShrinkWrap_WrapSession_h
#define ShrinkWrap_WrapSession_h

#include "Evolution/Evolver.h"
#include "Evolution/StepCache.h"
#include "Wrap/LeftOut.h"
#include "Wrap/WrapFields.h"
#include "Wrap/WrapPlan.h"

#include <map>
#include <memory>
#include <optional>
#include <string>

namespace shrinkwrap
{

class WrapSession
{
public:
  // `start` ready to evolve (startingSurface()). The plan's target box centres the scaled
  // coordinates and, without remeshing, sizes phi (Section 2.4: the mean co-volume of the sphere
  // inscribed in the target's box is tau).
  static Status create(WrapFields fields, const WrapPlan& plan, const SurfaceMesh& start,
    std::unique_ptr<WrapSession>& session);

  // The step shown for a wanted one: after a failure, the last good step at most.
  int shown(int wanted) const
  {
    return this->LastGood >= 0 ? std::min(wanted, this->LastGood) : wanted;
  }
  // Computes the missing steps up to shown(k); false when progress asked to stop (the steps
  // computed stay cached).
  bool advanceTo(int k, const Progress& progress = {});
  // The surface of step k (or the nearest cached one before it) in the caller's units.
  struct Surface
  {
    int step = 0;
    std::vector<Vec3> points;
    const StepCache::Step* cached = nullptr;
  };
  Surface surface(int k) const;
  // The target's field (WrapFields::target) at the points of `surface`: d and grad d, what the
  // output shows; measured once per step.
  const std::vector<DistanceSample>& targetSamples(const Surface& surface) const;
  // The run is over (its last step computed, or a step failed) with every step cached: the session
  // then releases the evolver and the fields (after measuring every step's samples and what it left
  // out), where the target's triangles outnumber the cached vertices, so that a large target's
  // tree does not outlive its use. Its steps are still shown; edit() and evolver() then fail.
  bool released() const { return !this->Evolving; }
  // Keeps the evolver after the last step (a followed frame reads its mesh's vertex properties).
  void keepEvolver() { this->KeepEvolver = true; }
  // How far step k moved the surface from step k - 1, on average along its normals (the change of
  // the enclosed volume over the area), in cells of the field; none unless both steps are cached.
  std::optional<double> meanMotion(int k) const;
  // The target's parts that the surface of step k (or the nearest cached one before it) leaves out
  // (LeftOut.h), farther than kLeftOutCells cells of the field from it; measured once per surface.
  static constexpr double kLeftOutCells = 2;
  LeftOutParts leftOut(int k) const;

  // Edits the evolver's current surface (Evolver::edit); phi follows the new vertex count when the
  // settings scale automatically, the current step is cached anew and later ones are dropped.
  Status edit(const std::function<void(SurfaceMesh&)>& change);

  const WrapFields& fields() const { return this->Fields; }
  const WrapPlan& plan() const { return this->Plan; }
  const Evolver& evolver() const { return *this->Evolving; } // not after released()
  int computedSteps() const { return this->Computed; }
  int lastGood() const { return this->LastGood; }
  const std::string& failure() const { return this->Failure; }

private:
  WrapSession() = default;
  double scaleFor(int vertexCount) const;
  void cacheCurrent(bool connectivityChanged, bool edited = false);
  void releaseIfOver();
  const TriangleSoup* targetTriangles() const; // of the target's field (none: points, released)

  WrapPlan Plan;
  EvolverSettings Evolution; // the plan's
  WrapFields Fields;
  double Radius = 1; // of the sphere inscribed in the target's box
  Vec3 Center;       // of the scaled coordinates
  std::unique_ptr<Evolver> Evolving;
  StepCache Cache;
  StepCache::Triangles EvolverTriangles; // the evolver's current connectivity
  int LastGood = -1;                     // set when a step failed: the last step that did not
  std::string Failure;
  int Computed = 0;
  bool Stopped = false; // a step was stopped midway: the evolver restarts from the cache
  bool KeepEvolver = false;
  struct LeftOutOf
  {
    const StepCache::Step* surface = nullptr;
    LeftOutParts parts;
  };
  mutable LeftOutOf LastLeftOut; // leftOut() of the surface it was measured on
  mutable std::map<int, std::vector<DistanceSample>> Samples; // targetSamples() by step
};

} // namespace shrinkwrap

#endif
