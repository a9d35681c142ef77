#include "vtkVisSweepVolumeRepresentation.h"

#include "vtkCommunicator.h"
#include "vtkEnvironmentMapReader.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOutlineSource.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include <algorithm>
#include <iterator>
#include <chrono>

vtkStandardNewMacro(vtkVisSweepVolumeRepresentation);

namespace
{
// The mapper clamps these settings silently (vtkSetClampMacro); a value set from ParaView's panel
// or a script outside the range is worth a word in ParaView's output window.
template <typename T>
void WarnOutOfRange(vtkObject* self, const char* name, T value, T low, T high)
{
  if (value < low || value > high)
  {
    vtkWarningWithObjectMacro(self, << name << " " << value << " is outside [" << low << ", "
                                    << high << "]: the mapper uses "
                                    << (value < low ? low : high) << ".");
  }
}

double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}

vtkVisSweepVolumeRepresentation::vtkVisSweepVolumeRepresentation()
{
  // The superclass made its own mapper; VisSweep's takes its place (the superclass reads
  // this->VolumeMapper wherever it passes ParaView's volume settings on).
  this->VolumeMapper = vtkSmartPointer<vtkVisibilitySweepVolumeMapper>::New();
  this->EnvironmentReader = vtkEnvironmentMapReader::New();
  this->WhiteSky = vtkEnvironmentMapSource::New();
  this->WhiteSky->SetOctahedralSize(16); // the mapper's own default sky, texel for texel
  this->GetVisSweepMapper()->SetEnvironmentConnection(this->WhiteSky->GetOutputPort());
  // Under MPI (pvbatch, pvserver) every process of the global controller renders the view; a client
  // has a controller of its own process only.
  if (vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController())
  {
    this->Processes = std::max(1, controller->GetNumberOfProcesses());
    this->ProcessId = controller->GetLocalProcessId();
  }
  if (this->Processes > 1)
  {
    vtkVisibilitySweepVolumeMapper* mapper = this->GetVisSweepMapper();
    mapper->SetRadianceCombiner(
      [this](std::vector<float>& mean, uint32_t samples) { return this->CombineRadiance(mean, samples); });
    // The first process draws the mean of all; the others' images would be composited over it.
    mapper->SetDrawImage(this->ProcessId == 0);
    mapper->SetEnvironmentVisible(false);
    this->UpdateDistributedSettings();
  }
}

vtkVisSweepVolumeRepresentation::~vtkVisSweepVolumeRepresentation()
{
  this->EnvironmentReader->Delete();
  this->WhiteSky->Delete();
}

vtkVisibilitySweepVolumeMapper* vtkVisSweepVolumeRepresentation::GetVisSweepMapper()
{
  return static_cast<vtkVisibilitySweepVolumeMapper*>(this->VolumeMapper.GetPointer());
}

void vtkVisSweepVolumeRepresentation::SetVisSweepRenderMode(int mode)
{
  WarnOutOfRange(this, "VisSweepRenderMode", mode, 0, 3);
  this->GetVisSweepMapper()->SetRenderMode(mode);
}

void vtkVisSweepVolumeRepresentation::SetSamplingStrategy(int strategy)
{
  WarnOutOfRange(this, "SamplingStrategy", strategy, 0, 5);
  this->GetVisSweepMapper()->SetSamplingStrategy(strategy);
}

void vtkVisSweepVolumeRepresentation::UpdateDistributedSettings()
{
  vtkVisibilitySweepVolumeMapper* mapper = this->GetVisSweepMapper();
  if (this->Processes <= 1)
  {
    mapper->SetSeed(this->Seed);
    this->SampleShare = this->MaximumSamples;
  }
  else
  {
    // Each process its own random numbers (the first the user's seed, so one process renders as
    // before) and its share of the samples: together MaximumSamples (at least one each).
    const long long seed = (static_cast<long long>(this->Seed) + 104729LL * this->ProcessId) % VTK_INT_MAX;
    mapper->SetSeed(static_cast<int>(seed));
    const int share = this->MaximumSamples / this->Processes + (this->ProcessId < this->MaximumSamples % this->Processes ? 1 : 0);
    this->SampleShare = std::max(1, share);
  }
  // A spent time budget holds the accumulation where it is (UpdateTimeBudget decides again before
  // the next render).
  mapper->SetMaximumSamples(this->BudgetSpent ? std::min(this->SampleShare, std::max(1, this->BudgetSamples)) : this->SampleShare);
}

