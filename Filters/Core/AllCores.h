// Runs work on all cores through vtkSMPTools. Debian's VTK defaults to the Sequential backend, so the
// work runs under a scoped STDThread backend, which leaves the process-wide choice alone; a backend the
// user chose through VTK_SMP_BACKEND_IN_USE wins.
#ifndef ShrinkWrap_AllCores_h
#define ShrinkWrap_AllCores_h

#include <vtkSMPTools.h>

#include <cstdlib>

namespace shrinkwrap
{

template <typename F>
void onAllCores(F&& f)
{
  if (std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    f();
    return;
  }
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, f);
}

} // namespace shrinkwrap

#endif
