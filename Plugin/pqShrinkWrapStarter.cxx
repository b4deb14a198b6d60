#include "pqShrinkWrapStarter.h"

#include "pqActiveObjects.h"
#include "pqAnimationManager.h"
#include "pqAnimationScene.h"
#include "pqApplicationCore.h"
#include "pqDataRepresentation.h"
#include "pqObjectBuilder.h"
#include "pqOutputPort.h"
#include "pqPVApplicationCore.h"
#include "pqPipelineSource.h"
#include "pqServerManagerModel.h"
#include "pqView.h"
#include "vtkNew.h"
#include "vtkPVArrayInformation.h"
#include "vtkPVDataInformation.h"
#include "vtkPVDataSetAttributesInformation.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMSourceProxy.h"
#include "vtkSMTransferFunctionManager.h"
#include "vtkSMTransferFunctionProxy.h"

#include <QTimer>
#include <QVariant>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace
{
// Where a created wrap stands: waiting for its first update (after Apply), then for the update at
// its last step.
const char* const kStage = "ShrinkWrapStage";

bool isShrinkWrap(pqPipelineSource* source)
{
  return source && source->getProxy() && source->getProxy()->GetXMLName() &&
    std::strcmp(source->getProxy()->GetXMLName(), "ShrinkWrap") == 0;
}

// Whether an input proxy's output is a distance field (an image with a SignedDistance array).
bool isField(vtkSMProxy* proxy)
{
  auto* source = vtkSMSourceProxy::SafeDownCast(proxy);
  vtkPVDataInformation* info = source ? source->GetDataInformation(0) : nullptr;
  return info && info->GetDataSetType() == VTK_IMAGE_DATA &&
    info->GetPointDataInformation()->GetArrayInformation("SignedDistance");
}

// A mesh and its field both on the Input, as the menus connect two selected sources: the panel's
// Distance Field shows the field (the filter skips it on Input then).
void showField(vtkSMProxy* wrap)
{
  vtkSMPropertyHelper input(wrap, "Input");
  vtkSMPropertyHelper field(wrap, "DistanceField");
  for (unsigned int k = 0; input.GetNumberOfElements() == 2 && !field.GetAsProxy() && k < 2; ++k)
  {
    if (isField(input.GetAsProxy(k)))
    {
      field.Set(input.GetAsProxy(k), input.GetOutputPort(k));
      wrap->UpdateVTKObjects();
    }
  }
}

// The target on the Input: the one that is not a distance field.
vtkSMProxy* targetOf(vtkSMProxy* wrap)
{
  vtkSMPropertyHelper input(wrap, "Input");
  for (unsigned int k = 0; k < input.GetNumberOfElements(); ++k)
  {
    if (!isField(input.GetAsProxy(k)))
    {
      return input.GetAsProxy(k);
    }
  }
  return nullptr;
}

// The colour map of the target as measured (output port 1, shown when the user turns it on, as
// ParaView colours it: by its active scalars, DistanceToWrap): diverging, centred at 0 over the
// largest distance either way, kept there as the animation moves.
void prepareMeasuredColours(pqPipelineSource* wrap, vtkSMProxy* representation, pqView* view)
{
  // Port 1 is shown by no view yet: brought to the view's time, as the wrap is.
  auto* source = vtkSMSourceProxy::SafeDownCast(wrap->getProxy());
  source->UpdatePipeline(vtkSMPropertyHelper(view->getProxy(), "ViewTime").GetAsDouble());
  pqOutputPort* port = wrap->getOutputPort(1);
  vtkPVDataInformation* info = port ? port->getDataInformation() : nullptr;
  vtkPVArrayInformation* distance =
    info ? info->GetPointDataInformation()->GetArrayInformation("DistanceToWrap") : nullptr;
  if (!distance)
  {
    return;
  }
  const double* range = distance->GetComponentRange(0);
  const double largest = std::max({ std::abs(range[0]), std::abs(range[1]), 1e-12 });
  vtkNew<vtkSMTransferFunctionManager> colours;
  vtkSMProxy* lut =
    colours->GetColorTransferFunction("DistanceToWrap", representation->GetSessionProxyManager());
  vtkSMTransferFunctionProxy::ApplyPreset(lut, "Cool to Warm", false);
  vtkSMTransferFunctionProxy::RescaleTransferFunction(lut, -largest, largest, false);
  vtkSMPropertyHelper(lut, "AutomaticRescaleRangeMode").Set(vtkSMTransferFunctionManager::NEVER);
  lut->UpdateVTKObjects();
}

// The shown wrap coloured by Distance over its range, with its legend; the target beside it in
// grey, a mesh as its edges, so that where it leaves the wrap shows.
void present(pqPipelineSource* wrap, pqDataRepresentation* representation, pqView* view)
{
  prepareMeasuredColours(wrap, representation->getProxy(), view);
  vtkSMProxy* proxy = representation->getProxy();
  if (vtkSMPVRepresentationProxy::SetScalarColoring(proxy, "Distance", 0))
  {
    vtkSMPVRepresentationProxy::RescaleTransferFunctionToDataRange(proxy, false, false);
    vtkSMPVRepresentationProxy::SetScalarBarVisibility(proxy, view->getProxy(), true);
  }
  auto* target =
    pqApplicationCore::instance()->getServerManagerModel()->findItem<pqPipelineSource*>(
      targetOf(wrap->getProxy()));
  pqDataRepresentation* shown = target ? target->getRepresentation(view) : nullptr;
  if (shown && shown->isVisible())
  {
    vtkSMProxy* look = shown->getProxy();
    vtkSMPropertyHelper(look, "Representation").Set("Wireframe"); // a cloud's points stay points
    vtkSMPVRepresentationProxy::SetScalarColoring(look, nullptr, 0);
    const double grey[3] = { 0.3, 0.3, 0.3 };
    vtkSMPropertyHelper(look, "AmbientColor").Set(grey, 3);
    vtkSMPropertyHelper(look, "DiffuseColor").Set(grey, 3);
    look->UpdateVTKObjects();
  }
  view->render();
}
} // namespace

