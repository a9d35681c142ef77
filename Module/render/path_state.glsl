/*
 * path_state.glsl — a path in flight, kept per pixel between dispatches (full transport, mc_path.glsl).
 * A dispatch stops when its loop budget is spent (mc_render.glsl), possibly in the middle of a path;
 * the path's state is stored exactly (its bits) and the next dispatch continues it, so a pixel's
 * samples are the same bits for any split into dispatches. The random stream needs only its counter:
 * its key is the pixel, the sample's index and the seed (rng.h). Included once, by mc_render.glsl.
 */

layout(std430, binding = VS_MC_PATH_POSITION) buffer PathPosition { vec4 uPathPosition[]; };
layout(std430, binding = VS_MC_PATH_DIRECTION) buffer PathDirection { vec4 uPathDirection[]; };
layout(std430, binding = VS_MC_PATH_THROUGHPUT) buffer PathThroughput { vec4 uPathThroughput[]; };
layout(std430, binding = VS_MC_PATH_RADIANCE) buffer PathRadiance { vec4 uPathRadiance[]; };

struct Path
{
  bool inFlight;      /* a path is in flight: its next segment continues it */
  vec3 x;             /* index space: the last scattering event, where the next ray starts */
  uint events;        /* scattering events so far */
  vec3 dw;            /* world space: the direction of the next ray (unit) */
  uint counter;       /* the sample's random stream's counter */
  vec3 beta;          /* the throughput: the product of the events' weights */
  float escapeWeight; /* the MIS weight of the environment the next ray sees if it escapes */
  vec4 L;             /* what the path has gathered so far: (rgb radiance, alpha) */
};

Path path_idle()
{
  Path p;
  p.inFlight = false;
  p.x = vec3(0.0);
  p.events = 0u;
  p.dw = vec3(0.0, 0.0, 1.0);
  p.counter = 0u;
  p.beta = vec3(1.0);
  p.escapeWeight = 1.0;
  p.L = vec4(0.0);
  return p;
}

/* The in-flight flag is position.w: 0 idle (what the host's Reset clears it to), else events + 1. */
Path path_load(uint idx)
{
  vec4 a = uPathPosition[idx];
  uint flag = floatBitsToUint(a.w);
  if (flag == 0u)
    return path_idle();
  vec4 b = uPathDirection[idx];
  vec4 c = uPathThroughput[idx];
  Path p;
  p.inFlight = true;
  p.x = a.xyz;
  p.events = flag - 1u;
  p.dw = b.xyz;
  p.counter = floatBitsToUint(b.w);
  p.beta = c.xyz;
  p.escapeWeight = c.w;
  p.L = uPathRadiance[idx];
  return p;
}

void path_store(uint idx, Path p)
{
  uPathPosition[idx] = vec4(p.x, uintBitsToFloat(p.inFlight ? p.events + 1u : 0u));
  if (!p.inFlight)
    return;
  uPathDirection[idx] = vec4(p.dw, uintBitsToFloat(p.counter));
  uPathThroughput[idx] = vec4(p.beta, p.escapeWeight);
  uPathRadiance[idx] = p.L;
}