void vtkVisSweepVolumeRepresentation::SetTimeBudget(double seconds)
{
  if (!(seconds >= 0.0)) // negative or NaN
  {
    vtkWarningMacro(<< "TimeBudget " << seconds << " is not a number of seconds >= 0: 0 (no budget) is used.");
    seconds = 0.0;
  }
  this->TimeBudget = seconds;
}

void vtkVisSweepVolumeRepresentation::UpdateTimeBudget()
{
  vtkVisibilitySweepVolumeMapper* mapper = this->GetVisSweepMapper();
  const int resets = mapper->GetAccumulationResetCount();
  const int samples = mapper->GetAccumulatedSamples(); // this process's
  // The render since the last call (if any): its time (distributed: the slowest process's, the same
  // on every process, so that all decide alike), and the next frame's without its update (new data,
  // sweeps), as the vissweep tool's --time-budget predicts it.
  const bool distributed = this->Processes > 1;
  const double frame = distributed ? this->CombinedFrameSeconds[0] : mapper->GetTimeToDraw();
  const double next = distributed ? this->CombinedFrameSeconds[1]
                                  : std::max(0.0, mapper->GetTimeToDraw() - mapper->GetLastUpdateSeconds());
  if (samples <= 0)
  {
    // No still accumulation (an interactive frame, another mode, nothing rendered yet).
    this->AccumulationSeconds = 0.0;
    this->BudgetSamples = 0;
    this->BudgetResets = resets;
  }
  else if (resets != this->BudgetResets)
  {
    // That render restarted the accumulation: the clock restarts with it.
    this->AccumulationSeconds = frame;
    std::fill(std::begin(this->RecentFrameSeconds), std::end(this->RecentFrameSeconds), next);
    this->FirstFrameOnly = true;
    this->NextFrameSeconds = next;
    this->BudgetSamples = samples;
    this->BudgetResets = resets;
  }
  else if (samples > this->BudgetSamples)
  {
    this->AccumulationSeconds += frame;
    // The next frame is expected to take as long as the longest of the last 16 and as much more as that
    // one took over their median: the frames' jitter. Predicted from the last frame alone, a frame slower
    // than the one before ran a 1 s budget of ~9 ms frames over (a clean clone's ParaView.Pvbatch:
    // AccumulationTime 1.000 s); from the longest of the last three, one slower than those three did
    // (1.002 s, 2026-12-07). A machine that stalls a frame by more than its recent jitter can still.
    // The accumulation's first frame (its one-off costs: pipelines, page faults) stands only until the
    // second, as in vs::FrameTimePredictor.
    if (this->FirstFrameOnly)
    {
      std::fill(std::begin(this->RecentFrameSeconds), std::end(this->RecentFrameSeconds), next);
      this->FirstFrameOnly = false;
    }
    this->RecentFrameSeconds[this->RecentFrame] = next;
    this->RecentFrame = (this->RecentFrame + 1) % RecentFrames;
    double sorted[RecentFrames];
    std::copy(std::begin(this->RecentFrameSeconds), std::end(this->RecentFrameSeconds), sorted);
    std::sort(std::begin(sorted), std::end(sorted));
    const double longest = sorted[RecentFrames - 1], median = 0.5 * (sorted[RecentFrames / 2 - 1] + sorted[RecentFrames / 2]);
    this->NextFrameSeconds = longest + std::max(0.0, longest - median);
    this->BudgetSamples = samples;
  }
  // Redraws (no new samples) cost nothing of the budget.
  const bool spent = this->TimeBudget > 0.0 && samples > 0 &&
    mapper->GetRenderMode() == vtkVisibilitySweepVolumeMapper::MonteCarlo &&
    this->AccumulationSeconds + this->NextFrameSeconds > this->TimeBudget;
  this->BudgetSpent = spent;
  // The deadline, for Auto's sweeps (the mapper's RemainingTimeBudget): what is left of the budget,
  // all of it before a still accumulation starts.
  mapper->SetRemainingTimeBudget(
    this->TimeBudget > 0.0 ? std::max(1e-3, this->TimeBudget - this->AccumulationSeconds) : 0.0);
  // The mapper's own progressive stop: MaximumSamples held at the samples reached.
  mapper->SetMaximumSamples(spent ? std::min(this->SampleShare, samples) : this->SampleShare);
  this->FrameStart = Now();
}

