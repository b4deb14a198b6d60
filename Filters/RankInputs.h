// What each MPI rank works on. Both filters need a whole target on a rank (distances need
// every triangle), and the filters ask their input for all of it; but a source under ParaView's MPI
// engine may hand each rank only its part whatever is asked (an in-situ adaptor, a script's
// source): then the ranks gather the parts. A composite's blocks, each computed on its own, are
// shared out.
#ifndef ShrinkWrap_RankInputs_h
#define ShrinkWrap_RankInputs_h

#include "Distance/SlabDistance.h"

#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <algorithm>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkInformationVector;
class vtkDataSet;
class vtkInformation;
class vtkMultiProcessController;

namespace shrinkwrap
{
namespace convert
{

// The processes of ParaView's MPI engine (pvbatch, pvserver) as the core's computations talk to
// them.
class ControllerExchange : public SlabExchange
{
public:
  explicit ControllerExchange(vtkMultiProcessController* controller)
    : Controller(controller)
  {
  }
  int rank() const override;
  int size() const override;
  Messages allGather(const std::vector<char>& mine) const override;

private:
  vtkMultiProcessController* Controller;
};

// A digest of a dataset's or composite's geometry (points, cells; a grid and its scalars): equal
// data, equal digest.
std::uint64_t contentDigest(vtkDataObject* data);

// The digest of each rank's input, the same list on every rank. Collective over `controller`; one
// entry (this process's) without a controller or with one process.
std::vector<std::uint64_t> digestsOfRanks(
  vtkDataObject* input, vtkMultiProcessController* controller);

// Whether the ranks hold different inputs (the parts of a distributed one) by their digests.
bool distributed(const std::vector<std::uint64_t>& digests);

// The leaves of an input appended into one dataset: polygonal data when every leaf is (its cells
// kept as they are), else an unstructured grid with coincident points merged (so that faces between
// the parts of a distributed volume are interior again and Extract Surface drops them). Null for
// none.
vtkSmartPointer<vtkDataSet> appendedLeaves(vtkDataObject* input);

// The ranks' inputs gathered, kept between updates while the ranks hold the same parts.
struct GatheredInput
{
  std::vector<std::uint64_t> digests; // of the parts it was gathered from
  vtkSmartPointer<vtkDataSet> whole;  // the parts appended, in rank order, each distinct part once
};

// The whole input on this rank: `input` itself when every rank holds the same, else the parts of
// all ranks appended (ranks holding a part equal to a lower rank's send nothing), kept in
// `gathered` (made when first needed). Collective over `controller`: every rank calls it at the
// same update.
vtkDataObject* wholeInput(vtkDataObject* input, vtkMultiProcessController* controller,
  std::unique_ptr<GatheredInput>& gathered);

// The piece that computes each block, by the blocks' expected costs: largest first, each to the
// least loaded piece (the same answer on every rank).
std::vector<int> shareOut(const std::vector<double>& cost, int pieces);

// The piece of the pipeline's request this process computes, and of how many.
struct PieceRequest
{
  int piece = 0, pieces = 1;
};
PieceRequest pieceRequest(vtkInformation* outInfo);

// The piece that computes each of a composite's `leaves` (as its iterator gives them): when the
// composite arrives distributed, each rank its own non-empty leaves (-1 for the others'); else
// `sharedOut()`. Collective over `controller` when the request has more than one piece.
std::vector<int> piecesOfLeaves(vtkCompositeDataSet* composite,
  const std::vector<vtkDataSet*>& leaves, const PieceRequest& request,
  vtkMultiProcessController* controller, const std::function<std::vector<int>()>& sharedOut);

// Asks a filter's inputs on its first `ports` ports for all of their data (piece 0 of 1, no ghost
// levels), and with `anyTime` at the time they have (no time asked for).
void askWholeInputs(vtkInformationVector** inputVector, int ports, bool anyTime);

// The first composite among a port's inputs, if any.
vtkCompositeDataSet* compositeOf(vtkInformationVector* port);

// The leaves of a composite, in its iterator's order.
std::vector<vtkDataSet*> leavesOf(vtkCompositeDataSet* composite);

// A composite's leaves computed by the pieces `computedOn` gives them (piecesOfLeaves): `output`
// takes the input's shape, and at each leaf a new Leaf that compute(leaf, flat index, made, first,
// share) fills where this piece computes it (first and share: the leaf's part of one progress bar
// over them); empty elsewhere.
template <typename Leaf, typename Compute>
void computeLeaves(vtkCompositeDataSet* input, vtkCompositeDataSet* output,
  const std::vector<int>& computedOn, int piece, Compute&& compute)
{
  output->CopyStructure(input);
  const std::vector<vtkDataSet*> leaves = leavesOf(input);
  const auto here = static_cast<double>(std::count(computedOn.begin(), computedOn.end(), piece));
  auto at = vtkSmartPointer<vtkCompositeDataIterator>::Take(input->NewIterator());
  int done = 0;
  std::size_t count = 0;
  for (at->InitTraversal(); !at->IsDoneWithTraversal(); at->GoToNextItem(), ++count)
  {
    vtkNew<Leaf> made;
    if (leaves[count] && computedOn[count] == piece)
    {
      compute(leaves[count], at->GetCurrentFlatIndex(), made.Get(), done++ / here, 1 / here);
    }
    output->SetDataSet(at, made);
  }
}

} // namespace convert
} // namespace shrinkwrap

#endif
