// The surface a point set samples, for the near field of a wrap onto points (TargetDistance.h).
// Near x: the patch of x's nearest point, the plane fitted to the points around it (centroid and
// covariance, Gaussian weights of width h) and over that plane a quadratic height field (moving
// least squares); x's surface point lies on it. A patch depends on its point alone: fitted the
// first time a query lands there and kept (a wrap asks about the same points step after step), so
// answers do not depend on the order or the thread of the queries. Driven by the distance to the
// nearest point, a wrap dimples towards every point; driven by this it lands between them on the
// sampled surface, and averages noise over a neighbourhood instead of following it; where noise
// hides the plane at h, at 2 h or 4 h (over a quarter or a sixteenth of the points: a wider fit
// averages as many points, not more), from the width at which most of the cloud's points look flat
// (finer only where none from it fits). Where no plane fits, nothing is found and the caller's grid
// decides: no points or no flat neighbourhood (a part thinner than h; on a noisy cloud, the points
// x's line of sight meets first speak for it instead), or x's foot beyond the points on one side of
// it (a gap's rim), which fades the answer's trust out.
#ifndef ShrinkWrap_PointSurface_h
#define ShrinkWrap_PointSurface_h

#include "Distance/PointGrid.h"
#include "Distance/PointSource.h"

#include <atomic>
#include <cstdint>
#include <memory>

