#include "vsContext.h"
#include "vsError.h"
#include "vsPipeline.h"
#include "vsPipelineCache.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <iostream>
#include <sstream>

VULKAN_HPP_DEFAULT_DISPATCH_LOADER_DYNAMIC_STORAGE

namespace vs
{
namespace
{
std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string VersionString(uint32_t v)
{
  std::ostringstream os;
  os << VK_API_VERSION_MAJOR(v) << "." << VK_API_VERSION_MINOR(v) << "." << VK_API_VERSION_PATCH(v);
  return os.str();
}

std::string TypeName(vk::PhysicalDeviceType t)
{
  switch (t)
  {
    case vk::PhysicalDeviceType::eDiscreteGpu:
      return "discrete GPU";
    case vk::PhysicalDeviceType::eIntegratedGpu:
      return "integrated GPU";
    case vk::PhysicalDeviceType::eVirtualGpu:
      return "virtual GPU";
    case vk::PhysicalDeviceType::eCpu:
      return "CPU";
    default:
      return "other";
  }
}

int TypeRank(vk::PhysicalDeviceType t)
{
  switch (t)
  {
    case vk::PhysicalDeviceType::eDiscreteGpu:
      return 4;
    case vk::PhysicalDeviceType::eIntegratedGpu:
      return 3;
    case vk::PhysicalDeviceType::eVirtualGpu:
      return 2;
    case vk::PhysicalDeviceType::eCpu:
      return 1;
    default:
      return 0;
  }
}

bool HasExtension(vk::PhysicalDevice pd, const char* name)
{
  for (const auto& e : pd.enumerateDeviceExtensionProperties())
  {
    if (std::string(e.extensionName.data()) == name)
    {
      return true;
    }
  }
  return false;
}

int ComputeQueueFamily(vk::PhysicalDevice pd)
{
  auto families = pd.getQueueFamilyProperties();
  // Prefer a family with compute and timestamps.
  int best = -1;
  for (uint32_t i = 0; i < families.size(); ++i)
  {
    if (families[i].queueFlags & vk::QueueFlagBits::eCompute)
    {
      if (best < 0 || (families[best].timestampValidBits == 0 && families[i].timestampValidBits > 0))
      {
        best = static_cast<int>(i);
      }
    }
  }
  return best;
}

DeviceInfo Describe(vk::PhysicalDevice pd, uint32_t index)
{
  DeviceInfo info;
  info.Index = index;
  vk::PhysicalDeviceSubgroupProperties subgroup;
  vk::PhysicalDeviceDriverProperties driver;
  vk::PhysicalDeviceProperties2 props2;
  props2.pNext = &subgroup;
  subgroup.pNext = &driver;
  pd.getProperties2(&props2);
  const auto& p = props2.properties;
  info.Name = p.deviceName.data();
  info.Type = TypeName(p.deviceType);
  info.Driver = std::string(driver.driverName.data()) + " " + driver.driverInfo.data();
  info.ApiVersion = VersionString(p.apiVersion);
  info.MaxImageDimension3D = p.limits.maxImageDimension3D;
  info.MaxImageDimension2D = p.limits.maxImageDimension2D;
  info.MaxStorageBufferRange = p.limits.maxStorageBufferRange;
  info.MaxTexelBufferElements = p.limits.maxTexelBufferElements;
  for (int i = 0; i < 3; ++i)
  {
    info.MaxComputeWorkGroupCount[i] = p.limits.maxComputeWorkGroupCount[i];
  }
  info.MaxPushConstantsSize = p.limits.maxPushConstantsSize;
  info.SubgroupSize = subgroup.subgroupSize;
  info.SubgroupStages = static_cast<uint32_t>(subgroup.supportedStages);
  info.SubgroupOperations = static_cast<uint32_t>(subgroup.supportedOperations);
  info.ApiVersionNumber = p.apiVersion;
  info.DriverId = static_cast<uint32_t>(driver.driverID);
  info.TimestampPeriodNs = p.limits.timestampPeriod;
  int family = ComputeQueueFamily(pd);
  info.Timestamps =
    family >= 0 && pd.getQueueFamilyProperties()[family].timestampValidBits > 0;
  auto mem = pd.getMemoryProperties();
  for (uint32_t h = 0; h < mem.memoryHeapCount; ++h)
  {
    if (mem.memoryHeaps[h].flags & vk::MemoryHeapFlagBits::eDeviceLocal)
    {
      info.DeviceLocalHeapBytes = std::max<uint64_t>(info.DeviceLocalHeapBytes, mem.memoryHeaps[h].size);
    }
  }
  if (HasExtension(pd, VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME))
  {
    vk::PhysicalDeviceShaderAtomicFloatFeaturesEXT atomics;
    vk::PhysicalDeviceFeatures2 f2;
    f2.pNext = &atomics;
    pd.getFeatures2(&f2);
    info.FloatAtomicAdd = atomics.shaderBufferFloat32AtomicAdd == VK_TRUE;
  }
  return info;
}

VKAPI_ATTR VkBool32 VKAPI_CALL DebugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
  VkDebugUtilsMessageTypeFlagsEXT, const VkDebugUtilsMessengerCallbackDataEXT* data, void* user)
{
  if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT)
  {
    static_cast<Context*>(user)->CountValidationMessage();
    std::cerr << "VisSweep Vulkan validation: " << (data && data->pMessage ? data->pMessage : "")
              << std::endl;
  }
  return VK_FALSE;
}

