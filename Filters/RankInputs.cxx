#include "RankInputs.h"

#include <vtkAlgorithm.h>
#include <vtkAppendFilter.h>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <numeric>
#include <string>

namespace shrinkwrap
{
namespace convert
{
namespace
{
// 64-bit words mixed in turn (splitmix64's finaliser): fast enough to digest a large mesh at every
// update, and a digest that equal parts of a distributed input share.
class Digest
{
public:
  void add(const void* data, std::size_t bytes)
  {
    const auto* c = static_cast<const unsigned char*>(data);
    std::size_t i = 0;
    for (; i + 8 <= bytes; i += 8)
    {
      std::uint64_t word;
      std::memcpy(&word, c + i, 8);
      this->mix(word);
    }
    std::uint64_t tail = bytes;
    std::memcpy(&tail, c + i, bytes - i);
    this->mix(tail ^ (static_cast<std::uint64_t>(bytes) << 56));
  }
  void add(std::uint64_t value) { this->mix(value); }
  void add(vtkDataArray* array)
  {
    this->add(array ? static_cast<std::uint64_t>(array->GetNumberOfValues()) : ~0ull);
    if (array && array->GetNumberOfValues() > 0)
    {
      this->add(array->GetVoidPointer(0),
        static_cast<std::size_t>(array->GetNumberOfValues()) * array->GetDataTypeSize());
    }
  }
  void add(vtkCellArray* cells)
  {
    this->add(cells ? cells->GetConnectivityArray() : nullptr);
    this->add(cells ? cells->GetOffsetsArray() : nullptr);
  }
  std::uint64_t value() const { return this->State; }

private:
  void mix(std::uint64_t word)
  {
    std::uint64_t z = (this->State ^ word) + 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    this->State = z ^ (z >> 31);
  }
  std::uint64_t State = 0x6a09e667f3bcc909ull;
};
// A part's geometry as bytes (points, then each cell's type and point ids; no arrays: the filters
// measure geometry only), and back: vtkCommunicator's own marshalling of data objects goes through
// XML and failed on a redistributed grid.
void put(std::vector<char>& bytes, const void* data, std::size_t size)
{
  const auto* c = static_cast<const char*>(data);
  bytes.insert(bytes.end(), c, c + size);
}

std::vector<char> packed(vtkDataSet* part)
{
  std::vector<char> bytes;
  const std::int64_t kind = vtkPolyData::SafeDownCast(part) ? 0 : 1;
  const std::int64_t points = part->GetNumberOfPoints(), cells = part->GetNumberOfCells();
  for (std::int64_t value : { kind, points, cells })
  {
    put(bytes, &value, sizeof(value));
  }
  for (vtkIdType i = 0; i < points; ++i)
  {
    double p[3];
    part->GetPoint(i, p);
    put(bytes, p, sizeof(p));
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < cells; ++c)
  {
    part->GetCellPoints(c, ids);
    const std::int64_t head[2] = { part->GetCellType(c), ids->GetNumberOfIds() };
    put(bytes, head, sizeof(head));
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      const std::int64_t id = ids->GetId(k);
      put(bytes, &id, sizeof(id));
    }
  }
  return bytes;
}

vtkSmartPointer<vtkDataSet> unpacked(const char* bytes, std::size_t size)
{
  std::size_t at = 0;
  auto next = [&]() {
    std::int64_t value = 0;
    if (at + sizeof(value) <= size)
    {
      std::memcpy(&value, bytes + at, sizeof(value));
    }
    at += sizeof(value);
    return value;
  };
  const std::int64_t kind = next(), points = next(), cells = next();
  vtkNew<vtkPoints> coordinates;
  coordinates->SetDataTypeToDouble();
  coordinates->SetNumberOfPoints(points);
  for (vtkIdType i = 0; i < points && at + 3 * sizeof(double) <= size;
       ++i, at += 3 * sizeof(double))
  {
    double p[3];
    std::memcpy(p, bytes + at, sizeof(p));
    coordinates->SetPoint(i, p);
  }
  vtkSmartPointer<vtkPolyData> mesh = kind == 0 ? vtkSmartPointer<vtkPolyData>::New() : nullptr;
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    kind == 0 ? nullptr : vtkSmartPointer<vtkUnstructuredGrid>::New();
  if (mesh)
  {
    mesh->SetPoints(coordinates);
    mesh->AllocateEstimate(cells, 3);
  }
  else
  {
    grid->SetPoints(coordinates);
    grid->AllocateEstimate(cells, 4);
  }
  std::vector<vtkIdType> ids;
  for (std::int64_t c = 0; c < cells && at < size; ++c)
  {
    const int type = static_cast<int>(next());
    ids.resize(static_cast<std::size_t>(std::max<std::int64_t>(0, next())));
    for (vtkIdType& id : ids)
    {
      id = static_cast<vtkIdType>(next());
    }
    if (mesh)
    {
      mesh->InsertNextCell(type, static_cast<int>(ids.size()), ids.data());
    }
    else
    {
      grid->InsertNextCell(type, static_cast<vtkIdType>(ids.size()), ids.data());
    }
  }
  return mesh ? vtkSmartPointer<vtkDataSet>(mesh) : vtkSmartPointer<vtkDataSet>(grid);
}
} // namespace

int ControllerExchange::rank() const
{
  return this->Controller->GetLocalProcessId();
}

int ControllerExchange::size() const
{
  return this->Controller->GetNumberOfProcesses();
}

Messages ControllerExchange::allGather(const std::vector<char>& mine) const
{
  const int n = this->size();
  vtkIdType length = static_cast<vtkIdType>(mine.size());
  std::vector<vtkIdType> lengths(n), offsets(n, 0);
  this->Controller->AllGather(&length, lengths.data(), 1);
  for (int r = 1; r < n; ++r)
  {
    offsets[r] = offsets[r - 1] + lengths[r - 1];
  }
  Messages all;
  all.bytes.resize(static_cast<std::size_t>(offsets[n - 1] + lengths[n - 1]));
  this->Controller->AllGatherV(
    mine.data(), all.bytes.data(), length, lengths.data(), offsets.data());
  all.offsets.assign(offsets.begin(), offsets.end());
  all.offsets.push_back(all.bytes.size());
  return all;
}

std::uint64_t contentDigest(vtkDataObject* data)
{
  Digest digest;
  for (vtkDataSet* leaf : vtkCompositeDataSet::GetDataSets(data))
  {
    const std::string kind = leaf->GetClassName();
    digest.add(kind.data(), kind.size());
    digest.add(static_cast<std::uint64_t>(leaf->GetNumberOfPoints()));
    digest.add(static_cast<std::uint64_t>(leaf->GetNumberOfCells()));
    if (auto* points = vtkPointSet::SafeDownCast(leaf))
    {
      digest.add(points->GetPoints() ? points->GetPoints()->GetData() : nullptr);
    }
    else
    {
      double bounds[6];
      leaf->GetBounds(bounds);
      digest.add(bounds, sizeof(bounds));
      digest.add(leaf->GetPointData()->GetScalars()); // a field's values
    }
    if (auto* mesh = vtkPolyData::SafeDownCast(leaf))
    {
      for (vtkCellArray* cells :
        { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() })
      {
        digest.add(cells);
      }
    }
    else if (auto* grid = vtkUnstructuredGrid::SafeDownCast(leaf))
    {
      digest.add(grid->GetCells());
      digest.add(grid->GetCellTypesArray());
    }
  }
  return digest.value();
}

std::vector<std::uint64_t> digestsOfRanks(
  vtkDataObject* input, vtkMultiProcessController* controller)
{
  const long long mine = input ? static_cast<long long>(contentDigest(input)) : 0;
  const int n = controller ? controller->GetNumberOfProcesses() : 1;
  std::vector<long long> all(n, mine);
  if (n > 1)
  {
    controller->AllGather(&mine, all.data(), 1);
  }
  return std::vector<std::uint64_t>(all.begin(), all.end());
}

bool distributed(const std::vector<std::uint64_t>& digests)
{
  return std::adjacent_find(digests.begin(), digests.end(), std::not_equal_to<>()) != digests.end();
}

vtkSmartPointer<vtkDataSet> appendedLeaves(vtkDataObject* input)
{
  const std::vector<vtkDataSet*> leaves = vtkCompositeDataSet::GetDataSets(input);
  if (leaves.empty())
  {
    return nullptr;
  }
  const bool polygonal = std::all_of(
    leaves.begin(), leaves.end(), [](vtkDataSet* leaf) { return vtkPolyData::SafeDownCast(leaf); });
  if (polygonal)
  {
    vtkNew<vtkAppendPolyData> append;
    for (vtkDataSet* leaf : leaves)
    {
      append->AddInputData(vtkPolyData::SafeDownCast(leaf));
    }
    append->Update();
    return append->GetOutput();
  }
  vtkNew<vtkAppendFilter> append;
  append->MergePointsOn();
  for (vtkDataSet* leaf : leaves)
  {
    append->AddInputData(leaf);
  }
  append->Update();
  return append->GetOutput();
}

vtkDataObject* wholeInput(
  vtkDataObject* input, vtkMultiProcessController* controller, std::unique_ptr<GatheredInput>& kept)
{
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    return input; // one process: nothing to gather, nothing to digest
  }
  const std::vector<std::uint64_t> digests = digestsOfRanks(input, controller);
  if (!distributed(digests))
  {
    kept.reset();
    return input;
  }
  if (kept && digests == kept->digests)
  {
    return kept->whole;
  }
  kept = std::make_unique<GatheredInput>();
  GatheredInput& gathered = *kept;
  // Every rank sends its part once (nothing if a lower rank holds the same) and appends all parts
  // in rank order: the same whole on every rank.
  const int rank = controller->GetLocalProcessId();
  const bool first =
    std::find(digests.begin(), digests.end(), digests[rank]) - digests.begin() == rank;
  const vtkSmartPointer<vtkDataSet> part = first && input ? appendedLeaves(input) : nullptr;
  const Messages parts =
    ControllerExchange(controller).allGather(part ? packed(part) : std::vector<char>());
  vtkNew<vtkMultiBlockDataSet> all;
  unsigned int block = 0;
  for (std::size_t r = 0; r < parts.count(); ++r)
  {
    if (parts.length(r) > 0)
    {
      all->SetBlock(block++, unpacked(parts.data(r), parts.length(r)));
    }
  }
  gathered.digests = digests;
  gathered.whole = appendedLeaves(all);
  if (!gathered.whole)
  {
    gathered.whole = vtkSmartPointer<vtkPolyData>::New();
  }
  return gathered.whole;
}

