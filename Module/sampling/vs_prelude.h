/*
 * vs_prelude.h — the common ground of the sampling math shared by GLSL and C++.
 *
 * Every header in this folder compiles twice: included by the compute shaders
 * (GLSL 4.60, with GL_GOOGLE_include_directive) and included by C++ code and
 * the CPU unit tests, where GLM provides the GLSL vector types and built-ins.
 * Write in the common subset: GLSL types (vec3, uint, uvec4), GLSL built-ins,
 * no constructors of structs (write an init function), no references except
 * through VS_INOUT/VS_OUT, every function marked VS_FUNC.
 */
#ifndef VS_PRELUDE_H
#define VS_PRELUDE_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/integer.hpp>
#define VS_NAMESPACE_BEGIN                                                                         \
  namespace vs                                                                                     \
  {                                                                                                \
  namespace shared                                                                                 \
  {                                                                                                \
  using namespace glm;
#define VS_NAMESPACE_END                                                                           \
  }                                                                                                \
  }
#define VS_FUNC inline
#define VS_INOUT(T) T&
#define VS_OUT(T) T&
#define VS_CONST constexpr
#define VS_MAP_PARAM const float *values,
#define VS_MAP_ARG values,
#define VS_MAP(i) values[i]
#define VS_MIPS_PARAM const float *mips,
#define VS_MIPS_ARG mips,
#define VS_MIPS(i) mips[i]
#define VS_TABLE_PARAM const uint32_t *table,
#define VS_TABLE_ARG table,
#define VS_TABLE(i) table[i]
#else
#define VS_NAMESPACE_BEGIN
#define VS_NAMESPACE_END
#define VS_FUNC
#define VS_INOUT(T) inout T
#define VS_OUT(T) out T
#define VS_CONST const
#define VS_MAP_PARAM
#define VS_MAP_ARG
#define VS_MAP(i) vs_map_value(i)
#define VS_MIPS_PARAM
#define VS_MIPS_ARG
#define VS_MIPS(i) vs_env_mip(i)
#define VS_TABLE_PARAM
#define VS_TABLE_ARG
#define VS_TABLE(i) vs_table_value(i)
#endif

/* The small tabulated direction maps (visibility or product, D x D <= 256 values)
 * the strategies warp: in C++ a `const float* values` argument (VS_MAP_PARAM /
 * VS_MAP_ARG); in GLSL the one map of the invocation, which the shader keeps in a
 * module-scope array and exposes as `float vs_map_value(uint n)`. GLSL passes arrays
 * by value, and copying a 256-float map into every call made lavapipe spend minutes
 * compiling the render shader. VS_MAP(i) reads entry i either way.
 * The environment's importance quadtree (warp.h, "env mips") is read the same way: VS_MIPS(i)
 * is `mips[i]` of a `const float* mips` argument in C++ (VS_MIPS_PARAM / VS_MIPS_ARG, first in
 * the parameter list), the shader's `float vs_env_mip(uint i)` (its storage buffer) in GLSL.
 * The precomputed direction tables (direction_table.h) are read the same way: VS_TABLE(i)
 * is `table[i]` of a `const uint32_t* table` argument in C++, the shader's
 * `uint vs_table_value(uint i)` (its storage buffer) in GLSL. */

VS_NAMESPACE_BEGIN

VS_CONST float VS_PI = 3.14159265358979323846f;
VS_CONST float VS_INV_PI = 0.31830988618379067154f;
VS_CONST float VS_INV_4PI = 0.07957747154594766788f;
/* The largest float below 1: samples in [0,1) stay below 1 after rounding. */
VS_CONST float VS_ONE_MINUS_EPSILON = 0.99999994f;
/* Clip planes the passes take (render, emission-absorption, sweeps): vtkGPUVolumeRayCastMapper's
 * limit. The host first drops the planes that clip nothing of the box (vsVolumeInput.h
 * EffectiveClipPlanes), so only planes that cut the volume count. */
VS_CONST uint VS_MAX_CLIP_PLANES = 8u;

/* |a| with the sign of b (GLSL has no copysign). */
VS_FUNC float vs_copysign(float a, float b)
{
  return b < 0.0f ? -abs(a) : abs(a);
}

/* The luminance weights of linear Rec. 709 RGB, written once: vs_luminance takes them in float
 * (GLSL and C++ alike); host code that sums luminance in double takes the same decimals in double
 * (`const double w[3] = { VS_LUMINANCE_WEIGHTS };`, vsDeviceEnvironment.cxx). A list of decimals
 * rather than a typed constant, so that each reads them at its own precision. */
#define VS_LUMINANCE_WEIGHTS 0.2126, 0.7152, 0.0722

VS_FUNC float vs_luminance(vec3 c)
{
  return dot(c, vec3(VS_LUMINANCE_WEIGHTS));
}

VS_NAMESPACE_END

#endif
