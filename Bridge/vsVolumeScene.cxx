#include "vsVolumeScene.h"

#include "vsBrickRanges.h"
#include "vsDeviceVolume.h"
#include "vsError.h"
#include "vsGradientOpacity.h"
#include "vsMajorantGrid.h"
#include "vsPhaseTimes.h"
#include "vsTransferFunctionTable.h"
#include "vsVolumeInput.h"
#include "sampling/interpolation.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <chrono>
#include <limits>

namespace vs
{
VolumeScene::VolumeScene(std::shared_ptr<Context> context)
  : Context_(std::move(context))
  , LastPhases_(std::make_unique<PhaseTimes>())
{
}

VolumeScene::~VolumeScene() = default;

float VolumeScene::MaxResolvedExtinction(const VolumeGeometry& geometry)
{
  double largestIndex = 1.0, largestEdge = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    largestIndex = std::max(largestIndex, double(geometry.Dims[i]));
    largestEdge = std::max(largestEdge, geometry.Spacing(i));
  }
  const double resolution = double(std::numeric_limits<float>::epsilon()) * largestIndex * largestEdge;
  const double cap = resolution > 0.0 ? 1.0 / (kResolvedFreePaths * resolution) : 0.0;
  return float(std::min(cap, double(TransferFunctionSamples::kMaxExtinction)));
}

TransferFunctionSamples VolumeScene::SampleRenderedTransferFunction(vtkVolumeProperty* property, float smin,
  float smax, double densityScale, const VolumeGeometry& geometry)
{
  TransferFunctionSamples samples = SampleTransferFunction(property, smin, smax, densityScale);
  const float cap = MaxResolvedExtinction(geometry);
  for (size_t i = 3; i < samples.Entries.size(); i += 4)
  {
    samples.Entries[i] = std::min(samples.Entries[i], cap);
  }
  return samples;
}

