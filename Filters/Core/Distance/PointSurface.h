// The surface a point set samples, for the near field of a wrap onto points (issue #13; TargetDistance.h).
// Near x: the plane fitted to the points around x's nearest point (centroid and covariance, Gaussian
// weights of width h), fitted again about x's foot on it, and over that plane a quadratic height field
// (moving least squares). Driven by the distance to the nearest point, a wrap dimples towards every
// point; driven by this it lands between them on the sampled surface, and averages noise over a
// neighbourhood instead of following it; where noise hides the plane at h, at 2 h or 4 h (over a quarter
// or a sixteenth of the points: a wider fit averages as many points, not more). Where no plane fits, nothing is found and the caller's grid
// decides: no points or no flat neighbourhood around the foot (a part thinner than h), or points on
// one side of it only (a gap's rim), which fades the answer's trust out.
#ifndef ShrinkWrap_PointSurface_h
#define ShrinkWrap_PointSurface_h

#include "PointGrid.h"
#include "PointSource.h"

#include <memory>

namespace shrinkwrap
{

class PointSurface : public DistanceSource
{
public:
  // `width`: h, the weights' width (a small multiple of the points' spacing).
  PointSurface(std::shared_ptr<const PointSource> points, double width);
  Box bounds() const override { return this->Points->bounds(); }
  bool outline(const GridLattice& lattice, const Progress& progress, std::vector<std::int64_t>& cells) const override
  {
    return this->Points->outline(lattice, progress, cells);
  }
  // The surface point under x; side 0 (points have no sides: the caller orients the plane), not sure,
  // and trusted less as the points around it lie to one side.
  SourcePoint closestPoint(const Vec3& x, double maxSquaredDistance) const override;

private:
  struct Plane
  {
    Vec3 centroid;
    Vec3 normal;
  };
  struct Neighbourhood // the points within the cutoff of a centre: offsets from it, weights
  {
    Vec3 centre;
    std::vector<Vec3> offsets;
    std::vector<double> weights;
  };
  struct Scale // a width and the points binned for it: at 2^s h, one point in 4^s (as many per fit)
  {
    Scale(std::vector<Vec3> sample, double w);
    double width;
    std::vector<Vec3> points;
    PointGrid grid; // of `points`
  };
  void gather(const Vec3& centre, const Scale& scale, Neighbourhood& around) const;
  // The plane fitted to a neighbourhood; false where none fits.
  static bool fit(const Neighbourhood& around, Plane& plane);
  // The height over `plane` at `foot` (on it) of the quadric fitted to the neighbourhood (the plane
  // alone cuts through a curved surface: a bias of about h^2 times the curvature).
  static double height(const Neighbourhood& around, const Vec3& foot, const Plane& plane, double width);

  std::shared_ptr<const PointSource> Points;
  std::vector<std::unique_ptr<const Scale>> Scales; // finest first
};

} // namespace shrinkwrap

#endif
