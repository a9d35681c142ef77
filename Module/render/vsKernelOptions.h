// vsKernelOptions.h — the render kernel's options, listed once: for each, the values (the
// mc_params.h constants, which the mapper's enums equal), the word the scene file and the command
// line use ("two-step"), the API's name (the mapper's enum, "TwoStep"), and the specialization
// constant it selects (sampling/kernel_spec.h). The mapper's Get...AsString, the pass's pipeline
// names, the scene schema's words and the benchmarks' flags all read this table; and
// KernelSpecialization builds the pipeline's constants by id, not by position.
#ifndef vsKernelOptions_h
#define vsKernelOptions_h

#include "vissweepCoreModule.h"

#include <cstdint>
#include <string>
#include <vector>

namespace vs
{
/** One value of an option. */
struct KernelOptionValue
{
  uint32_t Value;      // the mc_params.h / strategies.h constant (= the mapper's enum value)
  const char* Word;    // the scene file's and the command line's word
  const char* ApiName; // the mapper's enum name, as Get...AsString returns it
};

/** An option of the Monte Carlo kernel that takes one of a few values. */
struct KernelOption
{
  const char* Setting;      // the mapper's setting ("SamplingStrategy")
  const char* SceneKey;     // its key in the scene file's render section ("" if none)
  int SpecializationId;     // the kernel_spec.h id its value selects (-1: a parameter, not compiled in)
  std::vector<KernelOptionValue> Values;
};

enum class KernelOptionId
{
  Strategy,          // the light direction's sampling strategy (Auto: the mapper's choice per frame)
  CellMode,          // how a point reads the grid's cells
  CameraEstimator,   // the camera ray's tracker
  Sampler,           // the pixel jitter and light directions' numbers
  ControlExtinction, // which rays integrate each brick's smallest extinction exactly
  Transmittance,     // the shadow rays' transmittance estimator
  Mis                // how light sampling and phase sampling are weighted at the events
};

/** The mapper's Auto strategy: not a kernel strategy (the mapper renders each frame with
 *  Environment or TwoStep), listed with them for the words and names. */
constexpr uint32_t kAutoStrategy = 5u;

VISSWEEPCORE_EXPORT const KernelOption& GetKernelOption(KernelOptionId id);
/** The API's name of `value` ("Unknown" if the option has no such value). */
VISSWEEPCORE_EXPORT const char* KernelOptionApiName(KernelOptionId id, uint32_t value);
/** The word of `value` ("?" if the option has no such value). */
VISSWEEPCORE_EXPORT const char* KernelOptionWord(KernelOptionId id, uint32_t value);
/** The option's words, in the order of its values. */
VISSWEEPCORE_EXPORT std::vector<std::string> KernelOptionWords(KernelOptionId id);
/** The value whose word or API name is `name`, ignoring case, '-' and '_' ("Two_Step", "twostep",
 *  "TwoStep"); -1 if none. */
VISSWEEPCORE_EXPORT int KernelOptionValueOf(KernelOptionId id, const std::string& name);

/** Throws InputError naming the setting, the value and the range for an event limit outside
 *  [1, VS_MAX_SCATTERING_EVENTS] or an anisotropy outside (-1, 1) or not finite (the mapper's
 *  settings and the pass's parameters alike). */
VISSWEEPCORE_EXPORT void CheckScatteringSettings(double maxEvents, double anisotropy);

/** The specialization constants of one kernel pipeline, set by id (kernel_spec.h). */
class VISSWEEPCORE_EXPORT KernelSpecialization
{
public:
  KernelSpecialization();
  /** Sets constant `id`; throws std::logic_error for an id out of range or set twice. */
  KernelSpecialization& Set(uint32_t id, uint32_t value);
  /** The constants in id order; throws std::logic_error naming an id left unset. */
  std::vector<uint32_t> Values() const;

private:
  std::vector<uint32_t> Values_;
  std::vector<bool> Set_;
};
}

#endif
