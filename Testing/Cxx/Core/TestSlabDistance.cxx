// The field by pieces (issue #14, SlabDistance.h) equals the whole grid's at every node: processes
// played by threads that exchange their messages in memory, on closed, open, crossing and
// inward-facing surfaces, a grid that cuts the mesh, points, pieces that share their border planes
// as ParaView's extent translator gives them, ghost planes, more processes than planes; and an
// abort on one process ends all without a hang.
#include "Distance/DistanceSource.h"
#include "Distance/PointSource.h"
#include "Distance/SlabDistance.h"
#include "Surface/Icosphere.h"
#include "TestUtilities.h"

#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace
{
using namespace shrinkwrap;

// All-gather between threads: each round completes when every thread has given its bytes.
class ThreadExchange : public SlabExchange
{
public:
  struct Shared
  {
    explicit Shared(int n)
      : slots(n)
    {
    }
    std::mutex mutex;
    std::condition_variable done;
    std::vector<std::vector<char>> slots, published;
    int arrived = 0;
    long long round = 0;
  };
  ThreadExchange(Shared& shared, int rank)
    : S(shared)
    , Rank(rank)
  {
  }
  int rank() const override { return this->Rank; }
  int size() const override { return static_cast<int>(this->S.slots.size()); }
  Messages allGather(const std::vector<char>& mine) const override
  {
    std::unique_lock<std::mutex> lock(this->S.mutex);
    this->S.slots[this->Rank] = mine;
    const long long round = this->S.round;
    if (++this->S.arrived == this->size())
    {
      this->S.published = this->S.slots;
      this->S.arrived = 0;
      ++this->S.round;
      this->S.done.notify_all();
    }
    else
    {
      this->S.done.wait(lock, [&] { return this->S.round != round; });
    }
    Messages all;
    for (const auto& m : this->S.published)
    {
      all.offsets.push_back(all.bytes.size());
      all.bytes.insert(all.bytes.end(), m.begin(), m.end());
    }
    all.offsets.push_back(all.bytes.size());
    return all;
  }

private:
  Shared& S;
  int Rank;
};

struct Piece
{
  int first, last;
  std::vector<float> values;
  SignedDistanceResult result;
  Status status;
};

// Splits the planes' cells into `n` pieces as vtkExtentTranslator's slab mode does (pieces share
// their border plane), with `ghosts` planes more on each side.
std::vector<Piece> translatorPieces(int planes, int n, int ghosts)
{
  std::vector<Piece> pieces(n);
  const int cells = planes - 1;
  for (int p = 0; p < n; ++p)
  {
    const int a = p * cells / n, b = (p + 1) * cells / n;
    pieces[p].first = a == b ? 1 : std::max(0, a - ghosts);
    pieces[p].last = a == b ? 0 : std::min(planes - 1, b + ghosts);
  }
  return pieces;
}

// Every piece computed on its own thread; `abortRank` >= 0 asks that process to stop half-way.
void computePieces(const std::function<std::unique_ptr<DistanceSource>()>& makeSource,
  const GridLattice& lattice, std::vector<Piece>& pieces, int abortRank = -1)
{
  ThreadExchange::Shared shared(static_cast<int>(pieces.size()));
  std::vector<std::thread> threads;
  for (int r = 0; r < static_cast<int>(pieces.size()); ++r)
  {
    threads.emplace_back([&, r] {
      Piece& p = pieces[r];
      const auto source = makeSource();
      const GridLattice slab = planesOf(lattice, p.first, p.last);
      p.values.assign(std::max<std::int64_t>(0, slab.nodeCount()), 0.f);
      const Progress progress(r == abortRank
          ? std::function<bool(double)>([](double f) { return f < 0.5; })
          : std::function<bool(double)>());
      p.status = computeSlabSignedDistance(*source, lattice, p.first, p.last,
        SignedDistanceSettings(), ThreadExchange(shared, r), p.values.data(), p.result, progress);
    });
  }
  for (auto& t : threads)
  {
    t.join();
  }
}

// Compares every piece with the whole grid's field: the largest difference in units of the grid's
// diagonal, and nodes of the other sign.
void compare(const std::string& name,
  const std::function<std::unique_ptr<DistanceSource>()>& makeSource, const GridLattice& lattice,
  std::vector<Piece> pieces)
{
  const auto wholeSource = makeSource();
  std::vector<float> whole(lattice.nodeCount());
  const SignedDistanceResult serial =
    computeSignedDistance(*wholeSource, lattice, SignedDistanceSettings(), whole.data());
  computePieces(makeSource, lattice, pieces);
  const std::int64_t plane = static_cast<std::int64_t>(lattice.dims[0]) * lattice.dims[1];
  const double diagonal = lattice.bounds().diagonal();
  double worst = 0;
  long long signs = 0, nodes = 0;
  bool same = true;
  for (const Piece& p : pieces)
  {
    same = same && p.status && p.result.completed && p.result.isSigned == serial.isSigned &&
      p.result.signMethod == serial.signMethod &&
      p.result.invertedOrientation == serial.invertedOrientation &&
      p.result.signDisagreements == serial.signDisagreements;
    for (std::int64_t n = 0; n < static_cast<std::int64_t>(p.values.size()); ++n)
    {
      const float a = p.values[n], b = whole[p.first * plane + n];
      worst = std::max(worst, std::abs(static_cast<double>(a) - b) / diagonal);
      signs += (a < 0) != (b < 0);
      ++nodes;
    }
  }
  std::printf(
    "%s: %zu pieces, %lld nodes, largest difference %.2e of the diagonal, %lld signs differ (%s)\n",
    name.c_str(), pieces.size(), nodes, worst, signs, signStatus(serial, true).c_str());
  SW_CHECK(same, name + ": every piece completed with the whole grid's sign method and votes");
  SW_CHECK(worst <= 1e-6 && signs == 0,
    name + ": the pieces equal the whole field to 1e-6 of the diagonal, same signs");
}

std::function<std::unique_ptr<DistanceSource>()> triangles(const TriangleSoup& soup)
{
  return [soup] { return std::make_unique<TriangleSource>(soup); };
}

TriangleSoup joined(TriangleSoup a, const TriangleSoup& b)
{
  const int offset = static_cast<int>(a.points.size());
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (auto t : b.triangles)
  {
    a.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  return a;
}

GridLattice around(const TriangleSoup& soup, int resolution)
{
  GridLattice lattice;
  placeGrid(soup.bounds(), GridPlacement{ 1.1, 0.15, resolution, 0 }, lattice);
  return lattice;
}
} // namespace

int TestSlabDistance(int, char*[])
{
  // Closed: two spheres apart (two inside regions, one outside region across every border).
  const TriangleSoup two =
    joined(icosphere(3, Vec3(-0.6, 0, -0.5), 0.5), icosphere(3, Vec3(0.5, 0.2, 0.6), 0.45));
  const GridLattice lattice = around(two, 48);
  const int nz = lattice.dims[2];
  compare("two spheres, 2 pieces", triangles(two), lattice, translatorPieces(nz, 2, 0));
  compare("two spheres, 3 pieces", triangles(two), lattice, translatorPieces(nz, 3, 0));
  compare(
    "two spheres, 3 pieces, 2 ghost planes", triangles(two), lattice, translatorPieces(nz, 3, 2));

  // Facing inwards: the votes of the corner region flip every sign.
  TriangleSoup inward = two;
  for (auto& t : inward.triangles)
  {
    std::swap(t[1], t[2]);
  }
  compare(
    "inward-facing spheres, 2 pieces", triangles(inward), lattice, translatorPieces(nz, 2, 1));

  // Open and crossing: the votes disagree and the winding number decides, from sites of other
  // pieces too.
  TriangleSoup open = icosphere(3, Vec3::Zero(), 1);
  open.triangles.resize(open.triangles.size() - 12);
  compare("sphere with a hole, 3 pieces", triangles(open), around(open, 40),
    translatorPieces(around(open, 40).dims[2], 3, 1));
  const TriangleSoup crossing =
    joined(icosphere(3, Vec3::Zero(), 1), icosphere(3, Vec3(0.8, 0.3, 0.2), 0.7));
  compare("crossing spheres, 2 pieces", triangles(crossing), around(crossing, 40),
    translatorPieces(around(crossing, 40).dims[2], 2, 0));

  // A grid that cuts the mesh: exact distances on the grid's faces (of the pieces that hold them).
  GridLattice cut;
  Box box;
  box.min = Vec3(-0.7, -0.7, -0.3);
  box.max = Vec3(0.7, 0.7, 0.9);
  explicitGrid(box, { 30, 30, 26 }, cut);
  compare("grid cutting the spheres, 3 pieces", triangles(two), cut, translatorPieces(26, 3, 0));

  // Points: unsigned.
  const TriangleSoup sphere = icosphere(3, Vec3::Zero(), 1);
  compare(
    "points of a sphere, 2 pieces", [&] { return std::make_unique<PointSource>(sphere.points); },
    around(sphere, 40), translatorPieces(around(sphere, 40).dims[2], 2, 0));

  // More processes than plane pairs: some compute nothing.
  GridLattice thin;
  explicitGrid(two.bounds(), { 20, 20, 4 }, thin);
  compare("4 planes, 5 pieces", triangles(two), thin, translatorPieces(4, 5, 0));

  // A gap: refused on every process.
  std::vector<Piece> gap = translatorPieces(nz, 2, 0);
  gap[1].first += 2;
  computePieces(triangles(two), lattice, gap);
  SW_CHECK(
    !gap[0].status && !gap[1].status, "pieces that leave a gap are refused on every process");

  // An abort on one process: every process returns incomplete.
  std::vector<Piece> aborted = translatorPieces(nz, 3, 0);
  computePieces(triangles(two), lattice, aborted, 1);
  SW_CHECK(std::all_of(aborted.begin(), aborted.end(),
             [](const Piece& p) { return p.status && !p.result.completed; }),
    "an abort on one process ends the computation on all");
  return testing::finish("TestSlabDistance");
}