uint32_t vtkVisSweepVolumeRepresentation::CombineRadiance(std::vector<float>& mean, uint32_t samples)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() != this->Processes)
  {
    return samples;
  }
  // The same image size everywhere (a view's windows are), else each keeps its own.
  const int size[2] = { static_cast<int>(mean.size()), -static_cast<int>(mean.size()) };
  int largest[2] = { 0, 0 };
  controller->AllReduce(size, largest, 2, vtkCommunicator::MAX_OP);
  // The time budget: the slowest process's frame so far and next frame (without the update), the
  // same on every process, so that all stop at the same frame (UpdateTimeBudget).
  const double frame = std::max(0.0, Now() - this->FrameStart);
  const double times[2] = { frame, std::max(0.0, frame - this->GetVisSweepMapper()->GetLastUpdateSeconds()) };
  controller->AllReduce(times, this->CombinedFrameSeconds, 2, vtkCommunicator::MAX_OP);
  if (largest[0] != -largest[1])
  {
    vtkErrorMacro(<< "the processes rendered images of different sizes; each shows its own samples");
    return samples;
  }
  // Sum over processes of samples x mean (each mean weighted by the samples behind it), then / total.
  std::vector<float> weighted(mean.size() + 1);
  for (size_t i = 0; i < mean.size(); ++i)
  {
    weighted[i] = mean[i] * static_cast<float>(samples);
  }
  weighted.back() = static_cast<float>(samples);
  std::vector<float> sum(weighted.size(), 0.0f);
  controller->AllReduce(weighted.data(), sum.data(), static_cast<vtkIdType>(weighted.size()), vtkCommunicator::SUM_OP);
  const float total = sum.back();
  if (total > 0.0f)
  {
    for (size_t i = 0; i < mean.size(); ++i)
    {
      mean[i] = sum[i] / total;
    }
  }
  this->CombinedSamples = static_cast<int>(total + 0.5f);
  this->CombinedLocalSamples = this->GetVisSweepMapper()->GetAccumulatedSamples();
  return static_cast<uint32_t>(this->CombinedSamples);
}

int vtkVisSweepVolumeRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestData(request, inputVector, outputVector))
  {
    return 0;
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (this->Processes <= 1 || !controller || inputVector[0]->GetNumberOfInformationObjects() != 1)
  {
    return 1;
  }
  // Every process renders the whole volume: gather the pieces (ghost cells already cropped by the
  // superclass) from all processes and put each at its extent. Every process runs this (ParaView
  // updates a representation's pipeline on all of them).
  vtkImageData* piece = vtkImageData::SafeDownCast(this->Cache);
  vtkNew<vtkImageData> empty;
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->AllGather(piece ? piece : empty.GetPointer(), pieces);
  vtkNew<vtkImageAppend> append;
  append->PreserveExtentsOn();
  int appended = 0;
  for (const auto& object : pieces)
  {
    vtkImageData* image = vtkImageData::SafeDownCast(object);
    if (image && image->GetNumberOfPoints() > 0)
    {
      append->AddInputData(image);
      ++appended;
    }
  }
  if (appended == 0 || !piece)
  {
    return 1;
  }
  append->Update();
  vtkNew<vtkImageData> whole;
  whole->ShallowCopy(append->GetOutput());
  whole->SetDirectionMatrix(piece->GetDirectionMatrix());
  this->Cache = whole.GetPointer();
  this->VolumeMapper->SetInputData(whole.GetPointer());
  this->OutlineSource->SetBounds(whole->GetBounds());
  this->OutlineSource->GetBounds(this->DataBounds);
  this->OutlineSource->Update();
  this->DataSize = whole->GetActualMemorySize();
  return 1;
}

