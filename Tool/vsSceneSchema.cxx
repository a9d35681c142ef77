// vsSceneSchema.cxx — the table of the scene file's keys (vsSceneSchema.h), the words of its
// Word keys included.
#include "vsSceneSchema.h"
#include "sampling/mc_params.h"
#include "vsKernelOptions.h"

#include <limits>
#include <stdexcept>

namespace vstool
{
std::string SceneKey::Path() const
{
  return *Section ? std::string(Section) + "." + Key : std::string(Key);
}

namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kIntMax = std::numeric_limits<int>::max();
constexpr double kFloatMax = double(std::numeric_limits<float>::max());
constexpr double kFloatMinNormal = double(std::numeric_limits<float>::min());

using T = SceneType;
using R = SceneRange;

// The words of a kernel option, from its one table (vsKernelOptions.cxx).
std::vector<std::string> KernelWords(vs::KernelOptionId id)
{
  return vs::KernelOptionWords(id);
}
}

const std::vector<SceneKey>& SceneSchema()
{
  // clang-format off
  static const std::vector<SceneKey> table{
    // section, key, type, range, min, max, default, required, noun, unit, words, description
    { "", "description", T::String, R::Any, 0, 0, nullptr, false, "", "", {}, "free text, ignored" },
    { "", "volume", T::Section, R::Any, 0, 0, nullptr, true, "", "", {}, "the volume to render" },
    { "", "transfer_function", T::Section, R::Any, 0, 0, nullptr, true, "", "", {}, "scalars to extinction and albedo" },
    { "", "environment", T::Section, R::Any, 0, 0, nullptr, false, "", "", {}, "the light; absent = a constant white sky of radiance 1" },
    { "", "camera", T::Section, R::Any, 0, 0, nullptr, false, "", "", {}, "the view; absent = frame the volume looking along +Y, +Z up" },
    { "", "render", T::Section, R::Any, 0, 0, nullptr, false, "", "", {}, "image size, samples and the renderer's settings" },
    { "", "visibility", T::Section, R::Any, 0, 0, nullptr, false, "", "", {}, "the visibility grid's settings (the mapper's)" },
    { "", "clip_planes", T::Planes, R::Any, 0, 0, nullptr, false, "", "", {}, "planes each keeping the half-space its normal points into" },
    { "", "lights", T::Lights, R::Any, 0, 0, nullptr, false, "", "", {}, "VTK's lights beside the environment (vtkLight), at most 8 used" },

    { "volume", "file", T::File, R::Any, 0, 0, nullptr, false, "", "", {}, "one volume file or a DICOM folder (this or 'files' is required)" },
    { "volume", "files", T::Files, R::Any, 0, 0, nullptr, false, "", "", {}, "instead of 'file': a .vdb sequence, one file per time step" },
    { "volume", "grid", T::String, R::Any, 0, 0, "\"density\"", false, "", "", {}, "the OpenVDB grid to read" },
    { "volume", "time_step", T::Integer, R::Closed, 0, kIntMax, "0", false, "time step", "", {}, "with 'files': the step to render, below the number of files" },

    { "transfer_function", "opacity", T::Points, R::Closed, 0, 1, nullptr, true, "opacity", "", {}, "[[scalar, alpha], ...], alpha in [0, 1]" },
    { "transfer_function", "color", T::Points, R::Closed, 0, 1, nullptr, false, "albedo", "", {}, "[[scalar, r, g, b], ...], the albedo in [0, 1]; absent = white" },
    { "transfer_function", "unit_distance", T::Number, R::PositiveFloat, kFloatMinNormal, kFloatMax, "1", false, "the unit distance", "", {}, "VTK's ScalarOpacityUnitDistance, in world units" },
    { "transfer_function", "density_scale", T::Number, R::NonNegativeFloat, 0, kFloatMax, "1", false, "the density scale", "", {}, "multiplies the extinction" },
    { "transfer_function", "interpolation", T::Word, R::Any, 0, 0, "\"linear\"", false, "interpolation", "", { "linear", "nearest" }, "linear (trilinear) or nearest (label maps)" },
    { "transfer_function", "gradient_opacity", T::Points, R::Closed, 0, 1, nullptr, false, "opacity", "", {}, "[[gradient magnitude, g], ...], magnitudes at least 0, g in [0, 1]; absent = none" },
    // issue 38: the vtkVolumeProperty's shading (the Monte Carlo mode's surface lobe, the emission-absorption mode's Phong).
    { "transfer_function", "shade", T::Boolean, R::Any, 0, 0, "false", false, "", "", {}, "the property's Shade: a surface lobe where the gradient is strong (Monte Carlo), Phong (emission-absorption)" },
    { "transfer_function", "ambient", T::Number, R::Closed, 0, 1, "0.1", false, "the ambient weight", "", {}, "the property's Ambient (emission-absorption only)" },
    { "transfer_function", "diffuse", T::Number, R::Closed, 0, 1, "0.7", false, "the diffuse weight", "", {}, "the property's Diffuse" },
    { "transfer_function", "specular", T::Number, R::Closed, 0, 1, "0.2", false, "the specular weight", "", {}, "the property's Specular" },
    { "transfer_function", "specular_power", T::Number, R::Closed, 0, 128, "10", false, "the specular power", "", {}, "the property's SpecularPower (the surface lobe's roughness)" },

    { "environment", "file", T::File, R::Any, 0, 0, nullptr, false, "", "", {}, "a lat-long .exr or .hdr (one source of four)" },
    { "environment", "constant", T::Color, R::NonNegativeFloat, 0, kFloatMax, nullptr, false, "radiance", "", {}, "[r, g, b] radiance from every direction" },
    { "environment", "sun", T::Section, R::Any, 0, 0, nullptr, false, "", "", {}, "a sun disk over a constant sky" },
    { "environment", "two_tone", T::Section, R::Any, 0, 0, nullptr, false, "", "", {}, "one radiance above the horizon (z > 0), another below" },
    { "environment", "octahedral_size", T::Integer, R::Closed, 0, 32768, "0", false, "size", "", {}, "the octahedral map's side, a power of two; 0 = automatic (a file only)" },
    { "environment", "rotation_deg", T::Number, R::Any, 0, 0, "0", false, "", "", {}, "(file only) rotation about +Z, degrees" },
    { "environment", "intensity", T::Number, R::NonNegativeFloat, 0, kFloatMax, "1", false, "the intensity", "", {}, "multiplies the radiance" },
    { "environment", "visible_background", T::Boolean, R::Any, 0, 0, "true", false, "", "", {}, "camera rays that leave the volume see the environment" },
    { "environment", "background", T::Color, R::NonNegativeFloat, 0, kFloatMax, "[0, 0, 0]", false, "colour", "", {}, "the colour seen instead when visible_background is false" },

    { "environment.sun", "direction", T::Direction, R::Any, 0, 0, nullptr, true, "", "", {}, "towards the sun" },
    { "environment.sun", "radius_deg", T::Number, R::Closed, 0, 180, "0.27", false, "radius", "", {}, "the disk's angular radius, degrees" },
    { "environment.sun", "radiance", T::Color, R::NonNegativeFloat, 0, kFloatMax, "[1000, 1000, 1000]", false, "radiance", "", {}, "the disk's radiance" },
    { "environment.sun", "sky", T::Color, R::NonNegativeFloat, 0, kFloatMax, "[0, 0, 0]", false, "radiance", "", {}, "the sky's radiance" },

    { "environment.two_tone", "upper", T::Color, R::NonNegativeFloat, 0, kFloatMax, nullptr, true, "radiance", "", {}, "the radiance above the horizon" },
    { "environment.two_tone", "lower", T::Color, R::NonNegativeFloat, 0, kFloatMax, nullptr, true, "radiance", "", {}, "the radiance below the horizon" },

    { "camera", "position", T::Point, R::Any, 0, 0, nullptr, true, "", "", {}, "the eye, world coordinates" },
    { "camera", "focal_point", T::Point, R::Any, 0, 0, nullptr, true, "", "", {}, "the point looked at, not the position" },
    { "camera", "view_up", T::Direction, R::Any, 0, 0, "[0, 0, 1]", false, "", "", {}, "up, not parallel to the view direction" },
    { "camera", "view_angle", T::Number, R::Open, 0, 180, "30", false, "angle", " degrees", {}, "the vertical view angle, degrees" },
    { "camera", "parallel_scale", T::Number, R::PositiveFloat, kFloatMinNormal, kFloatMax, nullptr, false, "the parallel scale", "", {}, "present: a parallel projection of this scale" },

    { "render", "width", T::Integer, R::Closed, 1, 16384, "512", false, "width", "", {}, "pixels" },
    { "render", "height", T::Integer, R::Closed, 1, 16384, "512", false, "height", "", {}, "pixels" },
    { "render", "spp", T::Integer, R::Closed, 1, 1 << 30, "64", false, "samples per pixel", "", {}, "samples per pixel" },
    { "render", "strategy", T::Word, R::Any, 0, 0, "\"auto\"", false, "strategy", "", KernelWords(vs::KernelOptionId::Strategy), "the sampling strategy (the API's spelling too: case, - and _ are ignored)" },
    { "render", "seed", T::Integer, R::Closed, 0, kIntMax, "1", false, "seed", "", {}, "the random seed" },
    { "render", "exposure", T::Number, R::NonNegativeFloat, 0, kFloatMax, "1", false, "the exposure", "", {}, "the PNG's exposure" },
    { "render", "tone_mapping", T::Boolean, R::Any, 0, 0, "true", false, "", "", {}, "the PNG's filmic tone mapping" },
    { "render", "update_scheme", T::Word, R::Any, 0, 0, "\"round-robin\"", false, "update scheme", "", { "full", "round-robin", "environment-guided", "static" }, "for --frames: how the visibility follows the time steps" },
    { "render", "directions_per_frame", T::Integer, R::Closed, 1, 4096, "4", false, "directions per frame", "", {}, "the update schemes' k" },
    { "render", "static_interval", T::Integer, R::Closed, 1, kIntMax, "16", false, "frames between static updates", "", {}, "the static scheme's interval" },
    { "render", "control_extinction", T::Word, R::Any, 0, 0, "\"shadow\"", false, "control extinction", "", KernelWords(vs::KernelOptionId::ControlExtinction), "which rays integrate each brick's smallest extinction exactly" },
    { "render", "transmittance_estimator", T::Word, R::Any, 0, 0, "\"ratio-tracking\"", false, "transmittance estimator", "", KernelWords(vs::KernelOptionId::Transmittance), "the shadow rays' transmittance estimator" },
    { "render", "sampler", T::Word, R::Any, 0, 0, "\"sobol\"", false, "sampler", "", KernelWords(vs::KernelOptionId::Sampler), "where a sample's jitter and light direction come from" },
    { "render", "mode", T::Word, R::Any, 0, 0, "\"monte-carlo\"", false, "render mode", "", { "emission-absorption", "monte-carlo", "preview", "ambient-occlusion" }, "the mapper's RenderMode (the API's spelling too)" },
    { "render", "shadow_rays", T::Integer, R::Closed, 1, 64, "1", false, "shadow rays per scatter point", "", {}, "shadow rays per scatter point (splitting)" },
    { "render", "max_scattering_events", T::Integer, R::Closed, 1, double(vs::shared::VS_MAX_SCATTERING_EVENTS), "1024", false, "scattering events", "", {}, "the most scattering events a path may have (1: single scattering)" },
    { "render", "anisotropy", T::Number, R::Open, -1, 1, "0", false, "anisotropy", "", {}, "the Henyey-Greenstein phase function's g (> 0 forward, < 0 backward)" },
    { "render", "volumetric_scattering_blending", T::Number, R::Closed, 0, 2, "0", false, "the volumetric scattering blending", "", {}, "with transfer_function.shade: 0 a surface wherever the gradient allows, 1 where the gradient is strong and the medium opaque, 2 volumetric only (VTK 9.2's)" },

    // The mapper's settings: absent = the mapper's default (vtkVisibilitySweepVolumeMapper.h).
    { "visibility", "direction_resolution", T::Integer, R::Closed, 1, 1024, nullptr, false, "resolution", "", {}, "directions per octahedral side: 4, 8 or 16" },
    { "visibility", "voxels_per_cell", T::Number, R::Closed, 1, 256, nullptr, false, "voxels per cell", "", {}, "the grid's cell size in voxels, 1 to 256 (absent: automatic)" },
    { "visibility", "kernel_resolution", T::Integer, R::Closed, 0, 1 << 14, nullptr, false, "rays", "", {}, "0 = automatic" },
    { "visibility", "filtering", T::Boolean, R::Any, 0, 0, nullptr, false, "", "", {}, "the mapper's Filtering" },
    { "visibility", "filter_angle_fraction", T::Number, R::Closed, 0, 1, nullptr, false, "fraction", "", {}, "the mapper's FilterAngleFraction" },
    { "visibility", "epsilon", T::Number, R::LeftOpen, 0, 1, nullptr, false, "epsilon", "", {}, "the mapper's Epsilon" },
    { "visibility", "cell_mode", T::Word, R::Any, 0, 0, nullptr, false, "cell mode", "", KernelWords(vs::KernelOptionId::CellMode), "the mapper's CellMode" },
    { "visibility", "skip_unlit_directions", T::Boolean, R::Any, 0, 0, nullptr, false, "", "", {}, "directions without light are not swept" },
    { "visibility", "progressive", T::Boolean, R::Any, 0, 0, nullptr, false, "", "", {}, "the grid fills in between frames (ProgressiveVisibility)" },
    { "visibility", "sweep_frame_fraction", T::Number, R::Closed, 0, 1000, nullptr, false, "fraction", "", {}, "sweep time per frame over render time" },
    { "visibility", "light_weighted_directions", T::Boolean, R::Any, 0, 0, nullptr, false, "", "", {}, "sweep towards each texel's light first" },
    { "visibility", "fill_unswept", T::Boolean, R::Any, 0, 0, nullptr, false, "", "", {}, "unswept directions read the nearest swept one (FillUnsweptDirections)" },
    { "visibility", "extinction_pooling", T::Integer, R::Closed, 0, 16, nullptr, false, "voxels per texel", "", {}, "voxels per pooled texel of the sweeps' extinction (0 = half a cell)" },

    { "clip_planes[]", "origin", T::Point, R::Any, 0, 0, nullptr, true, "", "", {}, "a point of the plane" },
    { "clip_planes[]", "normal", T::Direction, R::Any, 0, 0, nullptr, true, "", "", {}, "points into the half-space kept" },

    // issue 38: a vtkLight each, with VTK's semantics (docs/reference.md, "VTK's lights").
    { "lights[]", "type", T::Word, R::Any, 0, 0, "\"directional\"", false, "light type", "", { "directional", "positional", "spot" }, "directional (from the position towards the focal point), positional (a point light) or spot (a point light with a cone)" },
    { "lights[]", "position", T::Point, R::Any, 0, 0, "[0, 0, 1]", false, "", "", {}, "the light's position (vtkLight's Position)" },
    { "lights[]", "direction", T::Direction, R::Any, 0, 0, nullptr, false, "", "", {}, "directional only, instead of position: towards the light, from the focal point" },
    { "lights[]", "focal_point", T::Point, R::Any, 0, 0, "[0, 0, 0]", false, "", "", {}, "the point the light looks at (vtkLight's FocalPoint)" },
    { "lights[]", "color", T::Color, R::NonNegativeFloat, 0, kFloatMax, "[1, 1, 1]", false, "colour", "", {}, "the light's colour (vtkLight's DiffuseColor)" },
    { "lights[]", "intensity", T::Number, R::NonNegativeFloat, 0, kFloatMax, "1", false, "the intensity", "", {}, "vtkLight's Intensity: a plane facing the light receives pi x intensity x colour" },
    { "lights[]", "cone_angle", T::Number, R::Open, 0, 90, "30", false, "cone angle", " degrees", {}, "spot only: the cone's half angle, degrees (vtkLight's ConeAngle)" },
    { "lights[]", "exponent", T::Number, R::Closed, 0, 128, "1", false, "exponent", "", {}, "spot only: the falloff (cos)^exponent inside the cone (vtkLight's Exponent)" },
    { "lights[]", "attenuation", T::Color, R::NonNegativeFloat, 0, kFloatMax, "[1, 0, 0]", false, "attenuation", "", {}, "positional and spot only: 1 / (a0 + a1 r + a2 r^2) (vtkLight's AttenuationValues)" },
    { "lights[]", "follow_camera", T::Boolean, R::Any, 0, 0, "false", false, "", "", {}, "a camera light: position and focal point in the camera's frame (camera at the origin looking down -z, y up) and moving with it" },
  };
  // clang-format on
  return table;
}