std::vector<int> shareOut(const std::vector<double>& cost, int pieces)
{
  std::vector<std::size_t> order(cost.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(
    order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  std::vector<double> load(std::max(1, pieces), 0);
  std::vector<int> piece(cost.size(), 0);
  for (std::size_t b : order)
  {
    piece[b] = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    load[piece[b]] += cost[b];
  }
  return piece;
}

PieceRequest pieceRequest(vtkInformation* outInfo)
{
  PieceRequest request;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()))
  {
    request.piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  }
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()))
  {
    request.pieces =
      std::max(1, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
  }
  return request;
}

std::vector<int> piecesOfLeaves(vtkCompositeDataSet* composite,
  const std::vector<vtkDataSet*>& leaves, const PieceRequest& request,
  vtkMultiProcessController* controller, const std::function<std::vector<int>()>& sharedOut)
{
  if (request.pieces > 1 && distributed(digestsOfRanks(composite, controller)))
  {
    std::vector<int> here;
    for (vtkDataSet* leaf : leaves)
    {
      here.push_back(leaf && leaf->GetNumberOfPoints() > 0 ? request.piece : -1);
    }
    return here;
  }
  return sharedOut();
}

void askWholeInputs(vtkInformationVector** inputVector, int ports, bool anyTime)
{
  for (int port = 0; port < ports; ++port)
  {
    for (int c = 0; c < inputVector[port]->GetNumberOfInformationObjects(); ++c)
    {
      vtkInformation* info = inputVector[port]->GetInformationObject(c);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
      if (anyTime)
      {
        info->Remove(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
      }
    }
  }
}

vtkCompositeDataSet* compositeOf(vtkInformationVector* port)
{
  for (int c = 0; c < port->GetNumberOfInformationObjects(); ++c)
  {
    if (auto* composite = vtkCompositeDataSet::GetData(port, c))
    {
      return composite;
    }
  }
  return nullptr;
}

std::vector<vtkDataSet*> leavesOf(vtkCompositeDataSet* composite)
{
  std::vector<vtkDataSet*> leaves;
  auto at = vtkSmartPointer<vtkCompositeDataIterator>::Take(composite->NewIterator());
  for (at->InitTraversal(); !at->IsDoneWithTraversal(); at->GoToNextItem())
  {
    leaves.push_back(vtkDataSet::SafeDownCast(at->GetCurrentDataObject()));
  }
  return leaves;
}

} // namespace convert
} // namespace shrinkwrap