// Opens the loader once per process; throws when it is missing.
void LoadVulkan()
{
  static std::once_flag once;
  static std::string failure;
  // Never unloaded: contexts held in statics are destroyed at exit, after this function's statics.
  static vk::DynamicLoader* loader = nullptr;
  std::call_once(once, [] {
    try
    {
      loader = new vk::DynamicLoader();
      auto getProc = loader->getProcAddress<PFN_vkGetInstanceProcAddr>("vkGetInstanceProcAddr");
      if (!getProc)
      {
        failure = "the Vulkan loader has no vkGetInstanceProcAddr";
        return;
      }
      VULKAN_HPP_DEFAULT_DISPATCHER.init(getProc);
    }
    catch (const std::exception& e)
    {
      failure = std::string("cannot open the Vulkan loader (libvulkan.so.1): ") + e.what() +
        " — install libvulkan1 and a driver (mesa-vulkan-drivers for lavapipe)";
    }
  });
  if (!failure.empty())
  {
    throw VulkanUnavailableError(failure);
  }
}

vk::Instance MakeInstance(bool wantValidation, bool& validationOn, const std::vector<const char*>& extra)
{
  vk::ApplicationInfo app;
  app.pApplicationName = "VisSweep";
  app.apiVersion = VK_API_VERSION_1_1;
  std::vector<const char*> layers;
  std::vector<const char*> extensions = extra;
  validationOn = false;
  if (wantValidation)
  {
    bool haveLayer = false;
    for (const auto& l : vk::enumerateInstanceLayerProperties())
    {
      haveLayer |= std::string(l.layerName.data()) == "VK_LAYER_KHRONOS_validation";
    }
    bool haveUtils = false;
    for (const auto& e : vk::enumerateInstanceExtensionProperties())
    {
      haveUtils |= std::string(e.extensionName.data()) == VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    }
    if (haveLayer && haveUtils)
    {
      layers.push_back("VK_LAYER_KHRONOS_validation");
      extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
      validationOn = true;
    }
  }
  vk::InstanceCreateInfo ci;
  ci.pApplicationInfo = &app;
  ci.enabledLayerCount = static_cast<uint32_t>(layers.size());
  ci.ppEnabledLayerNames = layers.data();
  ci.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  ci.ppEnabledExtensionNames = extensions.data();
  try
  {
    return vk::createInstance(ci);
  }
  catch (const vk::SystemError& e)
  {
    throw VulkanUnavailableError(std::string("cannot create a Vulkan instance: ") + e.what() +
      " — no Vulkan driver (ICD) is installed or usable (try mesa-vulkan-drivers)");
  }
}