const SceneKey& SceneSchemaKey(const std::string& section, const std::string& key)
{
  for (const SceneKey& k : SceneSchema())
  {
    if (section == k.Section && key == k.Key)
    {
      return k;
    }
  }
  throw std::logic_error("the scene schema has no key '" + key + "' in section '" + section + "'");
}

const std::vector<std::string>& SceneStrategies()
{
  return SceneSchemaKey("render", "strategy").Words;
}

const std::vector<std::string>& SceneUpdateSchemes()
{
  return SceneSchemaKey("render", "update_scheme").Words;
}

const std::vector<std::string>& SceneControlExtinctions()
{
  return SceneSchemaKey("render", "control_extinction").Words;
}

const std::vector<std::string>& SceneTransmittanceEstimators()
{
  return SceneSchemaKey("render", "transmittance_estimator").Words;
}

const std::vector<std::string>& SceneSamplers()
{
  return SceneSchemaKey("render", "sampler").Words;
}

const std::vector<std::string>& SceneRenderModes()
{
  return SceneSchemaKey("render", "mode").Words;
}

std::vector<std::string> SceneSchemaKeys(const std::string& section)
{
  std::vector<std::string> keys;
  for (const SceneKey& k : SceneSchema())
  {
    if (section == k.Section)
    {
      keys.emplace_back(k.Key);
    }
  }
  return keys;
}
}
