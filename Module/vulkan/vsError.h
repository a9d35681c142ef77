// vsError.h — the typed errors of the compute core. Each message names the
// cause and, where one applies, the device limit that was hit.
#ifndef vsError_h
#define vsError_h

#include <stdexcept>
#include <string>

namespace vs
{
/** Base of every error raised by VisSweep's core. */
class Error : public std::runtime_error
{
public:
  explicit Error(const std::string& what)
    : std::runtime_error(what)
  {
  }
};

/** No Vulkan loader, or no driver (ICD) behind it. */
class VulkanUnavailableError : public Error
{
public:
  using Error::Error;
};

/** No device with a compute queue, or VISSWEEP_DEVICE matched none. */
class NoDeviceError : public Error
{
public:
  using Error::Error;
};

/** A buffer, image or dispatch larger than the device allows. */
class DeviceLimitError : public Error
{
public:
  using Error::Error;
};

/** A Vulkan call failed at run time (out of memory, device lost, ...). */
class VulkanCallError : public Error
{
public:
  using Error::Error;
};

/** Invalid input data or parameters given to a core pass. */
class InputError : public Error
{
public:
  using Error::Error;
};
}

#endif
