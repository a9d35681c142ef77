// The walk through a majorant grid's bricks (sampling/brick_walk.h), as the render kernel's
// majorant_segment and the sweeps' empty-space skip take it: the exit distance of a box is exact,
// a walk's segments tile the ray, each lies in the brick it was picked for, and a walk takes no
// more segments than the bricks the ray crosses (a 3D DDA's count) plus rounding slivers.
#include "sampling/brick_walk.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace vs::shared;

namespace
{
glm::vec3 RandomDirection(std::mt19937& rng)
{
  std::normal_distribution<float> n;
  glm::vec3 d;
  do
    d = glm::vec3(n(rng), n(rng), n(rng));
  while (glm::length(d) < 1e-3f);
  return glm::normalize(d);
}

glm::vec3 Reciprocal(glm::vec3 d)
{
  return glm::vec3(1.0f) / d;
}

// The bricks a segment from a to b crosses, counted as a 3D DDA steps: one plus the faces crossed
// on each axis.
int DdaBrickCount(glm::vec3 a, glm::vec3 b, float brickSize)
{
  glm::ivec3 ba(glm::floor(a / brickSize)), bb(glm::floor(b / brickSize));
  glm::ivec3 n = glm::abs(bb - ba);
  return 1 + n.x + n.y + n.z;
}
}

TEST(BrickWalk, BoxExitDistanceIsTheNearestFaceAhead)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i)
  {
    glm::vec3 lo(u(rng) * 10.0f - 5.0f, u(rng) * 10.0f - 5.0f, u(rng) * 10.0f - 5.0f);
    glm::vec3 hi = lo + glm::vec3(0.5f + 4.0f * u(rng), 0.5f + 4.0f * u(rng), 0.5f + 4.0f * u(rng));
    glm::vec3 p = glm::mix(lo, hi, glm::vec3(u(rng), u(rng), u(rng)));
    glm::vec3 d = RandomDirection(rng);
    float e = vs_box_exit_distance(p, d, Reciprocal(d), lo, hi);
    ASSERT_GE(e, 0.0f) << i;
    glm::vec3 x = p + e * d;
    // The exit point is on the box: inside up to rounding, and on one of its faces.
    float tol = 1e-5f * (1.0f + glm::length(hi - lo) + glm::length(p));
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(x, lo - tol)) && glm::all(glm::lessThanEqual(x, hi + tol))) << i;
    glm::vec3 toFace = glm::min(glm::abs(x - lo), glm::abs(x - hi));
    EXPECT_LT(glm::min(toFace.x, glm::min(toFace.y, toFace.z)), tol) << i;
    // And no earlier point of the ray is outside: just before the exit the ray is strictly inside.
    glm::vec3 before = p + 0.999f * e * d;
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(before, lo - tol)) && glm::all(glm::lessThanEqual(before, hi + tol))) << i;
  }
  // Axes the ray runs parallel to never bound it: the exit is the face ahead on the moving axis.
  glm::vec3 d(0.0f, 0.0f, -1.0f);
  EXPECT_FLOAT_EQ(vs_box_exit_distance(glm::vec3(1.0f, 1.0f, 1.5f), d, Reciprocal(d), glm::vec3(0.0f), glm::vec3(2.0f)), 1.5f);
  d = glm::vec3(1.0f, 0.0f, 0.0f);
  EXPECT_FLOAT_EQ(vs_box_exit_distance(glm::vec3(0.25f, 0.0f, 2.0f), d, Reciprocal(d), glm::vec3(0.0f), glm::vec3(2.0f)), 1.75f);
}