VolumeScene::Changes VolumeScene::Update(vtkImageData* image, vtkDataArray* scalars,
  vtkVolumeProperty* property, vtkMatrix4x4* volumeMatrix, double densityScale)
{
  std::string problem = CheckImage(image, scalars);
  if (problem.empty())
  {
    problem = CheckProperty(property);
  }
  if (!problem.empty())
  {
    throw InputError(problem);
  }
  Changes changes;
  this->LastPhases_->Clear();
  auto lap = PhaseTimes::Clock::now();
  VolumeGeometry geometry = ComputeGeometry(image, volumeMatrix);
  problem = CheckGeometry(geometry);
  if (!problem.empty())
  {
    throw InputError(problem);
  }
  changes.Geometry = !this->Volume_ || geometry.Dims != this->Geometry_.Dims ||
    geometry.IndexToWorld != this->Geometry_.IndexToWorld;
  this->Geometry_ = geometry;
  // Before the data check: new data drops the table (it is resampled over the new range).
  const float cap = MaxResolvedExtinction(geometry);
  changes.TransferFunction = !this->TF_ || property->GetMTime() > this->PropertyTime_ ||
    densityScale != this->DensityScale_ || cap != this->ExtinctionCap_;

  const vtkMTimeType dataTime = std::max(image->GetMTime(), scalars->GetMTime());
  std::vector<float> values; // the scalars as floats, when read for an upload
  if (!this->Volume_ || scalars != this->Scalars_ || dataTime > this->DataTime_ ||
    this->Volume_->Dims() != geometry.Dims)
  {
    this->Volume_.reset();
    this->TF_.reset();
    DeviceVolume::CheckFits(*this->Context_, geometry.Dims);
    // The scalars in place where VTK holds them contiguously (issue 39: no float copy of the volume);
    // else converted to floats first.
    HostScalars host = NativeScalars(scalars);
    if (!host.Data)
    {
      values = ScalarsAsFloat(scalars);
      host = HostScalars(values.data());
      lap = this->LastPhases_->Lap("convert", lap);
    }
    if (!this->Majorants_)
    {
      this->Majorants_ = std::make_unique<MajorantGrid>(this->Context_);
    }
    // The bricks' ranges from each slice as it is uploaded (vsBrickRanges.h).
    BrickRanges ranges(geometry.Dims, this->Majorants_->BrickSize());
    this->Volume_ = std::make_unique<DeviceVolume>(this->Context_, host, geometry.Dims,
      [&ranges](uint32_t z, const float* slice) { ranges.AddSlice(z, slice); });
    lap = this->LastPhases_->Lap("upload", lap);
    this->Majorants_->UpdateRanges(*this->Volume_, ranges);
    lap = this->LastPhases_->Lap("ranges", lap);
    this->DataTime_ = dataTime;
    this->Scalars_ = scalars;
    ++this->Uploads_;
    changes.Data = true;
  }

  // The gradient-opacity factor: new data drops it (UpdateRanges), a new function or spacing
  // recomputes it; the majorants follow below.
  bool factorChanged = false;
  if (changes.Data || changes.TransferFunction || changes.Geometry)
  {
    std::vector<double> signature = GradientOpacitySignature(property, image->GetSpacing());
    if (changes.Data || signature != this->FactorSignature_)
    {
      factorChanged = changes.Data ? !signature.empty() : true;
      if (!signature.empty())
      {
        const auto start = std::chrono::steady_clock::now();
        if (values.empty())
        {
          values = ScalarsAsFloat(scalars);
        }
        std::vector<float> factor = GradientOpacityFactor(
          values.data(), geometry.Dims, image->GetSpacing(), property->GetStoredGradientOpacity(0));
        this->Volume_->SetFactor(factor.data());
        this->Majorants_->SetFactor(factor.data());
        this->HostFactor_ = std::move(factor);
        this->LastFactorSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }
      else
      {
        this->Volume_->SetFactor(nullptr);
        this->Majorants_->SetFactor(nullptr);
        this->HostFactor_.clear();
      }
      this->FactorSignature_ = std::move(signature);
      if (factorChanged)
      {
        ++this->FactorBuilds_;
      }
    }
    lap = this->LastPhases_->Lap("factor", lap);
  }

  if (changes.Data || changes.TransferFunction)
  {
    auto range = this->Volume_->Range();
    TransferFunctionSamples samples =
      SampleRenderedTransferFunction(property, range[0], range[1], densityScale, geometry);
    // Compare with the previous table: only the columns that changed need work downstream.
    const bool comparable = this->TF_ && !changes.Data &&
      this->TF_->Samples().ScalarMin == samples.ScalarMin && this->TF_->Samples().ScalarMax == samples.ScalarMax &&
      this->TF_->Samples().Entries.size() == samples.Entries.size();
    bool sameExtinction = comparable, sameAlbedo = comparable;
    for (size_t i = 0; comparable && i < samples.Entries.size(); ++i)
    {
      const bool equal = this->TF_->Samples().Entries[i] == samples.Entries[i];
      if (i % 4 == 3)
      {
        sameExtinction = sameExtinction && equal;
      }
      else
      {
        sameAlbedo = sameAlbedo && equal;
      }
    }
    changes.Extinction = !sameExtinction;
    changes.Albedo = !sameAlbedo;
    if (changes.Extinction || changes.Albedo)
    {
      this->TF_ = std::make_unique<TransferFunctionTable>(this->Context_, samples);
      ++this->TableBuilds_;
    }
    lap = this->LastPhases_->Lap("table", lap);
    changes.Extinction = changes.Extinction || factorChanged;
    if (changes.Extinction)
    {
      this->Majorants_->UpdateMajorants(samples);
      lap = this->LastPhases_->Lap("majorants", lap);
    }
    this->PropertyTime_ = property->GetMTime();
    this->DensityScale_ = densityScale;
    this->ExtinctionCap_ = cap;
  }
  else if (factorChanged)
  {
    // The spacing changed the gradients (and so the factor) under the same table.
    this->Majorants_->UpdateMajorants(this->TF_->Samples());
    changes.Extinction = changes.TransferFunction = true;
  }
  // Nearest or trilinear reconstruction of the scalar: a different extinction between voxels
  // (the same table and majorants: a brick's majorant bounds both), so the visibility changes.
  const uint32_t interpolation = property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION
    ? shared::VS_INTERPOLATION_NEAREST
    : shared::VS_INTERPOLATION_LINEAR;
  if (interpolation != this->Interpolation_)
  {
    changes.Interpolation = changes.Extinction = changes.TransferFunction = true;
    this->Interpolation_ = interpolation;
  }
  return changes;
}
}
