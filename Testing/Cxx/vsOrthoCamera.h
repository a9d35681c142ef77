// An orthographic camera along +z for the render passes' tests: NDC x, y in [-1, 1] -> world
// [lo, hi], NDC z -1 -> z0, +1 -> z1, seed 1.
#ifndef vsOrthoCamera_h
#define vsOrthoCamera_h

#include "sampling/camera_params.h"

#include <cstdint>

namespace vstest
{
inline vs::shared::VsCameraParams OrthoAlongZ(uint32_t w, uint32_t h, float lo, float hi, float z0, float z1)
{
  vs::shared::VsCameraParams c{};
  glm::mat4 m(1.0f);
  m[0][0] = 0.5f * (hi - lo);
  m[1][1] = 0.5f * (hi - lo);
  m[2][2] = 0.5f * (z1 - z0);
  m[3] = glm::vec4(0.5f * (hi + lo), 0.5f * (hi + lo), 0.5f * (z1 + z0), 1.0f);
  c.invViewProj = m;
  c.width = w;
  c.height = h;
  c.seed = 1;
  return c;
}
}

#endif