namespace shrinkwrap
{

class PointSurface : public DistanceSource
{
public:
  // `width`: h, the weights' width (a small multiple of the points' spacing).
  PointSurface(std::shared_ptr<const PointSource> points, double width);
  ~PointSurface() override;
  PointSurface(const PointSurface&) = delete;
  PointSurface& operator=(const PointSurface&) = delete;
  Box bounds() const override { return this->Points->bounds(); }
  bool outline(
    const GridLattice& lattice, const Progress& progress, IndexList& cells) const override
  {
    return this->Points->outline(lattice, progress, cells);
  }
  // The surface point under x; side 0 (points have no sides: the caller orients the plane), not
  // sure, and trusted less as the points around it lie to one side.
  SourcePoint closestPoint(const Vec3& x, double maxSquaredDistance) const override;
  // The points on a rim (a sheet's edge, a thin part's tip) as rim edges of no length, for the wrap
  // to cover (RimCoverage.h): at the finest width where their neighbours look flat (from the one
  // where most of the cloud's points do), these lean to one side beyond an even sample's lean,
  // leave a rim's angular gap, and lie close to their plane; each is given as its foot on that
  // plane (a noisy point's noise left out). Points have no creases: `creaseAngle` is not used.
  std::vector<std::array<Vec3, 2>> rims(double creaseAngle) const override;
  // The input points that the fit under x weighs, at that fit's width (the finest where no plane
  // fits there), centred on x's surface point: those within the fit's cutoff, with its Gaussian
  // weights scaled to sum to 1; how a value given at the points is read at x's surface point.
  void fitWeights(const Vec3& x, std::vector<int>& ids, std::vector<double>& weights) const;
  // The index of the finest width (h, 2 h, 4 h) at which most of the points look flat (measured on
  // one point in 256 when made): above 0, noise hides the plane at h on most of the cloud.
  int typicalFlatScale() const { return this->TypicalScale; }
  // The noise of the points, as the median over that sample of the RMS height of a point's
  // neighbours over the surface fitted around it (at its flat width, weighted as in the fit): about
  // the noise's sigma; on clean points a small fraction of their spacing, curved or not (the
  // quadric takes the curvature).
  double typicalNoise() const { return this->TypicalNoise; }

private:
  static constexpr int kScales = 3; // widths h, 2 h, 4 h
  struct Plane
  {
    Vec3 centroid;
    Vec3 normal;
  };
  struct Patch // the surface fitted around a centre (an input point or a foot)
  {
    Vec3 centre = Vec3::Zero();
    Plane plane;
    Eigen::Matrix<double, 6, 1> quadric =
      Eigen::Matrix<double, 6, 1>::Zero(); // height(u, v), in widths
    double width = 0; // 0: no plane fits at any scale (then plane.centroid is the points' centroid)
    bool surrounded =
      false; // it leans, but its points lie all around its centre (no rim beside it)
  };
  struct Neighbourhood // the points within the cutoff of a centre: offsets from it, weights
  {
    Vec3 centre;
    std::vector<Vec3> offsets;
    std::vector<double> weights;
  };
  struct Scale // a width and the points binned for it: at 2^s h, one point in 4^s (as many per fit)
  {
    Scale(const PointList& sample, double w);
    double width;
    PointGrid grid; // of the sample, by its indices (the finest: all points, by input index)
  };
  void gather(const Vec3& centre, const Scale& scale, Neighbourhood& around) const;
  // The plane fitted to a neighbourhood; false where none fits (plane.centroid, the points'
  // weighted centroid, is set either way).
  static bool fit(const Neighbourhood& around, Plane& plane);
  // The quadric over the patch's plane fitted to the neighbourhood (the plane alone cuts through a
  // curved surface: a bias of about h^2 times the curvature); zero where the points do not pin one.
  static void fitQuadric(const Neighbourhood& around, Patch& patch);
  // Whether the neighbourhood's points, seen from its centre along the patch's plane, leave no
  // angular gap wider than a rim would: a sampling hole, however lopsided, is surrounded; a rim is
  // not.
  static bool surrounds(const Neighbourhood& around, const Patch& patch);
  // The neighbourhood of `centre` at one scale and the patch's plane; false where no plane fits.
  bool fitPlaneAround(
    const Vec3& centre, const Scale& scale, Neighbourhood& around, Patch& patch) const;
  // Whether the patch's points lean to one side of its centre beyond an even sample's lean.
  static bool leans(const Patch& patch);
  // The index of the finest scale, from `from` on and before `to`, at which a plane fits around
  // `centre` (noise thicker than a fraction of the width hides the plane until the width outgrows
  // it), with its neighbourhood and plane; -1 where none does.
  int flatScale(
    const Vec3& centre, Neighbourhood& around, Patch& patch, int from = 0, int to = kScales) const;
  void measureTypical(); // typicalFlatScale() and typicalNoise()
  // The RMS height of the neighbourhood's points over the patch's quadric, weighted as in the fit.
  static double roughness(const Neighbourhood& around, const Patch& patch);
  // The quadric and the surrounded flag of a patch whose plane is fitted to `around`.
  static void finishPatch(const Neighbourhood& around, Patch& patch);
  // The patch around `centre` at one scale; false where no plane fits.
  bool fitAround(const Vec3& centre, const Scale& scale, Patch& patch) const;
  Patch fitPatch(
    int id) const; // around point id, at the finest scale that fits from the typical one
  // Where no plane fits around x's nearest point (a part thinner than the fit's widths) on a cloud
  // whose noise hides the plane at h: the nearest point is the noise's outermost, and the closed
  // field the caller would fall back on lies on the noise's outer envelope, sigmas out. Instead,
  // the mean depth of the points that the line from `inside` (the centroid of the points around the
  // nearest) through x meets first, for the caller to take only where it lies beyond that closed
  // field (in a fold narrower than the line's neighbourhood it would lie at the fold's mouth);
  // nothing found on a clean cloud, or where fewer than a handful lie there.
  SourcePoint firstLayer(const Vec3& x, const SourcePoint& nearest, const Vec3& inside) const;
  bool onRim(
    const Vec3& centre, int from, Vec3& onPlane) const; // see rims(); scales from `from` on
  // How far x's surface point on the patch may be trusted, 0 to 1; 0 also where x's foot lies too
  // far from the patch's centre for the patch to speak for it.
  static double trustAt(const Vec3& x, const Patch& patch);
  Patch patchAt(int id) const; // fitted once, then kept
  // The input point nearest x (as PointSource::closestPoint), from the finest scale's bins where
  // one lies within a width of x.
  SourcePoint nearestPoint(const Vec3& x, double maxSquaredDistance) const;

  std::shared_ptr<const PointSource> Points;
  std::vector<std::unique_ptr<const Scale>> Scales; // finest first
  int TypicalScale = 0;
  double TypicalNoise = 0;
  // The patches fitted so far, in chunks made as they fill (a wrap fits a few percent of a large
  // cloud's points: per point only a slot, not a patch); per input point, its patch's place in
  // them: empty, being stored, or the place.
  struct Chunk
  {
    static constexpr int kSize = 1024;
    Patch patches[kSize];
  };
  mutable LargeVector<std::atomic<std::uint32_t>> Slots;
  mutable std::vector<std::atomic<Chunk*>> Chunks;
  mutable std::atomic<std::uint32_t> Stored{ 0 };
};

} // namespace shrinkwrap

#endif