std::vector<vk::PhysicalDevice> Devices(vk::Instance instance)
{
  std::vector<vk::PhysicalDevice> all = instance.enumeratePhysicalDevices();
  return all;
}
}

std::string DeviceInfo::Describe() const
{
  std::ostringstream os;
  os << "device " << this->Index << ": " << this->Name << " (" << this->Type << ")\n";
  os << "  driver:                  " << this->Driver << "\n";
  os << "  Vulkan API:              " << this->ApiVersion << "\n";
  os << "  device-local heap:       " << (this->DeviceLocalHeapBytes >> 20) << " MiB\n";
  os << "  max 3D image dimension:  " << this->MaxImageDimension3D << "\n";
  os << "  max 2D image dimension:  " << this->MaxImageDimension2D << "\n";
  os << "  max storage buffer:      " << (this->MaxStorageBufferRange >> 20) << " MiB ("
     << this->MaxStorageBufferRange << " bytes)\n";
  os << "  max workgroup count:     " << this->MaxComputeWorkGroupCount[0] << " x "
     << this->MaxComputeWorkGroupCount[1] << " x " << this->MaxComputeWorkGroupCount[2] << "\n";
  os << "  max push constants:      " << this->MaxPushConstantsSize << " bytes\n";
  os << "  subgroup size:           " << this->SubgroupSize << "\n";
  os << "  driver loop limiter:     "
     << (this->LoopLimited() ? "yes: the render kernel keeps a loop budget" : "no: no loop budget") << "\n";
  os << "  row workgroup width:     " << this->RowWorkgroupWidth() << " (sweep filter and projection)\n";
  const std::string missing = this->MissingFeatures();
  if (!missing.empty())
  {
    os << "  MISSING for VisSweep:    " << missing << "\n";
  }
  os << "  float32 atomic add:      " << (this->FloatAtomicAdd ? "yes" : "no") << "\n";
  os << "  compute timestamps:      "
     << (this->Timestamps ? "yes (" + std::to_string(this->TimestampPeriodNs) + " ns/tick)" : "no")
     << "\n";
  return os.str();
}

std::string DeviceInfo::MissingFeatures() const
{
  std::vector<std::string> missing;
  if (VK_API_VERSION_MAJOR(this->ApiVersionNumber) < 1 ||
    (VK_API_VERSION_MAJOR(this->ApiVersionNumber) == 1 && VK_API_VERSION_MINOR(this->ApiVersionNumber) < 1))
  {
    missing.push_back("Vulkan 1.1 (the device reports " + this->ApiVersion + ")");
  }
  if ((this->SubgroupStages & VK_SHADER_STAGE_COMPUTE_BIT) == 0u)
  {
    missing.push_back("subgroup operations in compute shaders");
  }
  const std::pair<uint32_t, const char*> operations[] = { { VK_SUBGROUP_FEATURE_BASIC_BIT, "basic" },
    { VK_SUBGROUP_FEATURE_VOTE_BIT, "vote" }, { VK_SUBGROUP_FEATURE_BALLOT_BIT, "ballot" },
    { VK_SUBGROUP_FEATURE_ARITHMETIC_BIT, "arithmetic" } };
  for (const auto& op : operations)
  {
    if ((this->SubgroupOperations & op.first) == 0u)
    {
      missing.push_back(std::string("subgroup ") + op.second + " operations in compute shaders");
    }
  }
  std::string out;
  for (const auto& m : missing)
  {
    out += (out.empty() ? "" : ", ") + m;
  }
  return out;
}

bool DeviceInfo::LoopLimited() const
{
  // An unknown driver (no VK_KHR_driver_properties) keeps the budget: it costs little.
  return this->DriverId == static_cast<uint32_t>(VK_DRIVER_ID_MESA_LLVMPIPE) || this->DriverId == 0u;
}

uint32_t DeviceInfo::RowWorkgroupWidth() const
{
  return std::clamp(this->SubgroupSize, 8u, 64u);
}

std::shared_ptr<Context> Context::Create(const ContextOptions& options)
{
  std::shared_ptr<Context> ctx(new Context());
  ctx->Initialize(options);
  return ctx;
}

