// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOBJSceneReader.h"

#include "ObjScene.h"
#include "vtkTriangleSceneConverter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkOBJSceneReader);

vtkOBJSceneReader::vtkOBJSceneReader()
{
  this->SetNumberOfInputPorts(0);
}

int vtkOBJSceneReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->Warnings.clear();
  this->NonManifoldEdges = 0;
  this->DegenerateTriangles = 0;
  if (this->FileName.empty())
  {
    vtkErrorMacro(<< "no FileName: set the .obj file to read");
    return 0;
  }
  mesolight::ObjReadOptions options;
  options.RequireEmitter = this->RequireEmitter;
  options.RemoveDegenerateTriangles = this->RemoveDegenerateTriangles;
  mesolight::ObjSceneRead read;
  try
  {
    read = mesolight::ReadObjScene(this->FileName, options);
  }
  catch (const std::exception& error) // ObjSceneError, or std::bad_alloc on absurd files
  {
    vtkErrorMacro(<< error.what());
    return 0;
  }
  this->UpdateProgress(0.5);
  this->Warnings = read.Warnings;
  this->NonManifoldEdges = static_cast<vtkIdType>(read.NonManifoldEdges);
  this->DegenerateTriangles = static_cast<vtkIdType>(read.DegenerateTriangles);
  for (const std::string& warning : this->Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  vtkNew<vtkTriangleSceneConverter> converter;
  converter->ToPolyData(read.Scene, output);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkOBJSceneReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "RequireEmitter: " << this->RequireEmitter << "\n";
  os << indent << "RemoveDegenerateTriangles: " << this->RemoveDegenerateTriangles << "\n";
  os << indent << "NonManifoldEdges: " << this->NonManifoldEdges << "\n";
  os << indent << "DegenerateTriangles: " << this->DegenerateTriangles << "\n";
}
