// A time series for the tests and benchmarks: a source whose time steps are 0, 1, ..., Frames - 1
// and whose output at time t is Make(t) (the frame index, the nearest to t); it records the times
// it was asked for, as a reader of a series would be asked.
#ifndef ShrinkWrap_SeriesSource_h
#define ShrinkWrap_SeriesSource_h

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace testing
{

class SeriesSource : public vtkPolyDataAlgorithm
{
public:
  static SeriesSource* New() { VTK_STANDARD_NEW_BODY(SeriesSource); }
  vtkTypeMacro(SeriesSource, vtkPolyDataAlgorithm);
  std::function<vtkSmartPointer<vtkPolyData>(int frame)> Make;
  int Frames = 0;
  std::vector<double> Asked; // the times of the requests, in order

protected:
  SeriesSource() { this->SetNumberOfInputPorts(0); }
  int RequestInformation(
    vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    std::vector<double> times(this->Frames);
    for (int k = 0; k < this->Frames; ++k)
    {
      times[k] = k;
    }
    vtkInformation* info = out->GetInformationObject(0);
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), this->Frames);
    const double range[2] = { 0.0, this->Frames - 1.0 };
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
    return 1;
  }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkInformation* info = out->GetInformationObject(0);
    const double t = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
      ? info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
      : 0.0;
    this->Asked.push_back(t);
    const int k = std::clamp(static_cast<int>(std::lround(t)), 0, this->Frames - 1);
    vtkPolyData* output = vtkPolyData::GetData(out);
    output->ShallowCopy(this->Make(k));
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), double(k));
    return 1;
  }
};

} // namespace testing

#endif
