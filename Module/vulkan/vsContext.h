// vsContext.h — a Vulkan instance, one physical device and its compute queue.
//
// Device choice: a discrete GPU, then an integrated one, then a virtual one,
// then a CPU device (lavapipe). VISSWEEP_DEVICE overrides it with an index
// (as listed by `vissweep info`) or a case-insensitive substring of the name.
// Validation layers are enabled in Debug builds (or with VISSWEEP_VALIDATION=1)
// when installed; every message they print is counted.
#ifndef vsContext_h
#define vsContext_h

#include "vsVulkan.h"
#include "vissweepCoreModule.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace vs
{
class ComputePipeline;
class PipelineCache;

/** What a device is and the limits that matter to VisSweep. */
struct VISSWEEPCORE_EXPORT DeviceInfo
{
  uint32_t Index = 0;
  std::string Name;
  std::string Type; // "discrete GPU", "integrated GPU", "virtual GPU", "CPU", "other"
  std::string Driver;
  std::string ApiVersion;
  uint64_t DeviceLocalHeapBytes = 0;
  uint32_t MaxImageDimension3D = 0;
  uint32_t MaxImageDimension2D = 0;
  uint64_t MaxStorageBufferRange = 0;
  uint64_t MaxTexelBufferElements = 0;
  uint32_t MaxComputeWorkGroupCount[3] = { 0, 0, 0 };
  uint32_t MaxPushConstantsSize = 0;
  uint32_t SubgroupSize = 0;
  uint32_t ApiVersionNumber = 0;   // VK_MAKE_API_VERSION of the device
  uint32_t DriverId = 0;           // VkDriverId (VK_DRIVER_ID_MESA_LLVMPIPE = 13 is lavapipe); 0 = unknown
  uint32_t SubgroupStages = 0;     // VkShaderStageFlags with subgroup operations
  uint32_t SubgroupOperations = 0; // VkSubgroupFeatureFlags
  bool FloatAtomicAdd = false;
  bool WriteWithoutFormat = false; // shaderStorageImageWriteWithoutFormat
  bool Timestamps = false;
  double TimestampPeriodNs = 0.0;

  /** Several lines, one per property, as `vissweep info` prints them. */
  std::string Describe() const;

  /** What the kernels need and this device lacks, named, comma-separated (Vulkan 1.1; subgroup
   *  basic, vote, ballot and arithmetic operations in compute shaders); empty when it has all. */
  std::string MissingFeatures() const;

  /** The choices made for the driver come from what it reports, not assumed (docs/reference.md,
   *  "Drivers"). Whether the driver has a loop limiter: llvmpipe (lavapipe) ends every loop of an
   *  invocation after 65,535 back-edges in all, silently, so the render kernel keeps a loop budget
   *  below that there (mc_params.h VS_LOOP_BUDGET); other drivers get none (vsMonteCarloPass). */
  bool LoopLimited() const;
  /** Workgroup width of the kernels that run one row of work per subgroup (the sweeps' filter and
   *  projection): the subgroup size, within [8, 64] (8 on lavapipe, 32 on NVIDIA, 64 on AMD). */
  uint32_t RowWorkgroupWidth() const;
};

struct VISSWEEPCORE_EXPORT ContextOptions
{
  /** Index or name substring; empty = $VISSWEEP_DEVICE, else the best device. */
  std::string DeviceSelector;
  /** -1 = default (on in Debug builds or with VISSWEEP_VALIDATION=1), 0 off, 1 on. */
  int Validation = -1;
  /** Whether pipelines get their modules with the specialization constants folded in ahead of the
   *  driver (vsSpirvSpecialization.h): -1 = default (on, unless VISSWEEP_SPECIALIZE=0), 0 off, 1 on. */
  int SpecializeModules = -1;
};

class VISSWEEPCORE_EXPORT Context
{
public:
  /** Creates a context. Throws VulkanUnavailableError or NoDeviceError. */
  static std::shared_ptr<Context> Create(const ContextOptions& options = ContextOptions());

  /** The process-wide context, created on first use (thread-safe). Throws like Create. */
  static std::shared_ptr<Context> Default();

  /** Every device the loader reports (no context is kept). Throws VulkanUnavailableError. */
  static std::vector<DeviceInfo> ListDevices();

  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const DeviceInfo& Info() const { return this->Info_; }
  vk::Device Device() const { return this->Device_; }
  vk::PhysicalDevice Physical() const { return this->Physical_; }
  vk::Queue Queue() const { return this->Queue_; }
  uint32_t QueueFamily() const { return this->QueueFamily_; }
  vk::CommandPool CommandPool() const { return this->CommandPool_; }
  bool ValidationEnabled() const { return this->ValidationEnabled_; }
  /** Whether its pipelines fold their specialization constants into the module before the driver
   *  compiles it (ContextOptions::SpecializeModules). */
  bool SpecializesModules() const { return this->SpecializesModules_; }

  /** Validation errors and warnings reported since the context was made. */
  uint64_t ValidationMessageCount() const;

  /** A memory type index with the given properties; -1 if none. */
  int FindMemoryType(uint32_t typeBits, vk::MemoryPropertyFlags properties) const;

  /** Guards the queue: submissions from several threads take turns. */
  std::mutex& QueueMutex() { return this->QueueMutex_; }

  /** The pipeline compiled under `key`, made by `make` on first use. Compiling a pipeline takes
   *  seconds on lavapipe, so every pass of every mapper in the process shares them. Thread-safe:
   *  a caller of one key waits while another thread makes that key's pipeline, not another's (a
   *  mapper makes its first render pipeline on a second thread while it uploads the scene). If
   *  `make` throws, the next call of the key tries again. */
  std::shared_ptr<ComputePipeline> Pipeline(
    const std::string& key, const std::function<std::shared_ptr<ComputePipeline>()>& make);

  /** How many pipelines the context holds. A compiled pipeline stays while the cache has room: past
   *  PipelineLimit() the least recently used ones that nothing else holds (no pass keeps them) are
   *  let go, so churning through many variants of the kernels (strategies, samplers, estimators,
   *  cropping, ...) does not grow the process without bound (issue 35: ~100-300 KB of compiled
   *  code per lavapipe pipeline, all kept for the process before). */
  size_t PipelineCount() const;
  /** Pipelines ever compiled (made) by this context: grows by one per compile, also when the
   *  compile let another go (memory checks tell a compile from a leak by this count). */
  uint64_t PipelineBuilds() const { return this->PipelineBuilds_.load(); }
  /** The cache's bound (default 96 pipelines; at least 1). Pipelines held elsewhere are never let go,
   *  so the count may exceed it while passes hold them. */
  void SetPipelineLimit(size_t limit);
  size_t PipelineLimit() const;
  /** The names of the pipelines the context holds, e.g. to tell which kernels a frame made. */
  std::vector<std::string> PipelineNames() const;

  /** Counts messages (called by the debug messenger). */
  void CountValidationMessage();

  /** The driver's pipeline cache every pipeline of this context is created with, kept on disk across
   *  runs (vsPipelineCache.h; saved after each compile); null when the driver could not make one. */
  PipelineCache* GetPipelineCache() const { return this->PipelineCache_.get(); }
  vk::PipelineCache PipelineCacheHandle() const;

private:
  Context() = default;
  void Initialize(const ContextOptions& options);

  vk::Instance Instance_;
  vk::DebugUtilsMessengerEXT Messenger_;
  vk::PhysicalDevice Physical_;
  vk::Device Device_;
  vk::Queue Queue_;
  uint32_t QueueFamily_ = 0;
  vk::CommandPool CommandPool_;
  DeviceInfo Info_;
  bool ValidationEnabled_ = false;
  bool SpecializesModules_ = true;
  uint64_t ValidationMessages_ = 0;
  mutable std::mutex Mutex_;
  std::mutex QueueMutex_;
  struct PipelineSlot
  {
    std::once_flag Made;
    std::shared_ptr<ComputePipeline> Pipeline; // set once, inside Made
    std::atomic<bool> Ready{ false };
    uint64_t LastUse = 0; // the context's use clock at the last Pipeline() call of the key
  };
  // Lets go of the least recently used ready pipelines nothing else holds, other than `keep`, while
  // more than PipelineLimit_ are ready. Called with PipelineMutex_ held.
  void TrimPipelines(const std::string& keep);
  uint64_t UseClock_ = 0;
  size_t PipelineLimit_ = 96;
  std::atomic<uint64_t> PipelineBuilds_{ 0 };
  mutable std::mutex PipelineMutex_; // guards the map, not the compiles
  std::map<std::string, std::shared_ptr<PipelineSlot>> Pipelines_;
  std::unique_ptr<PipelineCache> PipelineCache_;
};
}

#endif
