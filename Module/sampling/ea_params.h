/*
 * ea_params.h — what an emission-absorption dispatch needs (ea_render.comp; std430, the layout rule
 * of volume_params.h): the camera, the volume as every pass sees it, the march, the projections'
 * settings, the Phong shading of the composite and the light volume of the lit modes.
 */
#ifndef VS_EA_PARAMS_H
#define VS_EA_PARAMS_H
#include "camera_params.h"
#include "grid_params.h"
#include "scene_lights.h"
#include "volume_params.h"

VS_NAMESPACE_BEGIN

/* Blend modes, VTK's vtkVolumeMapper::BlendModes values. Composite is emission-absorption; the
 * projections follow vtkGPUVolumeRayCastMapper (ea_render.comp). */
VS_CONST uint VS_BLEND_COMPOSITE = 0u;
VS_CONST uint VS_BLEND_MAXIMUM = 1u;
VS_CONST uint VS_BLEND_MINIMUM = 2u;
VS_CONST uint VS_BLEND_AVERAGE = 3u;
VS_CONST uint VS_BLEND_ADDITIVE = 4u;

/* How the composite's colour is lit (ea_render.comp's specialization constant VS_EA_LIGHTING). */
VS_CONST uint VS_EA_LIGHTING_NONE = 0u;    /* emission-absorption: the colour transfer function is emitted */
VS_CONST uint VS_EA_LIGHTING_PREVIEW = 1u; /* single scattering from the light volume: the colour is the albedo,
                                              a sample emits albedo x I(x) / (4 pi) (I: vsLightVolume.h) */
VS_CONST uint VS_EA_LIGHTING_AMBIENT_OCCLUSION = 2u; /* the albedo x lightIntensity x the mean visibility V(x)
                                              (the light volume's alpha): the preview under a constant sky of
                                              radiance lightIntensity */

/* What the pass makes besides the radiance image (VsEmissionAbsorptionParams.display, flags). The
 * lit preview's window image is made on the device, so that a frame of the preview while the user
 * drags has no per-pixel work left on the host (display_transform.h). */
VS_CONST uint VS_EA_DISPLAY_IMAGE = 1u;       /* also the premultiplied window image (vs_display_pixel) */
VS_CONST uint VS_EA_DISPLAY_ENVIRONMENT = 2u; /* pixels without opaque geometry see the environment: its
                                                 radiance through the pixel's centre, times T, is added */
VS_CONST uint VS_EA_DISPLAY_COMPOSITE = 4u;   /* the window image is composited over the environment
                                                 behind (else it paints it, opaque) */
VS_CONST uint VS_EA_DISPLAY_TONE_MAPPING = 8u; /* the filmic curve (else a clamp) */

struct VsEmissionAbsorptionParams
{
  VsCameraParams camera;    /* camera.frame: the frame's index (its jitter) */
  VsVolumeParams volume;    /* volume.majorant*: the bricks the composite skips where empty (0: none;
                               set by EmissionAbsorptionPass::Render from its majorant grid) */
  float step;               /* march step (world units) */
  float terminationOpacity; /* the composite stops at this opacity */
  uint blend;               /* VS_BLEND_* */
  uint display;             /* VS_EA_DISPLAY_* flags (0: the radiance image only) */
  /* The projections (VS_BLEND_MAXIMUM..ADDITIVE). */
  float averageMin;          /* the average's scalar range (vtkVolumeMapper AverageIPScalarRange) */
  float averageMax;
  float opacityUnitDistance; /* the opacity of extinction sigma_t: alpha = 1 - exp(-sigma_t u) */
  float exposure;            /* the display image's exposure (VS_EA_DISPLAY_IMAGE) */
  /* Phong shading of the composite (with VS_EA_SHADE). */
  float ambient;
  float diffuse;
  float specular;
  float specularPower;
  vec3 lightDirection; /* world direction towards the light (VTK's headlight: against the view direction) */
  float lightIntensity; /* also the ambient occlusion's sky radiance */
  /* The light volume's cells (VS_EA_LIGHTING_PREVIEW, _AMBIENT_OCCLUSION): the visibility grid's shape over
     volume.boxMin..boxMax, one light-volume texel per cell; grid.side unused. */
  VsGridParams grid;
  /* The environment (VS_EA_DISPLAY_ENVIRONMENT): its equal-area map of environmentSize^2 texels,
     scaled by environmentScale (the intensity). */
  uint environmentSize;
  float environmentScale;
  uint ditherFrame; /* the lit modes' offsets: the pixel's fixed pattern rotated by this frame's share of
                       the golden ratio (dither.h vs_dither_offset; 0: the pattern itself) */
  uint ambientFromLights; /* VS_EA_SHADE with lightCount > 0: 1 where the renderer's lights are not a lone
                             headlight (VTK's lighting complexity 2 and 3): the ambient term is then ambient x
                             ambientLight, VTK's sum of the lights' ambient colours x intensities (black by
                             default), not ambient x the colour (VTK's headlight-only shading) */
  /* ---- issue 38: VTK's lights and the surface lobe. Added at the end. ---- */
  uint lightCount;         /* lights[0 .. lightCount): VS_EA_SHADE's Phong lights (then lightDirection and
                              lightIntensity are not used), or the preview's lights (VS_EA_LIGHTING_PREVIEW: their
                              transmittance from the light volume's VS_EA_LIGHT_TRANSMITTANCE) */
  float anisotropy;        /* the preview's Henyey-Greenstein g towards the lights (the environment's light volume is
                              isotropic) */
  uint surface;            /* the preview's surface lobe (1: as the Monte Carlo kernel's, mc_params.h surface*) */
  float surfaceBlending;   /* mc_params.h's surface fields, the same meaning */
  float surfaceDiffuse;
  float surfaceSpecular;
  float surfaceRoughness;
  float gradientScale;
  float opacityDistance;
  float ambientLightR;     /* ambientFromLights: the lights' ambient colours x intensities, summed */
  float ambientLightG;
  float ambientLightB;
  VsSceneLight lights[VS_MAX_SCENE_LIGHTS];
};

VS_NAMESPACE_END

#endif