void vtkVisSweepVolumeRepresentation::UpdateMapperParameters()
{
  this->Superclass::UpdateMapperParameters();
  this->UpdateTimeBudget();
  if (this->Processes > 1 && this->EnvironmentVisible && !this->WarnedEnvironment)
  {
    vtkWarningMacro(<< "EnvironmentVisible: with " << this->Processes
                    << " processes the environment lights the volume but is not drawn behind it "
                       "(ParaView's compositing keeps of each process's image only the pixels "
                       "inside its data's bounds); the background is the view's.");
    this->WarnedEnvironment = true;
  }
}

void vtkVisSweepVolumeRepresentation::SetSamplesPerFrame(int samples)
{
  WarnOutOfRange(this, "SamplesPerFrame", samples, 1, 1 << 16);
  this->GetVisSweepMapper()->SetSamplesPerFrame(samples);
}

void vtkVisSweepVolumeRepresentation::SetMaximumSamples(int samples)
{
  WarnOutOfRange(this, "MaximumSamples", samples, 1, 1 << 30);
  this->MaximumSamples = std::min(std::max(samples, 1), 1 << 30);
  this->UpdateDistributedSettings();
}

void vtkVisSweepVolumeRepresentation::SetEnvironmentIntensity(double intensity)
{
  if (intensity < 0)
  {
    vtkWarningMacro(<< "EnvironmentIntensity " << intensity << " is negative: the mapper uses 0.");
  }
  this->GetVisSweepMapper()->SetEnvironmentIntensity(intensity);
}

void vtkVisSweepVolumeRepresentation::SetEnvironmentVisible(bool visible)
{
  this->EnvironmentVisible = visible;
  this->WarnedEnvironment = false;
  // Distributed, the environment is not drawn (the class documentation says why).
  this->GetVisSweepMapper()->SetEnvironmentVisible(visible && this->Processes <= 1);
  this->Modified();
}

void vtkVisSweepVolumeRepresentation::SetExposure(double exposure)
{
  if (exposure < 0)
  {
    vtkWarningMacro(<< "Exposure " << exposure << " is negative: the mapper uses 0.");
  }
  this->GetVisSweepMapper()->SetExposure(exposure);
}

void vtkVisSweepVolumeRepresentation::SetToneMapping(bool toneMapping)
{
  this->GetVisSweepMapper()->SetToneMapping(toneMapping);
}

void vtkVisSweepVolumeRepresentation::SetSeed(int seed)
{
  WarnOutOfRange(this, "Seed", seed, 0, VTK_INT_MAX);
  this->Seed = std::max(seed, 0);
  this->UpdateDistributedSettings();
}

void vtkVisSweepVolumeRepresentation::SetMaximumScatteringEvents(int events)
{
  // The mapper refuses a value outside its range at render time, naming the setting.
  WarnOutOfRange(this, "MaximumScatteringEvents", events, 1, 100000);
  this->GetVisSweepMapper()->SetMaximumScatteringEvents(events);
}