pqShrinkWrapStarter::pqShrinkWrapStarter(QObject* parent)
  : Superclass(parent)
{
}

void pqShrinkWrapStarter::onStartup()
{
  pqObjectBuilder* builder = pqApplicationCore::instance()->getObjectBuilder();
  QObject::connect(builder, &pqObjectBuilder::filterCreated, this, &pqShrinkWrapStarter::created);
}

void pqShrinkWrapStarter::created(pqPipelineSource* source)
{
  if (!isShrinkWrap(source))
  {
    return;
  }
  showField(source->getProxy());
  source->setProperty(kStage, 1);
  QObject::connect(source, QOverload<pqPipelineSource*>::of(&pqPipelineSource::dataUpdated), this,
    &pqShrinkWrapStarter::updated);
}

void pqShrinkWrapStarter::updated(pqPipelineSource* source)
{
  const int stage = source->property(kStage).toInt();
  pqView* view = pqActiveObjects::instance().activeView();
  pqAnimationScene* scene = pqPVApplicationCore::instance()->animationManager()->getActiveScene();
  vtkSMPropertyHelper times(source->getProxy(), "TimestepValues", true);
  if (stage == 1 && scene && times.GetNumberOfElements() > 0)
  {
    // The first update after Apply shows the start when the scene stands at or before it.
    const double last = times.GetAsDouble(times.GetNumberOfElements() - 1);
    source->setProperty(kStage, 2);
    if (scene->getAnimationTime() <= times.GetAsDouble(0) && last > times.GetAsDouble(0))
    {
      scene->setAnimationTime(last); // updates the wrap again, at its last step
      return;
    }
  }
  source->setProperty(kStage, 0);
  QObject::disconnect(source, QOverload<pqPipelineSource*>::of(&pqPipelineSource::dataUpdated),
    this, &pqShrinkWrapStarter::updated);
  // After the Apply that updated it: then the wrap has its representation in the view.
  QPointer<pqPipelineSource> shown = source;
  QTimer::singleShot(0, this, [shown, view] {
    pqDataRepresentation* representation = shown && view ? shown->getRepresentation(view) : nullptr;
    if (representation && representation->isVisible())
    {
      present(shown, representation, view);
    }
  });
}
