/**
 * @class   vtkVisSweepDevice
 * @brief   The Vulkan device VisSweep computes on, and its limits.
 *
 * A small query object for scripts and applications: is a Vulkan compute
 * device available, which one (VISSWEEP_DEVICE selects by index or name
 * substring), and the limits that decide what fits (3D image size, storage
 * buffer range, memory heap).
 *
 * @code{.py}
 * import vissweep
 * d = vissweep.vtkVisSweepDevice()
 * if d.IsAvailable(): print(d.GetDescription())
 * else: print(d.GetErrorMessage())
 * @endcode
 */
#ifndef vtkVisSweepDevice_h
#define vtkVisSweepDevice_h

#include "vissweepFiltersModule.h"
#include "vtkObject.h"

#include <string>

class VISSWEEPFILTERS_EXPORT vtkVisSweepDevice : public vtkObject
{
public:
  static vtkVisSweepDevice* New();
  vtkTypeMacro(vtkVisSweepDevice, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** True when the shared device could be created (tries once per call until it succeeds). */
  bool IsAvailable();
  /** Why the device is not available (empty when it is). */
  const char* GetErrorMessage();
  /** The device and its limits, several lines. */
  const char* GetDescription();
  const char* GetDeviceName();
  /** Largest 3D image edge, in texels (0 when unavailable). */
  unsigned int GetMaxImageDimension3D();
  /** Bytes of the device-local heap (0 when unavailable). */
  double GetMemoryHeapBytes();
  /** Number of validation messages reported so far (validation on in Debug builds). */
  double GetValidationMessageCount();

protected:
  vtkVisSweepDevice() = default;
  ~vtkVisSweepDevice() override = default;

private:
  vtkVisSweepDevice(const vtkVisSweepDevice&) = delete;
  void operator=(const vtkVisSweepDevice&) = delete;

  std::string Error;
  std::string Description;
  std::string Name;
};

#endif
