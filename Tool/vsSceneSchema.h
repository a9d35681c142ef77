// vsSceneSchema.h — the scene file's keys in one table: for each key its section, value type,
// range, default and a one-line meaning. The parser (vsSceneFile.cxx) takes the allowed keys of
// each section and the type and range checks of each value from it; TestSceneSchema.cxx checks
// that docs/reference.md ("The scene file") documents exactly these keys and that the defaults
// here are the parser's. No JSON and no VTK here.
#ifndef vsSceneSchema_h
#define vsSceneSchema_h

#include <string>
#include <vector>

namespace vstool
{
/** What a key's value is. */
enum class SceneType
{
  Section,   // an object whose keys are the entries with this key's path as their Section
  Boolean,   // true or false
  Integer,   // an integer (2.0 is one), within the range
  Number,    // a finite number within the range
  String,    // any text
  Word,      // one of Words
  File,      // a file name, relative to the scene file's folder
  Files,     // a non-empty array of file names
  Point,     // [x, y, z], each within float's range
  Direction, // [x, y, z], not zero; any length (normalised when used)
  Color,     // [r, g, b], each at least 0 and within float's range
  Points,    // [[x, y...], ...] sorted by strictly increasing x: the y values within [Min, Max]
  Planes,    // [{"origin", "normal"}, ...]: the entries of section "clip_planes[]"
  Lights     // [{"type", ...}, ...]: the entries of section "lights[]" (issue 38: VTK's vtkLights)
};

/** How Min and Max bound a number (Integer, Number; Points: each point's values). */
enum class SceneRange
{
  Any,             // any finite number
  Closed,          // [Min, Max]
  LeftOpen,        // (Min, Max]
  Open,            // (Min, Max)
  Positive,        // > 0 (Min 0, no Max)
  PositiveFloat,   // > 0 and a normal float: [1.17549e-38, 3.40282e+38]
  NonNegativeFloat // >= 0 and at most float's largest, 3.40282e+38
};

struct SceneKey
{
  const char* Section; // "" (the top level), "volume", "environment.sun", "clip_planes[]" ...
  const char* Key;
  SceneType Type;
  SceneRange Range;
  double Min;
  double Max;
  const char* Default; // as JSON, nullptr if none (required, or absent means something else)
  bool Required;
  const char* Noun;    // names the value in error messages ("width 0 not in [1, 16384]")
  const char* Unit;    // after the range in error messages ("angle 180 not in (0, 180) degrees"), or ""
  std::vector<std::string> Words; // SceneType::Word: the allowed words, else empty
  const char* Description;

  /** "render.width"; "clip_planes[].origin" for a plane's keys. */
  std::string Path() const;
};

/** Every key of the scene file, each section's keys in the order its error messages list them. */
const std::vector<SceneKey>& SceneSchema();
/** The entry of section.key; throws std::logic_error if the table has none (a parser bug). */
const SceneKey& SceneSchemaKey(const std::string& section, const std::string& key);
/** The keys of one section, in the table's order. */
std::vector<std::string> SceneSchemaKeys(const std::string& section);

// The words of the render section's Word keys (their entries' Words).
/** The strategies of the scene file, in the mapper's enum order (uniform = 0 ... two-step = 4). */
const std::vector<std::string>& SceneStrategies();
/** The update schemes of the scene file, in the mapper's enum order (full = 0 ... static = 3). */
const std::vector<std::string>& SceneUpdateSchemes();
/** The control extinction names, in the order of vtkVisibilitySweepVolumeMapper::ControlExtinctions. */
const std::vector<std::string>& SceneControlExtinctions();
/** The transmittance estimator names, in the order of vtkVisibilitySweepVolumeMapper::TransmittanceEstimators. */
const std::vector<std::string>& SceneTransmittanceEstimators();
/** The sampler names, in the order of vtkVisibilitySweepVolumeMapper::Samplers. */
const std::vector<std::string>& SceneSamplers();
/** The render mode names, in the order of vtkVisibilitySweepVolumeMapper::RenderModes. */
const std::vector<std::string>& SceneRenderModes();
}

#endif