void vtkVisSweepVolumeRepresentation::SetScatteringAnisotropy(double g)
{
  if (!(g > -1.0 && g < 1.0))
  {
    vtkWarningMacro(<< "ScatteringAnisotropy " << g
                    << " is outside (-1, 1): the mapper refuses to render with it.");
  }
  this->GetVisSweepMapper()->SetScatteringAnisotropy(g);
}

void vtkVisSweepVolumeRepresentation::SetMultipleImportanceSampling(int mode)
{
  WarnOutOfRange(this, "MultipleImportanceSampling", mode, 0, 3);
  this->GetVisSweepMapper()->SetMultipleImportanceSampling(mode);
}

void vtkVisSweepVolumeRepresentation::SetEnvironmentFileName(const char* fileName)
{
  const std::string name = fileName ? fileName : "";
  if (name == this->EnvironmentFileName)
  {
    return;
  }
  this->EnvironmentFileName = name;
  if (name.empty())
  {
    this->GetVisSweepMapper()->SetEnvironmentConnection(this->WhiteSky->GetOutputPort());
  }
  else
  {
    this->EnvironmentReader->SetFileName(name.c_str());
    this->GetVisSweepMapper()->SetEnvironmentConnection(this->EnvironmentReader->GetOutputPort());
  }
  this->Modified();
}

void vtkVisSweepVolumeRepresentation::SetEnvironmentRotation(double degrees)
{
  if (degrees == this->EnvironmentRotation)
  {
    return;
  }
  this->EnvironmentRotation = degrees;
  this->EnvironmentReader->SetRotationDegrees(degrees);
  this->Modified();
}

int vtkVisSweepVolumeRepresentation::GetAccumulatedSamples()
{
  const int local = this->GetVisSweepMapper()->GetAccumulatedSamples();
  // Distributed: all processes' samples behind the image shown, while it is this one's last frame.
  return this->CombinedSamples >= 0 && local == this->CombinedLocalSamples ? this->CombinedSamples : local;
}

bool vtkVisSweepVolumeRepresentation::IsConverged()
{
  vtkVisibilitySweepVolumeMapper* mapper = this->GetVisSweepMapper();
  if (this->BudgetSpent && this->TimeBudget > 0.0 &&
    mapper->GetRenderMode() == vtkVisibilitySweepVolumeMapper::MonteCarlo)
  {
    // The budget held the accumulation; if the render after that restarted it (the camera moved),
    // the next render counts again.
    return mapper->GetAccumulationResetCount() == this->BudgetResets;
  }
  const bool local = mapper->IsConverged();
  if (this->CombinedSamples >= 0 && this->GetVisSweepMapper()->GetAccumulatedSamples() == this->CombinedLocalSamples &&
    this->GetVisSweepMapper()->GetRenderMode() == vtkVisibilitySweepVolumeMapper::MonteCarlo)
  {
    // Every process's share reached (the first's is the largest, but Auto's probes may lag another).
    return local && this->CombinedSamples >= this->MaximumSamples;
  }
  return local;
}

const char* vtkVisSweepVolumeRepresentation::GetLastError()
{
  return this->GetVisSweepMapper()->GetLastError();
}

void vtkVisSweepVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "EnvironmentFileName: "
     << (this->EnvironmentFileName.empty() ? "(none: white sky)" : this->EnvironmentFileName) << "\n";
  os << indent << "EnvironmentRotation: " << this->EnvironmentRotation << "\n";
  os << indent << "Processes: " << this->Processes << " (this one " << this->ProcessId << ")\n";
  os << indent << "Seed: " << this->Seed << ", MaximumSamples: " << this->MaximumSamples << "\n";
  os << indent << "TimeBudget: " << this->TimeBudget << " s (0: none), AccumulationTime: "
     << this->AccumulationSeconds << " s, next frame " << this->NextFrameSeconds << " s"
     << (this->BudgetSpent ? ", spent" : "") << "\n";
  os << indent << "Mapper:\n";
  this->VolumeMapper->PrintSelf(os, indent.GetNextIndent());
}
