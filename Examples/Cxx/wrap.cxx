// wrap mesh.obj out.vtp [out.vti]: the shrink-wrap of a mesh and, given a second file, its signed
// distance field, from C++.
#include "vtkMeshSignedDistance.h"
#include "vtkShrinkWrapFilter.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: wrap mesh.obj out.vtp [out.vti]\n";
    return 2;
  }
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(argv[1]);

  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputConnection(reader->GetOutputPort());
  wrap->SetGapSize(0);        // 0: automatic, the target's diagonal / 50
  wrap->UpdateTimeStep(1e30); // a time past the end: the last step
  vtkPolyData* surface = wrap->GetOutput();
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(surface);
  writer->SetFileName(argv[2]);
  writer->Write();
  auto* summary =
    vtkStringArray::SafeDownCast(surface->GetFieldData()->GetAbstractArray("Summary"));
  std::cout << "wrote " << argv[2] << ": " << (summary ? summary->GetValue(0) : "no wrap") << "\n";

  if (argc > 3)
  {
    vtkNew<vtkMeshSignedDistance> distance;
    distance->SetInputConnection(reader->GetOutputPort());
    distance->SetResolution(120); // cells along the longest side of its box
    vtkNew<vtkXMLImageDataWriter> fieldWriter;
    fieldWriter->SetInputConnection(distance->GetOutputPort());
    fieldWriter->SetFileName(argv[3]);
    fieldWriter->Write();
    vtkImageData* image = distance->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    std::cout << "wrote " << argv[3] << ": " << dims[0] << " x " << dims[1] << " x " << dims[2]
              << " nodes, "
              << (image->GetFieldData()->GetArray("Signed")->GetTuple1(0) ? "signed" : "unsigned")
              << "\n";
  }
  return surface->GetNumberOfPoints() > 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
