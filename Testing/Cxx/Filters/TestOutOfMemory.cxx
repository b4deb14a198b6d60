// A process memory limit (ulimit -v, a batch job's cap): Mesh Signed Distance refuses a grid that
// would not fit under it before allocating, naming the memory left; where an estimate does not
// cover what runs out (a level-8 icosphere), the allocation fails and Shrink Wrap reports it as an
// error with an empty output instead of aborting the process. With the limit lifted the same filter
// computes again. Not run under AddressSanitizer,
// whose shadow memory does not fit under such a limit.
#include "TestUtilities.h"
#include "vtkMeshSignedDistance.h"
#include "vtkShrinkWrapFilter.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkSphereSource.h>

#include <functional>
#include <sys/resource.h>
#include <unistd.h>

namespace
{
// Address space in use now, from /proc/self/statm (pages).
double addressSpaceBytes()
{
  std::ifstream statm("/proc/self/statm");
  double pages = 0;
  statm >> pages;
  return pages * sysconf(_SC_PAGESIZE);
}

// Runs `run` with at most `headroom` bytes of address space more than now; returns the errors said.
std::string underLimit(vtkAlgorithm* algorithm, double headroom, const std::function<void()>& run)
{
  std::string errors;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&errors);
  observer->SetCallback([](vtkObject*, unsigned long, void* data, void* message) {
    *static_cast<std::string*>(data) += static_cast<const char*>(message);
  });
  const unsigned long tag = algorithm->AddObserver(vtkCommand::ErrorEvent, observer);
  rlimit old;
  getrlimit(RLIMIT_AS, &old);
  rlimit limited = old;
  limited.rlim_cur = static_cast<rlim_t>(addressSpaceBytes() + headroom);
  setrlimit(RLIMIT_AS, &limited);
  run();
  setrlimit(RLIMIT_AS, &old);
  algorithm->RemoveObserver(tag);
  return errors;
}
} // namespace

int TestOutOfMemory(int, char*[])
{
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  const double GiB = 1024.0 * 1024.0 * 1024.0;

  // 492 x 492 x 501 nodes: about 1 GiB by the filter's estimate, below the free memory of the test
  // machines, above a limit of 0.5 GiB more than the process uses now.
  vtkNew<vtkMeshSignedDistance> distance;
  distance->SetInputData(sphere->GetOutput());
  distance->SetResolution(500);
  std::string said = underLimit(distance, 0.5 * GiB, [&] { distance->Update(); });
  std::cout << "Mesh Signed Distance under the limit: " << said.substr(said.find("): ") + 3)
            << std::endl;
  SW_CHECK(said.find("would need 1.02 GiB but only 0.") != std::string::npos &&
      distance->GetOutput()->GetNumberOfPoints() == 0,
    "Mesh Signed Distance: the grid refused against the process's limit, empty output");
  distance->SetResolution(40);
  distance->Update();
  SW_CHECK(
    distance->GetOutput()->GetNumberOfPoints() == 41 * 41 * 41, "Mesh Signed Distance lives on");

  // Subdivision Level 8 (655,362 vertices) within 150 MiB more than now.
  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputData(sphere->GetOutput());
  wrap->SetResolution(24);
  wrap->SetStartingShape(
    vtkShrinkWrapFilter::ICOSPHERE); // a level-8 icosphere is what does not fit
  wrap->SetRemeshing(false);
  wrap->SetSubdivisionLevel(8);
  wrap->SetNumberOfSteps(2);
  said = underLimit(wrap, 0.15 * GiB, [&] { wrap->Update(); });
  std::cout << "Shrink Wrap under the limit: " << said.substr(said.find("): ") + 3) << std::endl;
  SW_CHECK(!said.empty() && wrap->GetOutput()->GetNumberOfPoints() == 0,
    "Shrink Wrap: an error, empty output");
  wrap->SetSubdivisionLevel(2);
  wrap->Update();
  SW_CHECK(wrap->GetOutput()->GetNumberOfPoints() == 162, "Shrink Wrap lives on");
  return testing::finish("TestOutOfMemory");
}
