#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * Emission-absorption ray casting (course notes 003, ch. 1), the mapper's first
 * render path: front-to-back compositing with opacity A = 1 - exp(-sigma_t dt)
 * per segment, colour from the colour transfer function, a jittered sample in
 * every segment, early termination, rays stopped at the opaque depth.
 * The blend modes MIP, MinIP, average and additive are projections, not light transport: with
 * P.blend one of them, the ray is projected instead (project(), as vtkGPUVolumeRayCastMapper).
 * With VS_EA_FACTOR, the composite's extinction is scaled by the volume's factor (the gradient
 * opacity, uFactor, interpolated as the scalar), as vtkGPUVolumeRayCastMapper applies gradient
 * opacity in composite blending only (not in the projections).
 * With VS_EA_SHADE, the composite's colour is Phong-shaded as vtkGPUVolumeRayCastMapper shades it
 * (the vtkVolumeProperty's ShadeOn): ambient x albedo + intensity x (diffuse |n.l| albedo +
 * specular |n.h|^power), n the normalised gradient of the scalar (central differences, in world
 * units), l the headlight, two-sided; where the gradient vanishes, ambient only. With P.lightCount > 0
 * (issue 38: the renderer's lights, VTK's automatic headlight included, as VTK's GPU mapper lights
 * with them) the sum over the lights instead, each of radiance E / pi towards the sample (E its irradiance
 * there, sampling/scene_lights.h: intensity x colour x attenuation x spot) in place of the intensity, and
 * with P.ambientFromLights (lights other than a lone headlight) VTK's ambient term of such lights, ambient x
 * the sum of their ambient colours x intensities, in place of ambient x albedo.
 * With VS_EA_LIGHTING (ea_params.h) the composite is lit from the light volume uLight instead of
 * emitting the colour transfer function (issue 15's preview): per segment of constant medium,
 * sigma_t and the albedo at one point of it, offset by the pixel's fixed pattern (dither.h: no random
 * numbers, the image is deterministic; midpoints would draw wood-grain rings), the segment adds
 * T (1 - exp(-sigma_t dt)) albedo I(x) / (4 pi), the exact integral of T sigma_s I / (4 pi) over it
 * (VS_EA_LIGHTING_PREVIEW: single scattering of the light volume I, trilinear between cell centres,
 * clamped at the box); VS_EA_LIGHTING_AMBIENT_OCCLUSION puts 4 pi lightIntensity V(x) for I, V the
 * mean visibility (the light volume's alpha). Alpha is 1 - T.
 * The preview and VTK's lights (issue 38): with P.lightCount > 0 each sample is lit by each light directly,
 * E_l T_l k(w_l), T_l the light volume's transmittance towards the light (uLightT, trilinear between the
 * cells' centres as uLight), E_l its irradiance at the sample and k the phase function (g = P.anisotropy)
 * times the albedo; the light volume's I carries the lights' multiple scattering (vsLightVolume.h).
 * The preview's phase towards the environment (issue 39): with VS_EA_ANISOTROPIC (P.anisotropy != 0 and the light
 * volume's band-1 moment uLightM, vsLightVolume.h) the single scattering of the environment's light is
 * Henyey-Greenstein's, exact in bands 0 and 1 (I + 3 g M.d) / (4 pi), the light taken as one HG lobe around M
 * (sampling/phase_moments.h vs_hg_lobe_light; M trilinear as I; with multiple scattering I and M are all the
 * orders', vsLightVolume.h, and VS_EA_ANISOTROPIC 2 reads two lobes: the first order's, kept apart in layers
 * 3 .. 5 of uLightM, and the other orders', the rest). Without it, I / (4 pi) as before (the same code).
 * With VS_EA_SHADE in the preview: the surface lobe of the Monte Carlo kernel (surface_scattering.glsl),
 * the same mixture k(w) = (1 - P_s) albedo f_HG + P_s f_r |n.w| towards each light, and towards the
 * environment (1 - P_s) albedo I / (4 pi) + P_s (k_d albedo + k_s) I / (4 pi): the light volume's I / (4 pi)
 * stands for the radiance arriving from every direction (exact under a uniform incident radiance, which the
 * lobe reflects as k_d albedo + k_s E(wo), E <= 1 the GGX lobe's albedo; docs/reference.md for its bias).
 * With P.display (VS_EA_DISPLAY_*), the environment seen through the volume (T x its radiance) and
 * the window image are made here too (write_pixel).
 * The composite skips the majorant grid's empty bricks (skip_empty: no extinction there, so nothing
 * to add); the projections sample every step (their minimum or average may lie in empty space).
 * Output: premultiplied RGBA per pixel, rows bottom-up (OpenGL order).
 */
#include "bindings.h"
#include "brick_walk.h"
#include "display_transform.h"
#include "dither.h"
#include "environment_display.glsl"
#include "rng.h"
#include "ea_params.h"
#include "microfacet.h"
#include "phase_moments.h"
#include "scene_lights.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = VS_EA_VOLUME, r32f) uniform readonly image3D uVolume;
layout(binding = VS_EA_TF) uniform samplerBuffer uTF; /* the table's entries (volume_access.glsl) */
layout(std430, binding = VS_EA_PARAMS) readonly buffer Params { VsEmissionAbsorptionParams P; };
layout(binding = VS_EA_DEPTH) uniform samplerBuffer uDepth; /* r32f texels, one per pixel */
layout(std430, binding = VS_EA_RESULT) writeonly buffer Result { vec4 uOut[]; };
layout(binding = VS_EA_FACTOR_IMAGE, r32f) uniform readonly image3D uFactor; /* read only with VS_EA_FACTOR */
layout(binding = VS_EA_LIGHT, rgba32f) uniform readonly image3D uLight; /* read only with VS_EA_LIGHTING */
layout(binding = VS_EA_BRICKS, rgba32f) uniform readonly image3D uBricks; /* the majorant grid's tracking image
                                                   (vsMajorantGrid.h), read when volume.majorantBrickSize > 0 */
layout(binding = VS_EA_ENVIRONMENT) uniform samplerBuffer uEnvironment; /* read with VS_EA_DISPLAY_ENVIRONMENT */
layout(std430, binding = VS_EA_DISPLAY) writeonly buffer Display { vec4 uDisplay[]; }; /* VS_EA_DISPLAY_IMAGE */
layout(binding = VS_EA_LIGHT_TRANSMITTANCE, rgba32f) uniform readonly image3D uLightT; /* the preview with lights */
layout(binding = VS_EA_LIGHT_MOMENT, rgba32f) uniform readonly image3D uLightM; /* the preview with VS_EA_ANISOTROPIC */
layout(constant_id = 0) const uint VS_EA_FACTOR = 0u;
layout(constant_id = 1) const uint VS_EA_SHADE = 0u;
layout(constant_id = 2) const uint VS_EA_LIGHTING = 0u; /* VS_EA_LIGHTING_* */
/* Whether P.blend is a projection (else the composite), and whether P.display asks for the window
 * image: constants, so that a pipeline holds only the code it runs. lavapipe runs straight-line code
 * under a branch for every lane even where no lane takes it (it masks lanes instead of jumping; only
 * loops end early): the projections' code cost the composite ~10 ms and the window image's ~10 ms a
 * frame at 512^2 (an early return measured 39, 29 and 19 ms with both, one and none). */
layout(constant_id = 3) const uint VS_EA_PROJECTION = 0u;
layout(constant_id = 4) const uint VS_EA_WINDOW_IMAGE = 0u;
/* Whether P.lightCount > 0 (issue 38: VTK's lights in the preview or the Phong shading): the lights' code
 * only in the pipelines that run it. A loop over no lights in every pipeline made the preview's drag frame
 * 1.3-1.9x slower on lavapipe (measured on ch2 at 512^2, loaded machine). */
layout(constant_id = 5) const uint VS_EA_LIGHTS = 0u;
/* Whether the preview's phase is anisotropic towards the environment (issue 39: P.anisotropy != 0, the light
 * volume's band-1 moment bound): 1 one lobe (three extra trilinear reads), 2 two lobes, the first order's and the
 * other orders' (six; the light volume's moment with the first order apart, vsLightVolume.h); only in the
 * pipelines that use them, and the isotropic preview's code unchanged. */
layout(constant_id = 6) const uint VS_EA_ANISOTROPIC = 0u;
#define VS_FACTOR_IMAGE
#define VS_TF_ENTRY_TEXELS

#include "volume_access.glsl"

/* The projections, as vtkGPUVolumeRayCastMapper computes them (single component), over the samples
 * of the ray's interval t (one jittered sample per step): maximum / minimum intensity, the colour
 * and opacity of the largest / smallest scalar (premultiplied); average, the mean over the samples
 * whose scalar lies in the average range of opacity(s) x s normalised to the data's range, as an
 * opaque grey (transparent without such samples); additive, the integral of opacity(s) x normalised
 * s per opacity unit distance (VTK's sum over samples one unit distance apart), clamped to 1, an
 * opaque grey. The opacity is that of the transfer function, alpha = 1 - exp(-sigma_t u). */
vec4 project(vec3 oi, vec3 di, vec2 t, float stepSize, uint blend, float jitter)
{
  ivec3 dims = ivec3(P.volume.dims);
  float unitDistance = P.opacityUnitDistance;
  float extreme = blend == VS_BLEND_MINIMUM ? 3.4e38 : -3.4e38;
  float sum = 0.0;
  uint samples = 0u;
  for (float a = t.x; a < t.y; a += stepSize)
  {
    float b = min(a + stepSize, t.y);
    float s = vs_sample(oi + (a + jitter * (b - a)) * di, dims, P.volume.interpolation);
    if (isnan(s))
      continue; /* non-finite voxels are empty space */
    if (blend == VS_BLEND_MAXIMUM)
      extreme = max(extreme, s);
    else if (blend == VS_BLEND_MINIMUM)
      extreme = min(extreme, s);
    else
    {
      float normalised = clamp((s - P.volume.tf.scalar0) * P.volume.tf.entriesPerUnit / max(P.volume.tf.entries - 1.0, 1.0), 0.0, 1.0);
      float opacity = 1.0 - exp(-vs_classify(s, P.volume.tf).w * unitDistance);
      if (blend == VS_BLEND_ADDITIVE)
        sum += opacity * normalised * (b - a) / unitDistance;
      else if (s >= P.averageMin && s <= P.averageMax)
      {
        sum += opacity * normalised;
        ++samples;
      }
    }
  }
  if (blend == VS_BLEND_MAXIMUM || blend == VS_BLEND_MINIMUM)
  {
    if (abs(extreme) > 3.0e38)
      return vec4(0.0); /* no finite sample */
    vec4 c = vs_classify(extreme, P.volume.tf);
    float opacity = 1.0 - exp(-c.w * unitDistance);
    return vec4(c.rgb * opacity, opacity);
  }
  if (blend == VS_BLEND_AVERAGE)
    return samples == 0u ? vec4(0.0) : vec4(vec3(clamp(sum / float(samples), 0.0, 1.0)), 1.0);
  return vec4(vec3(clamp(sum, 0.0, 1.0)), 1.0);
}

mat4 gIndexToWorld = mat4(1.0); /* the inverse of P.volume.worldToIndex (main, with lights) */

/* Phong shading at index-space point x of a sample of colour albedo (VS_EA_SHADE). */
vec3 shade(vec3 x, vec3 albedo, ivec3 dims, vec3 toEye)
{
  vec3 gw = vs_world_gradient(x, dims, P.volume.interpolation, P.volume.worldToIndex);
  float len = length(gw);
  vec3 color = VS_EA_LIGHTS == 1u && P.ambientFromLights != 0u
    ? P.ambient * vec3(P.ambientLightR, P.ambientLightG, P.ambientLightB)
    : P.ambient * albedo;
  if (len > 0.0 && !isnan(len) && !isinf(len))
  {
    vec3 n = -gw / len;
    if (VS_EA_LIGHTS == 0u)
    {
      vec3 l = P.lightDirection;
      vec3 h = normalize(l + toEye);
      float nl = abs(dot(n, l)), nh = abs(dot(n, h));
      color += P.lightIntensity * (P.diffuse * nl * albedo + P.specular * pow(nh, P.specularPower) * vec3(1.0));
    }
    else
    {
      vec3 xw = (gIndexToWorld * vec4(x, 1.0)).xyz;
      for (uint i = 0u; i < P.lightCount; ++i)
      {
        vec3 l;
        float distance;
        vec3 radiance = vs_scene_light_incident(P.lights[i], xw, l, distance) * (1.0 / VS_PI);
        vec3 h = normalize(l + toEye);
        float nl = abs(dot(n, l)), nh = abs(dot(n, h));
        color += radiance * (P.diffuse * nl * albedo + P.specular * pow(nh, P.specularPower) * vec3(1.0));
      }
    }
  }
  return color;
}

/* The light volume at index-space point x: trilinear between the cells' centres, clamped at the box. */
ivec3 gLerpI0, gLerpI1;
vec3 gLerpF;
vec4 light_at(vec3 x)
{
  ivec3 cells = ivec3(P.grid.cells);
  vec3 g = clamp((x - P.volume.boxMin) / P.grid.cellSize - 0.5, vec3(0.0), vec3(cells - 1));
  ivec3 i0 = min(ivec3(floor(g)), cells - 1);
  ivec3 i1 = min(i0 + 1, cells - 1);
  vec3 f = g - vec3(i0);
  if (VS_EA_LIGHTS == 1u || VS_EA_ANISOTROPIC != 0u)
  {
    gLerpI0 = i0; /* for transmittance_at and moment_at, at the same point */
    gLerpI1 = i1;
    gLerpF = f;
  }
  vec4 c00 = mix(imageLoad(uLight, ivec3(i0.x, i0.y, i0.z)), imageLoad(uLight, ivec3(i1.x, i0.y, i0.z)), f.x);
  vec4 c10 = mix(imageLoad(uLight, ivec3(i0.x, i1.y, i0.z)), imageLoad(uLight, ivec3(i1.x, i1.y, i0.z)), f.x);
  vec4 c01 = mix(imageLoad(uLight, ivec3(i0.x, i0.y, i1.z)), imageLoad(uLight, ivec3(i1.x, i0.y, i1.z)), f.x);
  vec4 c11 = mix(imageLoad(uLight, ivec3(i0.x, i1.y, i1.z)), imageLoad(uLight, ivec3(i1.x, i1.y, i1.z)), f.x);
  return mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
}

/* The transmittance towards lights 4 k .. 4 k + 3 at the point of the last light_at (the same weights),
 * from layer k of uLightT (vsLightVolume.h). */
vec4 transmittance_at(uint k)
{
  ivec3 i0 = gLerpI0, i1 = gLerpI1;
  vec3 f = gLerpF;
  int z = int(k * P.grid.cells.z);
  i0.z += z;
  i1.z += z;
  vec4 c00 = mix(imageLoad(uLightT, ivec3(i0.x, i0.y, i0.z)), imageLoad(uLightT, ivec3(i1.x, i0.y, i0.z)), f.x);
  vec4 c10 = mix(imageLoad(uLightT, ivec3(i0.x, i1.y, i0.z)), imageLoad(uLightT, ivec3(i1.x, i1.y, i0.z)), f.x);
  vec4 c01 = mix(imageLoad(uLightT, ivec3(i0.x, i0.y, i1.z)), imageLoad(uLightT, ivec3(i1.x, i0.y, i1.z)), f.x);
  vec4 c11 = mix(imageLoad(uLightT, ivec3(i0.x, i1.y, i1.z)), imageLoad(uLightT, ivec3(i1.x, i1.y, i1.z)), f.x);
  return mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
}

/* Layer a of uLightM at the point of the last light_at (the same weights): a < 3 component a of the band-1 moment
 * (rgb); with two lobes (VS_EA_ANISOTROPIC 2) layers 3 .. 5 the first order's, M_1's component a - 3 in rgb and
 * I_1's channel a - 3 in alpha (vsLightVolume.h). */
vec4 moment_layer(int a)
{
  ivec3 i0 = gLerpI0, i1 = gLerpI1;
  vec3 f = gLerpF;
  int z = a * int(P.grid.cells.z);
  i0.z += z;
  i1.z += z;
  vec4 c00 = mix(imageLoad(uLightM, ivec3(i0.x, i0.y, i0.z)), imageLoad(uLightM, ivec3(i1.x, i0.y, i0.z)), f.x);
  vec4 c10 = mix(imageLoad(uLightM, ivec3(i0.x, i1.y, i0.z)), imageLoad(uLightM, ivec3(i1.x, i1.y, i0.z)), f.x);
  vec4 c01 = mix(imageLoad(uLightM, ivec3(i0.x, i0.y, i1.z)), imageLoad(uLightM, ivec3(i1.x, i0.y, i1.z)), f.x);
  vec4 c11 = mix(imageLoad(uLightM, ivec3(i0.x, i1.y, i1.z)), imageLoad(uLightM, ivec3(i1.x, i1.y, i1.z)), f.x);
  return mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
}

/* The light volume's I at index-space point x for a camera ray along d, over 4 pi: isotropic (I / 4 pi), or with
 * VS_EA_ANISOTROPIC Henyey-Greenstein's from I and M (phase_moments.h): one lobe of all the orders (1), or the
 * first order's lobe and the other orders' (2). iso: the isotropic I / (4 pi). */
vec3 in_scattered(vec3 x, vec3 d, out vec3 iso)
{
  vec3 I = light_at(x).rgb;
  iso = I * (1.0 / (4.0 * VS_PI));
  if (VS_EA_ANISOTROPIC == 0u)
    return iso;
  vec3 mx = moment_layer(0).rgb, my = moment_layer(1).rgb, mz = moment_layer(2).rgb;
  if (VS_EA_ANISOTROPIC == 1u)
    return vs_hg_lobe_light(I, mx, my, mz, d, P.anisotropy) * (1.0 / (4.0 * VS_PI));
  vec4 fx = moment_layer(3), fy = moment_layer(4), fz = moment_layer(5);
  vec3 first = vec3(fx.a, fy.a, fz.a);
  return (vs_hg_lobe_light(first, fx.rgb, fy.rgb, fz.rgb, d, P.anisotropy) +
           vs_hg_lobe_light(max(I - first, vec3(0.0)), mx - fx.rgb, my - fy.rgb, mz - fz.rgb, d, P.anisotropy)) *
    (1.0 / (4.0 * VS_PI));
}

/* The preview's radiance towards the camera per unit collision at index-space point x (issue 38): the
 * sample's albedo, extinction sigma, the camera ray's world direction d, and I / (4 pi) of the light
 * volume there (light_at just read; phased: with the phase towards the environment, in_scattered). Without lights and the lobe:
 * albedo I / (4 pi), as before. The lobe's surface share reflects the isotropic I / (4 pi), as before. */
vec3 preview_radiance(vec3 x, vec3 albedo, float sigma, vec3 d, vec3 inScattered, vec3 phased, ivec3 dims)
{
  float ps = 0.0;
  vec3 n = vec3(0.0, 0.0, 1.0);
  vec3 kd = albedo * P.surfaceDiffuse;
  vec3 L;
  if (VS_EA_SHADE == 1u)
  {
    /* P_s and the normal as the Monte Carlo kernel's surface_event. */
    vec3 gw = vs_world_gradient(x, dims, P.volume.interpolation, P.volume.worldToIndex);
    float len = length(gw);
    if (len > 0.0 && !isinf(len))
    {
      float g = min(1.0, len * P.gradientScale);
      float alpha = 1.0 - exp(-sigma * P.opacityDistance);
      ps = vs_surface_probability(P.surfaceBlending, g, isnan(alpha) ? 0.0 : alpha);
      n = gw / len;
    }
    if (VS_EA_ANISOTROPIC == 0u)
      L = ((1.0 - ps) * albedo + ps * (kd + vec3(P.surfaceSpecular))) * inScattered;
    else
      L = (1.0 - ps) * albedo * phased + ps * (kd + vec3(P.surfaceSpecular)) * inScattered;
  }
  else
    L = albedo * phased;
  vec4 T4 = vec4(0.0);
  for (uint l = 0u; VS_EA_LIGHTS == 1u && l < P.lightCount; ++l)
  {
    if ((l & 3u) == 0u)
      T4 = transmittance_at(l >> 2u);
    vec3 xw = (gIndexToWorld * vec4(x, 1.0)).xyz;
    vec3 w;
    float distance;
    vec3 E = vs_scene_light_incident(P.lights[l], xw, w, distance);
    vec3 k = albedo * vs_hg_pdf(dot(d, w), P.anisotropy);
    if (VS_EA_SHADE == 1u)
    {
      k *= 1.0 - ps;
      if (ps > 0.0)
        k += ps * abs(dot(n, w)) * vs_surface_brdf(n, -d, w, kd, P.surfaceSpecular, P.surfaceRoughness);
    }
    L += T4[l & 3u] * E * k;
  }
  return L;
}

/* Empty-space skipping of the composite: a brick whose majorant is 0 (vsMajorantGrid.h) holds no
 * extinction, so its samples add nothing. At ray distance t (index-space ray oi + t di), the brick
 * the march enters: if empty, returns where the ray leaves the cube of empty bricks around it (at
 * chessboard distance k from the nearest non-empty brick, the cube of radius k - 1: brick_walk.h);
 * else t. tQuery: where the march asks again (the exit of the brick or of the cube). A brick outside
 * the grid (rounding at the box) is never skipped. */
float skip_empty(vec3 oi, vec3 di, vec3 invDi, float walkScale, float t, out float tQuery)
{
  float brickSize = P.volume.majorantBrickSize;
  ivec3 bricks = ivec3(P.volume.majorantBricks);
  float h = vs_walk_min_step(t, walkScale);
  ivec3 b = vs_brick_after(oi, di, t, h, 1.0 / brickSize);
  tQuery = vs_brick_cube_exit(oi, di, invDi, t, h, b, 0.0, brickSize);
  if (any(lessThan(b, ivec3(0))) || any(greaterThanEqual(b, bricks)))
    return t;
  vec3 brick = imageLoad(uBricks, b).xyz; /* majorant, control, empty-space distance */
  if (brick.x != 0.0)
    return t;
  if (brick.z > 1.0)
    tQuery = max(tQuery, vs_brick_cube_exit(oi, di, invDi, t, h, b, brick.z - 1.0, brickSize));
  return tQuery;
}

/* Writes pixel idx: the radiance (premultiplied rgb, alpha = 1 - T) and, with VS_EA_DISPLAY_IMAGE,
 * its window pixel. With VS_EA_DISPLAY_ENVIRONMENT, where nothing opaque lies in front (depth 1),
 * the environment seen through the volume, T x its radiance along d, is added to the radiance and
 * the window pixel is that of a pixel that sees the environment (vs_display_pixel). */
void write_pixel(uint idx, vec4 radiance, vec3 d, float depth)
{
  uint flags = VS_EA_WINDOW_IMAGE == 1u ? P.display : 0u;
  bool seesEnvironment = (flags & VS_EA_DISPLAY_ENVIRONMENT) != 0u && depth >= 1.0;
  vec3 background = vec3(0.0);
  if (seesEnvironment)
  {
    vec3 environment = vs_environment_bilinear(uEnvironment, P.environmentSize, d) * P.environmentScale;
    radiance.rgb += (1.0 - radiance.a) * environment;
    background = vs_display_rgb(P.exposure * environment, (flags & VS_EA_DISPLAY_TONE_MAPPING) != 0u);
  }
  uOut[idx] = radiance;
  if ((flags & VS_EA_DISPLAY_IMAGE) != 0u)
    uDisplay[idx] = vs_display_pixel(radiance, seesEnvironment, (flags & VS_EA_DISPLAY_COMPOSITE) != 0u, background,
      1.0, P.exposure, (flags & VS_EA_DISPLAY_TONE_MAPPING) != 0u);
}

void main()
{
  uvec2 pix = gl_GlobalInvocationID.xy;
  uint W = P.camera.width, H = P.camera.height;
  if (pix.x >= W || pix.y >= H)
    return;
  uint idx = pix.y * W + pix.x;
  vs_set_cropping(P.volume.cropLo, P.volume.cropHi, P.volume.cropFlags);
  if (VS_EA_LIGHTS == 1u)
    gIndexToWorld = inverse(P.volume.worldToIndex);
  VsRng rng = vs_rng_init(pix, P.camera.frame, P.camera.seed);

  vec2 ndc = (vec2(pix) + 0.5) / vec2(W, H) * 2.0 - 1.0;
  vec4 pn = P.camera.invViewProj * vec4(ndc, -1.0, 1.0);
  vec4 pf = P.camera.invViewProj * vec4(ndc, 1.0, 1.0);
  vec3 o = pn.xyz / pn.w;
  vec3 d = normalize(pf.xyz / pf.w - o);
  float depth = texelFetch(uDepth, int(idx)).r;
  float tDepth = 1e30;
  if (depth < 1.0)
  {
    vec4 pd = P.camera.invViewProj * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    tDepth = dot(pd.xyz / pd.w - o, d);
  }

  vec3 oi = (P.volume.worldToIndex * vec4(o, 1.0)).xyz;
  vec3 di = (P.volume.worldToIndex * vec4(d, 0.0)).xyz;
  vec2 t = vs_intersect_box(oi, di, P.volume.boxMin, P.volume.boxMax);
  t = vs_clip_planes(oi, di, t, P.volume.clipPlanes, P.volume.clipPlaneCount);
  t.x = max(t.x, 0.0);
  t.y = min(t.y, tDepth);

  vec3 color = vec3(0.0);
  float alpha = 0.0;
  ivec3 dims = ivec3(P.volume.dims);
  float stepSize = P.step;
  uint blend = P.blend;
  if (VS_EA_PROJECTION == 1u)
  {
    write_pixel(idx, t.x < t.y ? project(oi, di, t, stepSize, blend, vs_rng_float(rng)) : vec4(0.0), d, depth);
    return;
  }
  if (t.x < t.y)
  {
    float jitter = VS_EA_LIGHTING == VS_EA_LIGHTING_NONE ? vs_rng_float(rng) : vs_dither_offset(pix, P.ditherFrame);
    bool skip = P.volume.majorantBrickSize > 0.0;
    vec3 invDi = 1.0 / di;
    float walkScale = vs_walk_scale(oi, di);
    float tQuery = t.x; /* where the march next asks the bricks */
    float a = t.x;
    /* Across the empty space in front of the volume first, in a loop of its own: lavapipe runs every
       lane through both paths of a divergent loop body, so lanes still in the air would otherwise
       pay for their neighbours' samples, and these for the air's brick walk. */
    while (skip && a < t.y)
    {
      float next = skip_empty(oi, di, invDi, walkScale, a, tQuery);
      if (!(next > a))
        break;
      a = next;
    }
    while (a < t.y)
    {
      if (skip && a >= tQuery)
      {
        float next = skip_empty(oi, di, invDi, walkScale, a, tQuery);
        if (next > a)
        {
          a = next;
          continue;
        }
      }
      float b = min(a + stepSize, t.y);
      float ts = a + jitter * (b - a);
      vec3 x = oi + ts * di;
      vec4 c = vs_classify(vs_sample(x, dims, P.volume.interpolation), P.volume.tf);
      if (VS_EA_FACTOR == 1u)
        c.w *= vs_sample_factor(x, dims, P.volume.interpolation);
      if (c.w > 0.0)
      {
        if (VS_EA_LIGHTING == VS_EA_LIGHTING_PREVIEW)
        {
          vec3 iso;
          vec3 phased = in_scattered(x, d, iso);
          c.rgb = preview_radiance(x, c.rgb, c.w, d, iso, phased, dims);
        }
        else if (VS_EA_LIGHTING == VS_EA_LIGHTING_AMBIENT_OCCLUSION)
          c.rgb *= P.lightIntensity * light_at(x).a;
        else if (VS_EA_SHADE == 1u)
          c.rgb = shade(x, c.rgb, dims, -d);
        float A = 1.0 - exp(-c.w * (b - a));
        color += (1.0 - alpha) * A * c.rgb;
        alpha += (1.0 - alpha) * A;
        if (alpha >= P.terminationOpacity)
          break;
      }
      a = b;
    }
  }
  write_pixel(idx, vec4(color, alpha), d, depth);
}
