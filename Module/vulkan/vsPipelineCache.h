// vsPipelineCache.h — the driver's compiled pipelines kept across runs (issue 39, item 0): a Vulkan
// pipeline cache loaded from a file at the context's start and written back after each pipeline the
// context compiles, so a later process finds them (drivers that fill VkPipelineCache: NVIDIA, AMD,
// Intel; Mesa's lavapipe 22.3 keeps nothing in it, only its own shader cache, ~/.cache/mesa_shader_cache).
//
// The file: $VISSWEEP_PIPELINE_CACHE_DIR, else $XDG_CACHE_HOME/vissweep, else $HOME/.cache/vissweep,
// named by the device and its driver (vendor, device id, driver version, pipelineCacheUUID), so another
// GPU or driver never reads it. VISSWEEP_PIPELINE_CACHE_DIR=off leaves the disk out. A file that is not
// this device's cache as VisSweep wrote it (truncated, corrupt, another device's, another format) is
// ignored with one line on stderr naming it and why, never handed to the driver, and replaced at the next
// save. Writes go to a temporary file renamed over the old one: a reader never sees half a file.
#ifndef vsPipelineCache_h
#define vsPipelineCache_h

#include "vsVulkan.h"
#include "vissweepCoreModule.h"

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace vs
{
class VISSWEEPCORE_EXPORT PipelineCache
{
public:
  /** The cache of `device` (whose properties are `properties`) in `directory` ("" = in memory only):
   *  loads this device's file when there is a valid one. Never throws for the file's sake. */
  PipelineCache(vk::Device device, const vk::PhysicalDeviceProperties& properties, const std::string& directory);
  ~PipelineCache();
  PipelineCache(const PipelineCache&) = delete;
  PipelineCache& operator=(const PipelineCache&) = delete;

  /** The handle pipelines are created with (thread-safe: Vulkan synchronizes the cache itself). */
  vk::PipelineCache Handle() const { return this->Cache_; }
  /** Writes the driver's data to the file (temporary file, then rename) when it differs from what
   *  the file holds. Returns false, with the reason in LastProblem(), when it could not. */
  bool Save();

  /** The file ("" without a directory). */
  const std::string& Path() const { return this->Path_; }
  /** Whether a file was read and given to the driver. */
  bool Loaded() const { return this->Loaded_; }
  /** Why the file was ignored or could not be written ("" when neither happened). */
  const std::string& LastProblem() const { return this->Problem_; }

  /** The folder from the environment (see the file's comment); "" when off or no home is known. */
  static std::string DefaultDirectory();
  /** The file name for a device: pipelines-<vendor>-<device>-<driver version>-<pipelineCacheUUID>.bin. */
  static std::string FileName(const vk::PhysicalDeviceProperties& properties);
  /** VisSweep's file around the driver's data: a header (magic, format version, data size, FNV-1a
   *  hash of the data), then the data. */
  static std::vector<uint8_t> Wrap(const std::vector<uint8_t>& data);
  /** The driver's data from a file's bytes, or "" in `problem` and the data in `data`: checks the
   *  header, the size and hash, and the data's own Vulkan header (version one, this vendor, device
   *  and pipelineCacheUUID). */
  static std::string Unwrap(const std::vector<uint8_t>& file, const vk::PhysicalDeviceProperties& properties,
    std::vector<uint8_t>& data);

private:
  vk::Device Device_;
  vk::PipelineCache Cache_;
  std::string Path_;
  std::string Problem_;
  bool Loaded_ = false;
  uint64_t SavedHash_ = 0; // the hash of the data the file holds (0: none)
  std::mutex SaveMutex_;
};
}

#endif
