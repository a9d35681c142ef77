#include "vsPipelineCache.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <system_error>

namespace vs
{
namespace
{
constexpr char kMagic[4] = { 'V', 'S', 'P', 'C' };
constexpr uint32_t kFormatVersion = 1;
constexpr size_t kHeaderBytes = 24;              // magic, version, data size (u64), hash (u64)
constexpr uint64_t kMaxBytes = 512ull << 20;     // a larger file is not read (nor written)
constexpr size_t kVulkanHeaderBytes = 16 + VK_UUID_SIZE; // VkPipelineCacheHeaderVersionOne

uint64_t Fnv1a(const uint8_t* data, size_t size)
{
  uint64_t h = 0xcbf29ce484222325ull;
  for (size_t i = 0; i < size; ++i)
  {
    h ^= data[i];
    h *= 0x100000001b3ull;
  }
  return h;
}

template <typename T>
T Read(const uint8_t* p)
{
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;
}

template <typename T>
void Write(std::vector<uint8_t>& out, T v)
{
  const auto* p = reinterpret_cast<const uint8_t*>(&v);
  out.insert(out.end(), p, p + sizeof(T));
}
}

std::string PipelineCache::DefaultDirectory()
{
  if (const char* dir = std::getenv("VISSWEEP_PIPELINE_CACHE_DIR"))
  {
    const std::string d = dir;
    return d == "off" ? std::string() : d;
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg == '/')
  {
    return std::string(xdg) + "/vissweep";
  }
  if (const char* home = std::getenv("HOME"); home && *home)
  {
    return std::string(home) + "/.cache/vissweep";
  }
  return std::string();
}

std::string PipelineCache::FileName(const vk::PhysicalDeviceProperties& p)
{
  std::ostringstream os;
  os << "pipelines-" << std::hex << std::setfill('0') << std::setw(4) << p.vendorID << "-" << std::setw(4)
     << p.deviceID << "-" << std::setw(8) << p.driverVersion << "-";
  for (uint8_t b : p.pipelineCacheUUID)
  {
    os << std::setw(2) << unsigned(b);
  }
  os << ".bin";
  return os.str();
}

std::vector<uint8_t> PipelineCache::Wrap(const std::vector<uint8_t>& data)
{
  std::vector<uint8_t> out(kMagic, kMagic + 4);
  Write<uint32_t>(out, kFormatVersion);
  Write<uint64_t>(out, uint64_t(data.size()));
  Write<uint64_t>(out, Fnv1a(data.data(), data.size()));
  out.insert(out.end(), data.begin(), data.end());
  return out;
}

std::string PipelineCache::Unwrap(
  const std::vector<uint8_t>& file, const vk::PhysicalDeviceProperties& properties, std::vector<uint8_t>& data)
{
  data.clear();
  if (file.size() < kHeaderBytes || std::memcmp(file.data(), kMagic, 4) != 0)
  {
    return "not a VisSweep pipeline cache (no VSPC header)";
  }
  if (Read<uint32_t>(file.data() + 4) != kFormatVersion)
  {
    return "format version " + std::to_string(Read<uint32_t>(file.data() + 4)) + ", expected " +
      std::to_string(kFormatVersion);
  }
  const uint64_t size = Read<uint64_t>(file.data() + 8);
  if (size != file.size() - kHeaderBytes)
  {
    return "truncated or padded: the header says " + std::to_string(size) + " bytes of data, the file has " +
      std::to_string(file.size() - kHeaderBytes);
  }
  const uint8_t* d = file.data() + kHeaderBytes;
  if (Fnv1a(d, size_t(size)) != Read<uint64_t>(file.data() + 16))
  {
    return "corrupt (its data does not match its checksum)";
  }
  // The driver's own header (VkPipelineCacheHeaderVersionOne): for this device and driver only.
  if (size < kVulkanHeaderBytes || Read<uint32_t>(d) < kVulkanHeaderBytes ||
    Read<uint32_t>(d + 4) != uint32_t(VK_PIPELINE_CACHE_HEADER_VERSION_ONE))
  {
    return "its data has no Vulkan pipeline cache header";
  }
  if (Read<uint32_t>(d + 8) != properties.vendorID || Read<uint32_t>(d + 12) != properties.deviceID ||
    std::memcmp(d + 16, properties.pipelineCacheUUID.data(), VK_UUID_SIZE) != 0)
  {
    return "made by another device or driver";
  }
  data.assign(d, d + size);
  return std::string();
}

PipelineCache::PipelineCache(
  vk::Device device, const vk::PhysicalDeviceProperties& properties, const std::string& directory)
  : Device_(device)
{
  std::vector<uint8_t> data;
  if (!directory.empty())
  {
    this->Path_ = directory + "/" + FileName(properties);
    std::error_code ec;
    const bool exists = std::filesystem::is_regular_file(this->Path_, ec);
    const uintmax_t bytes = exists ? std::filesystem::file_size(this->Path_, ec) : 0;
    if (exists && !ec)
    {
      std::vector<uint8_t> file;
      if (bytes > kMaxBytes)
      {
        this->Problem_ = "larger than " + std::to_string(kMaxBytes >> 20) + " MiB";
      }
      else
      {
        std::ifstream in(this->Path_, std::ios::binary);
        file.resize(size_t(bytes));
        if (!in.read(reinterpret_cast<char*>(file.data()), std::streamsize(file.size())))
        {
          this->Problem_ = "cannot be read";
        }
      }
      if (this->Problem_.empty())
      {
        this->Problem_ = Unwrap(file, properties, data);
      }
    }
  }
  vk::PipelineCacheCreateInfo ci;
  if (this->Problem_.empty() && !data.empty())
  {
    ci.initialDataSize = data.size();
    ci.pInitialData = data.data();
    try
    {
      this->Cache_ = device.createPipelineCache(ci);
      this->Loaded_ = true;
      this->SavedHash_ = Fnv1a(data.data(), data.size());
    }
    catch (const vk::SystemError& e)
    {
      this->Problem_ = std::string("the driver refused it (") + e.what() + ")";
    }
  }
  if (!this->Problem_.empty())
  {
    std::fprintf(stderr, "VisSweep: ignoring the pipeline cache %s: %s; it will be rewritten\n", this->Path_.c_str(),
      this->Problem_.c_str());
  }
  if (!this->Cache_)
  {
    this->Cache_ = device.createPipelineCache(vk::PipelineCacheCreateInfo());
  }
}

PipelineCache::~PipelineCache()
{
  if (this->Cache_)
  {
    this->Device_.destroyPipelineCache(this->Cache_);
  }
}

bool PipelineCache::Save()
{
  if (this->Path_.empty())
  {
    return true;
  }
  std::lock_guard<std::mutex> lock(this->SaveMutex_);
  std::vector<uint8_t> data;
  try
  {
    data = this->Device_.getPipelineCacheData(this->Cache_);
  }
  catch (const vk::SystemError& e)
  {
    this->Problem_ = std::string("the driver's data could not be read: ") + e.what();
    return false;
  }
  const uint64_t hash = Fnv1a(data.data(), data.size());
  if (hash == this->SavedHash_ || data.size() > kMaxBytes)
  {
    return true;
  }
  const std::filesystem::path path(this->Path_);
  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  static std::atomic<unsigned> counter{ 0 };
  const std::string temporary =
    this->Path_ + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter.fetch_add(1));
  const std::vector<uint8_t> file = Wrap(data);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(file.data()), std::streamsize(file.size()));
    if (!out.flush())
    {
      out.close();
      std::filesystem::remove(temporary, ec);
      this->Problem_ = "cannot write " + temporary;
      return false;
    }
  }
  std::filesystem::rename(temporary, path, ec);
  if (ec)
  {
    std::filesystem::remove(temporary, ec);
    this->Problem_ = "cannot rename " + temporary + " to " + this->Path_;
    return false;
  }
  this->SavedHash_ = hash;
  return true;
}
}