TEST(BrickWalk, SegmentsTileTheRayBrickByBrick)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const float brickSizes[] = { 1.0f, 8.0f, 16.0f };
  int slivers = 0, segments = 0;
  for (int i = 0; i < 600; ++i)
  {
    const float size = brickSizes[i % 3];
    const float extent = 64.0f * size / 8.0f;
    glm::vec3 o(u(rng) * extent, u(rng) * extent, u(rng) * extent);
    glm::vec3 d = RandomDirection(rng) * (0.25f + 4.0f * u(rng)); // not unit length: t is not distance
    if (i % 7 == 0)
      d[i % 3] = 0.0f; // parallel to a face
    const glm::vec3 invD = Reciprocal(d);
    const float invLength = 1.0f / glm::length(d);
    const float scale = vs_walk_scale(o, d);
    const float t0 = u(rng), t1 = t0 + extent * invLength * (0.1f + u(rng));
    int n = 0;
    float t = t0;
    while (t < t1)
    {
      const float h = vs_walk_min_step(t, scale);
      const glm::ivec3 b = vs_brick_after(o, d, t, h, 1.0f / size);
      const float tExit = vs_brick_cube_exit(o, d, invD, t, h, b, 0.0f, size);
      ASSERT_GE(tExit, t + h) << i << " segment " << n; // always forward, by at least h
      const float tEnd = std::min(tExit, t1);
      // The segment's interior lies in brick b (its ends may sit on faces, up to rounding).
      const glm::vec3 mid = o + 0.5f * (t + tEnd) * d;
      if (tEnd - t > 4.0f * h)
        EXPECT_EQ(glm::ivec3(glm::floor(mid / size)), b) << i << " segment " << n;
      else
        ++slivers;
      t = tExit;
      ++n;
      ASSERT_LT(n, 10000) << i;
    }
    segments += n;
    // No more segments than the bricks crossed, but for slivers at a corner where faces meet (a
    // shortest step below a float ulp of the point's coordinates crawled: 13 segments for 7 bricks).
    EXPECT_LE(n, DdaBrickCount(o + t0 * d, o + t1 * d, size) + 2) << i;
  }
  EXPECT_LT(slivers, segments / 100); // slivers are rounding, not the rule
}

TEST(BrickWalk, TheShortestStepMovesThePoint)
{
  // From a scatter point deep in a volume (coordinates in the hundreds of voxels) a shadow ray starts
  // at t = 0: its shortest step must still move the point, or the walk stalls at a brick face.
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 10000; ++i)
  {
    const glm::vec3 o(u(rng) * 512.0f, u(rng) * 512.0f, u(rng) * 512.0f);
    const glm::vec3 d = RandomDirection(rng) * (0.1f + 4.0f * u(rng));
    const float t = i % 2 ? 0.0f : u(rng) * 300.0f;
    const float h = vs_walk_min_step(t, vs_walk_scale(o, d));
    const glm::vec3 p = o + t * d, q = o + (t + h) * d;
    ASSERT_GT(glm::length(q - p), 0.0f) << i;
    ASSERT_GT(t + h, t) << i;
  }
}

TEST(BrickWalk, ACubeOfEmptyBricksIsCrossedInOneStep)
{
  // A ray from the centre brick of a cube of radius r leaves it where it leaves the cube's box,
  // after crossing what a brick-by-brick walk takes several segments for.
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const float size = 8.0f;
  for (int i = 0; i < 500; ++i)
  {
    const glm::ivec3 b(10 + int(u(rng) * 5), 10 + int(u(rng) * 5), 10 + int(u(rng) * 5));
    const float r = float(1 + i % 3);
    const glm::vec3 o = (glm::vec3(b) + glm::vec3(u(rng), u(rng), u(rng))) * size;
    const glm::vec3 d = RandomDirection(rng);
    const glm::vec3 invD = Reciprocal(d);
    const float h = vs_walk_min_step(0.0f, vs_walk_scale(o, d));
    const float tCube = vs_brick_cube_exit(o, d, invD, 0.0f, h, b, r, size);
    const glm::vec3 lo = (glm::vec3(b) - r) * size, hi = (glm::vec3(b) + r + 1.0f) * size;
    EXPECT_NEAR(tCube, vs_box_exit_distance(o, d, invD, lo, hi), 1e-4f) << i;
    // The exit is on the cube's boundary: a brick-by-brick walk reaches the same point.
    float t = 0.0f;
    int steps = 0;
    while (t < tCube - 1e-3f && steps < 1000)
    {
      const float hs = vs_walk_min_step(t, vs_walk_scale(o, d));
      const glm::ivec3 bb = vs_brick_after(o, d, t, hs, 1.0f / size);
      const glm::ivec3 off = glm::abs(bb - b);
      EXPECT_LE(std::max(off.x, std::max(off.y, off.z)), int(r)) << i; // every brick before the exit is in the cube
      t = vs_brick_cube_exit(o, d, invD, t, hs, bb, 0.0f, size);
      ++steps;
    }
    EXPECT_NEAR(t, tCube, 1e-3f) << i;
    EXPECT_GE(steps, 1) << i;
  }
}
