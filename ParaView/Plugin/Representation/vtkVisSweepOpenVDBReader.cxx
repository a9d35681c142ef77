#include "vtkVisSweepOpenVDBReader.h"

#include "vtkImageData.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationInformationVectorKey.h"
#include "vtkInformationIntegerVectorKey.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkOpenVDBVolumeReader.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>

vtkStandardNewMacro(vtkVisSweepOpenVDBReader);

vtkVisSweepOpenVDBReader::vtkVisSweepOpenVDBReader()
  : Reader(vtkOpenVDBVolumeReader::New())
{
  this->SetNumberOfInputPorts(0);
}

vtkVisSweepOpenVDBReader::~vtkVisSweepOpenVDBReader()
{
  this->Reader->Delete();
}

void vtkVisSweepOpenVDBReader::AddFileName(const char* fileName)
{
  this->Reader->AddFileName(fileName);
  this->Modified();
}

void vtkVisSweepOpenVDBReader::RemoveAllFileNames()
{
  this->Reader->RemoveAllFileNames();
  this->Modified();
}

void vtkVisSweepOpenVDBReader::SetGridName(const char* name)
{
  this->Reader->SetGridName(name);
}

const char* vtkVisSweepOpenVDBReader::GetGridName()
{
  return this->Reader->GetGridName();
}

void vtkVisSweepOpenVDBReader::SetPadding(int padding)
{
  this->Reader->SetPadding(padding);
}

void vtkVisSweepOpenVDBReader::SetUnionBounds(int on)
{
  this->Reader->SetUnionBounds(on != 0);
}

int vtkVisSweepOpenVDBReader::CanReadFile(const char* fileName)
{
  return vtkOpenVDBVolumeReader::CanReadFile(fileName);
}

vtkMTimeType vtkVisSweepOpenVDBReader::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Reader->GetMTime());
}

int vtkVisSweepOpenVDBReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  this->Reader->UpdateInformation();
  vtkInformation* readerInfo = this->Reader->GetOutputInformation(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  // The reader's whole extent, geometry, time steps and scalar type (what it has of them).
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  outInfo->CopyEntry(readerInfo, vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
  outInfo->CopyEntry(readerInfo, vtkDataObject::ORIGIN());
  outInfo->CopyEntry(readerInfo, vtkDataObject::SPACING());
  outInfo->CopyEntry(readerInfo, vtkDataObject::DIRECTION());
  outInfo->CopyEntry(readerInfo, vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  outInfo->CopyEntry(readerInfo, vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  outInfo->CopyEntry(readerInfo, vtkDataObject::POINT_DATA_VECTOR(), 1);
  // Each process keeps the piece it is asked for (RequestData crops the grid read).
  outInfo->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  return 1;
}

int vtkVisSweepOpenVDBReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  if (!output)
  {
    return 0;
  }
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    this->Reader->UpdateTimeStep(outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()));
  }
  else
  {
    this->Reader->Update();
  }
  vtkImageData* grid = this->Reader->GetOutput();
  if (!grid || grid->GetNumberOfPoints() == 0)
  {
    output->Initialize();
    return 1; // the reader said why (vtkErrorMacro)
  }
  output->ShallowCopy(grid);
  if (grid->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP()))
  {
    output->GetInformation()->Set(
      vtkDataObject::DATA_TIME_STEP(), grid->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()));
  }
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    output->Crop(outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()));
  }
  return 1;
}

void vtkVisSweepOpenVDBReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Reader:\n";
  this->Reader->PrintSelf(os, indent.GetNextIndent());
}
