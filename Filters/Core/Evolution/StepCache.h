// The steps of an evolution kept for going back and forth in time: the evolver's exact state (so a
// restart continues bit for bit), the tangential velocity shown with it, and the triangles, shared
// by consecutive steps without edits. Beyond a memory limit every other step is dropped.
#ifndef ShrinkWrap_StepCache_h
#define ShrinkWrap_StepCache_h

#include "Common/Vec3.h"

#include <array>
#include <map>
#include <memory>
#include <vector>

namespace shrinkwrap
{

class StepCache
{
public:
  using Triangles = std::shared_ptr<const std::vector<std::array<int, 3>>>;
  struct Step
  {
    std::vector<Vec3> state; // the evolver's (scaled coordinates)
    std::vector<Vec3> tangentialVelocity;
    Triangles triangles;
    double scale = 1;    // phi of the state (an edit may recompute it)
    bool edited = false; // the surface after an edit: kept, as no step before it leads to it
  };

  void store(int k, Step step);
  bool has(int k) const { return this->Steps.count(k) > 0; }
  // The cached step at k, else the nearest before it (step 0 is always kept).
  const std::pair<const int, Step>& atOrBefore(int k) const;
  // Drops the steps after k (an edit at k makes them another evolution's).
  void dropAfter(int k);
  // Drops every other step until the cache fits `bytes`, keeping step 0, the newest, `kept` and
  // edited steps. Once the stride passes the newest step only those are left, however little memory
  // is allowed.
  void thin(double bytes, int kept);
  double bytes() const;
  int newest() const { return this->Newest; }

private:
  std::map<int, Step> Steps;
  int Newest = 0;
  int Stride = 1; // cached steps kept: multiples of Stride, and the newest
};

} // namespace shrinkwrap

#endif
