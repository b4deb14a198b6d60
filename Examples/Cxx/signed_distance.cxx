// signed_distance mesh.obj out.vti [resolution]: the signed distance field of a mesh, from C++.
#include "vtkMeshSignedDistance.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkXMLImageDataWriter.h>

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: signed_distance mesh.obj out.vti [resolution]\n";
    return 2;
  }
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(argv[1]);

  vtkNew<vtkMeshSignedDistance> distance;
  distance->SetInputConnection(reader->GetOutputPort());
  distance->SetResolution(argc > 3 ? std::atoi(argv[3]) : 120); // cells along the longest axis

  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputConnection(distance->GetOutputPort());
  writer->SetFileName(argv[2]);
  writer->Write();

  vtkImageData* image = distance->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  std::cout << "wrote " << argv[2] << ": " << dims[0] << " x " << dims[1] << " x " << dims[2]
            << " nodes, "
            << (image->GetFieldData()->GetArray("Signed")->GetTuple1(0) ? "signed" : "unsigned")
            << "\n";
  return image->GetNumberOfPoints() > 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