std::shared_ptr<Context> Context::Default()
{
  static std::mutex m;
  static std::shared_ptr<Context> instance;
  std::lock_guard<std::mutex> lock(m);
  if (!instance)
  {
    instance = Create();
  }
  return instance;
}

std::vector<DeviceInfo> Context::ListDevices()
{
  LoadVulkan();
  bool validation = false;
  vk::Instance instance = MakeInstance(false, validation, {});
  VULKAN_HPP_DEFAULT_DISPATCHER.init(instance);
  std::vector<DeviceInfo> result;
  auto devices = Devices(instance);
  for (uint32_t i = 0; i < devices.size(); ++i)
  {
    result.push_back(vs::Describe(devices[i], i));
  }
  instance.destroy();
  return result;
}

void Context::Initialize(const ContextOptions& options)
{
  LoadVulkan();
  bool wantValidation = false;
#ifndef NDEBUG
  wantValidation = true;
#endif
  if (const char* v = std::getenv("VISSWEEP_VALIDATION"))
  {
    wantValidation = std::string(v) == "1";
  }
  if (options.Validation >= 0)
  {
    wantValidation = options.Validation == 1;
  }
  if (const char* v = std::getenv("VISSWEEP_SPECIALIZE"))
  {
    this->SpecializesModules_ = std::string(v) != "0";
  }
  if (options.SpecializeModules >= 0)
  {
    this->SpecializesModules_ = options.SpecializeModules == 1;
  }
  this->Instance_ = MakeInstance(wantValidation, this->ValidationEnabled_, {});
  VULKAN_HPP_DEFAULT_DISPATCHER.init(this->Instance_);

  if (this->ValidationEnabled_)
  {
    vk::DebugUtilsMessengerCreateInfoEXT mci;
    mci.messageSeverity = vk::DebugUtilsMessageSeverityFlagBitsEXT::eWarning |
      vk::DebugUtilsMessageSeverityFlagBitsEXT::eError;
    mci.messageType = vk::DebugUtilsMessageTypeFlagBitsEXT::eGeneral |
      vk::DebugUtilsMessageTypeFlagBitsEXT::eValidation |
      vk::DebugUtilsMessageTypeFlagBitsEXT::ePerformance;
    mci.pfnUserCallback = DebugCallback;
    mci.pUserData = this;
    this->Messenger_ = this->Instance_.createDebugUtilsMessengerEXT(mci);
  }

  auto devices = Devices(this->Instance_);
  std::vector<DeviceInfo> infos;
  std::ostringstream available;
  for (uint32_t i = 0; i < devices.size(); ++i)
  {
    infos.push_back(vs::Describe(devices[i], i));
    available << (i ? ", " : "") << i << ": " << infos.back().Name;
  }
  if (devices.empty())
  {
    throw NoDeviceError("no Vulkan device found: the loader lists none (install mesa-vulkan-drivers "
                        "for the lavapipe CPU device)");
  }

  std::string selector = options.DeviceSelector;
  if (selector.empty())
  {
    if (const char* env = std::getenv("VISSWEEP_DEVICE"))
    {
      selector = env;
    }
  }

  int chosen = -1;
  if (!selector.empty())
  {
    bool numeric = std::all_of(selector.begin(), selector.end(), [](unsigned char c) { return std::isdigit(c); });
    for (uint32_t i = 0; i < devices.size() && chosen < 0; ++i)
    {
      bool match = numeric ? std::to_string(i) == selector
                           : Lower(infos[i].Name).find(Lower(selector)) != std::string::npos;
      if (match && ComputeQueueFamily(devices[i]) >= 0)
      {
        chosen = static_cast<int>(i);
      }
    }
    if (chosen < 0)
    {
      std::string list = available.str();
      throw NoDeviceError("VISSWEEP_DEVICE='" + selector +
        "' matches no Vulkan device with a compute queue; available: " + list);
    }
    if (!infos[chosen].MissingFeatures().empty())
    {
      throw NoDeviceError("the Vulkan device '" + infos[chosen].Name + "' (" + infos[chosen].Driver +
        ") lacks what VisSweep's kernels need: " + infos[chosen].MissingFeatures());
    }
  }
  else
  {
    int bestRank = -1;
    for (uint32_t i = 0; i < devices.size(); ++i)
    {
      int rank = TypeRank(devices[i].getProperties().deviceType);
      if (ComputeQueueFamily(devices[i]) >= 0 && infos[i].MissingFeatures().empty() && rank > bestRank)
      {
        bestRank = rank;
        chosen = static_cast<int>(i);
      }
    }
    if (chosen < 0)
    {
      // Name what each device lacks (a driver without the subgroup operations the kernels use).
      std::string lacks;
      for (uint32_t i = 0; i < devices.size(); ++i)
      {
        const std::string missing =
          ComputeQueueFamily(devices[i]) < 0 ? std::string("a compute queue") : infos[i].MissingFeatures();
        lacks += (i ? "; " : "") + infos[i].Name + " lacks " + missing;
      }
      throw NoDeviceError("no Vulkan device can run VisSweep's kernels: " + lacks);
    }
  }

  this->Physical_ = devices[chosen];
  this->Info_ = infos[chosen];
  this->QueueFamily_ = static_cast<uint32_t>(ComputeQueueFamily(this->Physical_));

  float priority = 1.0f;
  vk::DeviceQueueCreateInfo qci;
  qci.queueFamilyIndex = this->QueueFamily_;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;

  std::vector<const char*> extensions;
  vk::PhysicalDeviceShaderAtomicFloatFeaturesEXT atomics;
  vk::PhysicalDeviceFeatures2 features;
  if (this->Info_.FloatAtomicAdd)
  {
    extensions.push_back(VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
    atomics.shaderBufferFloat32AtomicAdd = VK_TRUE;
    features.pNext = &atomics;
  }
  // Sweeps write visibility in the grid's storage format (r8, r16 or r32f) from one shader.
  vk::PhysicalDeviceFeatures supported = this->Physical_.getFeatures();
  features.features.shaderStorageImageWriteWithoutFormat = supported.shaderStorageImageWriteWithoutFormat;
  this->Info_.WriteWithoutFormat = supported.shaderStorageImageWriteWithoutFormat == VK_TRUE;
  vk::DeviceCreateInfo dci;
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  dci.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  dci.ppEnabledExtensionNames = extensions.data();
  dci.pNext = &features;
  try
  {
    this->Device_ = this->Physical_.createDevice(dci);
  }
  catch (const vk::SystemError& e)
  {
    throw NoDeviceError(std::string("cannot create a logical device on '") + this->Info_.Name + "': " + e.what());
  }
  // No VULKAN_HPP_DEFAULT_DISPATCHER.init(Device_): the dispatcher is one per process, and a device's
  // own entry points (vkGetDeviceProcAddr) are valid for that device only. With them, every context's
  // device calls went to the last device made: after a validation context (its layer's entry points)
  // was destroyed, the default context's calls, its destruction at exit included, crashed in the layer.
  // The instance's entry points (the loader's trampolines) dispatch each call by its device.
  this->Queue_ = this->Device_.getQueue(this->QueueFamily_, 0);
  vk::CommandPoolCreateInfo pci;
  pci.queueFamilyIndex = this->QueueFamily_;
  pci.flags = vk::CommandPoolCreateFlagBits::eResetCommandBuffer;
  this->CommandPool_ = this->Device_.createCommandPool(pci);
  try
  {
    this->PipelineCache_ = std::make_unique<PipelineCache>(
      this->Device_, this->Physical_.getProperties(), PipelineCache::DefaultDirectory());
  }
  catch (const vk::SystemError&)
  {
    // Without a cache pipelines are compiled as before.
  }
}

vk::PipelineCache Context::PipelineCacheHandle() const
{
  return this->PipelineCache_ ? this->PipelineCache_->Handle() : vk::PipelineCache();
}

Context::~Context()
{
  this->Pipelines_.clear(); // before the device they live on
  this->PipelineCache_.reset();
  if (this->Device_)
  {
    this->Device_.waitIdle();
    if (this->CommandPool_)
    {
      this->Device_.destroyCommandPool(this->CommandPool_);
    }
    this->Device_.destroy();
  }
  if (this->Instance_)
  {
    if (this->Messenger_)
    {
      this->Instance_.destroyDebugUtilsMessengerEXT(this->Messenger_);
    }
    this->Instance_.destroy();
  }
}

std::shared_ptr<ComputePipeline> Context::Pipeline(
  const std::string& key, const std::function<std::shared_ptr<ComputePipeline>()>& make)
{
  std::shared_ptr<PipelineSlot> slot;
  {
    std::lock_guard<std::mutex> lock(this->PipelineMutex_);
    auto& entry = this->Pipelines_[key];
    if (!entry)
    {
      entry = std::make_shared<PipelineSlot>();
    }
    entry->LastUse = ++this->UseClock_;
    slot = entry;
  }
  bool made = false;
  std::call_once(slot->Made,
    [&]()
    {
      slot->Pipeline = make();
      slot->Ready = true;
      made = true;
    });
  if (made)
  {
    if (this->PipelineCache_)
    {
      this->PipelineCache_->Save(); // the next process finds it (a failure only costs that compile)
    }
    ++this->PipelineBuilds_;
    std::lock_guard<std::mutex> lock(this->PipelineMutex_);
    this->TrimPipelines(key);
  }
  return slot->Pipeline;
}

void Context::TrimPipelines(const std::string& keep)
{
  size_t ready = 0;
  for (const auto& entry : this->Pipelines_)
  {
    ready += entry.second->Ready ? 1 : 0;
  }
  while (ready > this->PipelineLimit_)
  {
    // Only the cache holds a candidate (use count 1): no pass keeps it, and no batch records it (a
    // pass holds what it dispatches; batches wait for their fence when submitted). A caller that
    // took the slot before it left the map keeps the slot, and with it the pipeline.
    auto oldest = this->Pipelines_.end();
    for (auto it = this->Pipelines_.begin(); it != this->Pipelines_.end(); ++it)
    {
      const PipelineSlot& s = *it->second;
      if (s.Ready && it->first != keep && s.Pipeline.use_count() <= 1 &&
        (oldest == this->Pipelines_.end() || s.LastUse < oldest->second->LastUse))
      {
        oldest = it;
      }
    }
    if (oldest == this->Pipelines_.end())
    {
      break; // the rest are in use
    }
    this->Pipelines_.erase(oldest);
    --ready;
  }
}

void Context::SetPipelineLimit(size_t limit)
{
  std::lock_guard<std::mutex> lock(this->PipelineMutex_);
  this->PipelineLimit_ = std::max<size_t>(1, limit);
  this->TrimPipelines(std::string());
}

size_t Context::PipelineLimit() const
{
  std::lock_guard<std::mutex> lock(this->PipelineMutex_);
  return this->PipelineLimit_;
}

size_t Context::PipelineCount() const
{
  std::lock_guard<std::mutex> lock(this->PipelineMutex_);
  size_t n = 0;
  for (const auto& entry : this->Pipelines_)
  {
    n += entry.second->Ready ? 1 : 0;
  }
  return n;
}

std::vector<std::string> Context::PipelineNames() const
{
  std::lock_guard<std::mutex> lock(this->PipelineMutex_);
  std::vector<std::string> names;
  for (const auto& entry : this->Pipelines_)
  {
    if (entry.second->Ready)
    {
      names.push_back(entry.first);
    }
  }
  return names;
}

uint64_t Context::ValidationMessageCount() const
{
  std::lock_guard<std::mutex> lock(this->Mutex_);
  return this->ValidationMessages_;
}

void Context::CountValidationMessage()
{
  std::lock_guard<std::mutex> lock(this->Mutex_);
  ++this->ValidationMessages_;
}

int Context::FindMemoryType(uint32_t typeBits, vk::MemoryPropertyFlags properties) const
{
  auto mem = this->Physical_.getMemoryProperties();
  for (uint32_t i = 0; i < mem.memoryTypeCount; ++i)
  {
    if ((typeBits & (1u << i)) && (mem.memoryTypes[i].propertyFlags & properties) == properties)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}
}
