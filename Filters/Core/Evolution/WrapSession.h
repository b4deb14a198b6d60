// One shrink-wrap run (Algorithm 3) as a session the filter keeps while its inputs and properties
// stay: the target's distance field, the evolver, and the cache of computed steps. Asking for a step
// computes what is missing from the nearest cached step before it.
#ifndef ShrinkWrap_WrapSession_h
#define ShrinkWrap_WrapSession_h

#include "Evolver.h"
#include "StartingSurface.h"
#include "StepCache.h"

#include <memory>
#include <string>

namespace shrinkwrap
{

// Every setting of a wrap, with Shrink Wrap's defaults: the one place they are stated (the filter's
// properties start from them).
struct WrapSettings
{
  EvolverSettings evolution;
  StartSettings start;
  int steps = 200;              // N_t
  bool automaticScaling = true; // phi of Section 2.4
  int resolution = 120;         // cells along the longest axis of the distance field computed here
  double cacheMiB = 512;        // memory for cached steps

  Status validate() const;
};

class WrapSession
{
public:
  // `start` ready to evolve (startingSurface()); `targetBox` sizes phi (Section 2.4: the mean
  // co-volume of the sphere inscribed in the target's box is tau) and centres the scaled coordinates.
  static Status create(DistanceGrid field, const Box& targetBox, const SurfaceMesh& start,
    const WrapSettings& settings, std::unique_ptr<WrapSession>& session);

  // The step shown for a wanted one: after a failure, the last good step at most.
  int shown(int wanted) const { return this->LastGood >= 0 ? std::min(wanted, this->LastGood) : wanted; }
  // Computes the missing steps up to shown(k); false when progress asked to stop (the steps computed
  // stay cached).
  bool advanceTo(int k, const Progress& progress = {});
  // The surface of step k (or the nearest cached one before it) in the caller's units.
  struct Surface
  {
    int step = 0;
    std::vector<Vec3> points;
    const StepCache::Step* cached = nullptr;
  };
  Surface surface(int k) const;

  // Edits the evolver's current surface (Evolver::edit); phi follows the new vertex count when the
  // settings scale automatically, the current step is cached anew and later ones are dropped.
  Status edit(const std::function<void(SurfaceMesh&)>& change);

  const DistanceGrid& field() const { return this->Field; }
  const Evolver& evolver() const { return *this->Evolution; }
  int computedSteps() const { return this->Computed; }
  int lastGood() const { return this->LastGood; }
  const std::string& failure() const { return this->Failure; }

private:
  WrapSession() = default;
  double scaleFor(int vertexCount) const;
  void cacheCurrent(bool connectivityChanged, bool edited = false);

  WrapSettings Settings;
  DistanceGrid Field;
  double Radius = 1; // of the sphere inscribed in the target's box
  std::unique_ptr<Evolver> Evolution;
  StepCache Cache;
  StepCache::Triangles EvolverTriangles; // the evolver's current connectivity
  int LastGood = -1; // set when a step failed: the last step that did not
  std::string Failure;
  int Computed = 0;
};

} // namespace shrinkwrap

#endif
