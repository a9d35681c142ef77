/*
 * scene_lights.h — VTK's lights as lights of the Monte Carlo estimate (issue 38), beside the
 * environment: directional lights, and positional ones (point and spot) with VTK's attenuation, cone
 * angle and exponent. Shared by the path kernel (scene_lights.glsl: next-event estimation with a
 * ratio-tracked shadow ray at every event) and the host (Rendering/vsSceneLights.cxx fills them from
 * the renderer's vtkLights; the CPU tests check the falloff).
 *
 * Units: a VTK light of intensity I and colour c is, here, a delta light whose irradiance on a plane
 * facing it is E = pi I c (a directional light everywhere; a positional light at distance r, times VTK's
 * attenuation 1 / (a0 + a1 r + a2 r^2) and the spot's (cos phi)^exponent inside its cone, 0 outside).
 * pi so that a white Lambert surface facing a light of intensity 1 reflects radiance 1, VTK's diffuse
 * term (and a sky of radiance 1 gives the same irradiance on a plane as a light of intensity 1 facing
 * it). VTK's default attenuation (1, 0, 0) does not fall off with distance; (0, 0, 1) is the physical
 * inverse square.
 */
#ifndef VS_SCENE_LIGHTS_H
#define VS_SCENE_LIGHTS_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* Lights the estimate takes at most (the renderer's switched-on lights beyond it are left out, with a
 * warning). */
VS_CONST uint VS_MAX_SCENE_LIGHTS = 8u;

VS_CONST uint VS_LIGHT_DIRECTIONAL = 0u; /* along `direction` everywhere */
VS_CONST uint VS_LIGHT_POSITIONAL = 1u;  /* from `position` (a spot where cosCone > -1) */

/* One light, four std430 rows (the layout rule of volume_params.h). World space. */
struct VsSceneLight
{
  vec3 position;    /* positional: where it is */
  uint kind;        /* VS_LIGHT_* */
  vec3 direction;   /* unit: the direction the light travels (VTK's position -> focal point) */
  float cosCone;    /* a spot's cos(cone angle); -2: no cone (VTK's cone angle >= 90 degrees) */
  vec3 irradiance;  /* pi x intensity x colour: E on a plane facing it (before attenuation and spot) */
  float exponent;   /* the spot's exponent */
  vec3 attenuation; /* VTK's (constant, linear, quadratic) attenuation of a positional light */
  float pad;
};

/* What light `l` sends to world point x: the unit direction w towards it, the distance to it (1e30 for a
 * directional light), and the irradiance it gives a plane facing it at x (0 outside a spot's cone, or
 * where the attenuation is not positive). */
VS_FUNC vec3 vs_scene_light_incident(VsSceneLight l, vec3 x, VS_OUT(vec3) w, VS_OUT(float) distance)
{
  if (l.kind == VS_LIGHT_DIRECTIONAL)
  {
    w = -l.direction;
    distance = 1e30f;
    return l.irradiance;
  }
  vec3 d = l.position - x;
  float r = length(d);
  distance = r;
  w = r > 0.0f ? d / r : -l.direction;
  float a = l.attenuation.x + l.attenuation.y * r + l.attenuation.z * r * r;
  if (!(a > 0.0f) || !(r > 0.0f))
  {
    return vec3(0.0f);
  }
  float spot = 1.0f;
  if (l.cosCone > -1.5f)
  {
    float c = dot(-w, l.direction); /* the cosine off the spot's axis */
    if (c < l.cosCone)
    {
      return vec3(0.0f);
    }
    spot = l.exponent > 0.0f ? pow(max(c, 0.0f), l.exponent) : 1.0f;
  }
  return l.irradiance * (spot / a);
}

VS_NAMESPACE_END

#endif
