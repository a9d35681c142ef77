/*
 * scene_lights.glsl — VTK's lights in the path kernel (issue 38; sampling/scene_lights.h): at every
 * scattering event, beside the environment's next-event estimation, each light of P.lights is lit
 * with a ratio-tracked shadow ray (to the light, or to where the ray leaves the volume),
 *     beta k(w) T(x -> light) E(x),
 * k the event's kernel towards the light (albedo x f_HG, or hybrid scattering's mixture with
 * VS_SPEC_SURFACE) and E the light's irradiance at x. Delta lights cannot be found by the continuation,
 * so they need no MIS weight. Compiled only into the pipelines with VS_SPEC_LIGHTS (a renderer with
 * lights the estimate takes: Rendering/vsSceneLights.cxx): the others keep their code and bits.
 * The shadow rays share the sample's shadow-ray budget with the environment's (main: a light counts as
 * one more shadow ray per event). Included once, by mc_render.glsl, after light_samples.
 */

uint gLightCount;  /* P.lightCount (main) */
mat4 gIndexToWorld; /* the inverse of gWorldToIndex (main, with VS_SPEC_LIGHTS) */

/* The sum over the lights of k(w) T E at index-space point x of a path that arrived along world
 * direction dw, the event's albedo `albedo` (the kernel's without the surface lobe). */
vec3 scene_light_samples(vec3 x, vec3 dw, vec3 albedo, inout VsRng rng, uint scatterCostPerRay, inout uint shadowCost)
{
  vec3 sum = vec3(0.0);
  vec3 xw = (gIndexToWorld * vec4(x, 1.0)).xyz;
  uint shadowLeft = gShadowLeft;
  for (uint i = 0u; i < gLightCount; ++i)
  {
    vec3 w;
    float distance;
    vec3 E = vs_scene_light_incident(P.lights[i], xw, w, distance);
    vec3 k;
    if (VS_SPEC_SURFACE != 0u)
    {
      float ignored;
      k = event_kernel(dw, w, ignored);
    }
    else
      k = albedo * vs_hg_pdf(dot(dw, w), gAnisotropy);
    uint steps = 0u;
    if (any(greaterThan(E * k, vec3(0.0))))
    {
      vec3 di = (gWorldToIndex * vec4(w, 0.0)).xyz;
      vec2 ts = ray_interval(x, di);
      float T = shadow_transmittance(x, di, 0.0, min(ts.y, distance), vec2(-1.0), rng,
        min(VS_TRACKING_CAP, max(shadowLeft, 1u)), steps);
      sum += T * E * k;
    }
    uint groupSteps = subgroupMax(steps);
    shadowLeft -= min(shadowLeft, groupSteps);
    shadowCost += groupSteps + scatterCostPerRay;
  }
  gShadowLeft = shadowLeft;
  return sum;
}
