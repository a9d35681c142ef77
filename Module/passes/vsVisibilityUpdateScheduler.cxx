#include "vsVisibilityUpdateScheduler.h"
#include "vsError.h"

#include "shared/rng.h"
#include "shared/update_order.h"

#include <algorithm>
#include <string>

namespace vs
{
std::vector<uint32_t> VisibilityUpdateScheduler::AllDirections(uint32_t side)
{
  std::vector<uint32_t> all(size_t(side) * side);
  for (uint32_t n = 0; n < all.size(); ++n)
  {
    all[n] = n;
  }
  return all;
}

std::vector<uint32_t> VisibilityUpdateScheduler::OnDataChange(
  const UpdateSchedule& schedule, uint32_t side, const std::vector<float>& importance)
{
  if (side < 1 || side > 64 || (side & (side - 1)) != 0)
  {
    throw InputError("lazy visibility updates need a power-of-two direction resolution, got " + std::to_string(side));
  }
  const uint32_t k = std::max(1u, schedule.DirectionsPerFrame);
  switch (schedule.Scheme)
  {
    case UpdateScheme::RoundRobin:
      return this->NextRoundRobin(side, k);
    case UpdateScheme::EnvironmentGuided:
      return this->DrawFromEnvironment(side, k, importance, schedule.Seed);
    case UpdateScheme::Static:
      if (++this->SinceRefresh_ < std::max(1u, schedule.StaticInterval))
      {
        return {};
      }
      this->SinceRefresh_ = 0;
      return AllDirections(side);
    default:
      return AllDirections(side);
  }
}

std::vector<uint32_t> VisibilityUpdateScheduler::NextRoundRobin(uint32_t side, uint32_t k)
{
  const uint32_t count = side * side;
  std::vector<uint32_t> out;
  for (uint32_t i = 0; i < std::min(k, count); ++i)
  {
    out.push_back(shared::vs_round_robin_direction(uint32_t(this->RoundRobinNext_ % count), side));
    ++this->RoundRobinNext_;
  }
  return out;
}

// k distinct directions, each drawn with probability proportional to its importance among
// those not drawn yet (sampling without replacement); directions of zero importance never.
std::vector<uint32_t> VisibilityUpdateScheduler::DrawFromEnvironment(
  uint32_t side, uint32_t k, const std::vector<float>& importance, uint32_t seed)
{
  if (importance.size() != size_t(side) * side)
  {
    throw InputError("environment-guided updates need " + std::to_string(side * side) +
      " importance weights (the environment at the grid's resolution), got " + std::to_string(importance.size()));
  }
  std::vector<double> w(importance.begin(), importance.end());
  for (double& x : w)
  {
    x = x > 0.0 ? x : 0.0; // NaN and negatives carry no light
  }
  shared::VsRng rng = shared::vs_rng_init(glm::uvec2(this->Draws_++, 0u), 0x5eedu, seed);
  std::vector<uint32_t> out;
  while (out.size() < k)
  {
    double total = 0.0;
    for (double x : w)
    {
      total += x;
    }
    if (!(total > 0.0))
    {
      break; // every lit direction is drawn already
    }
    const double u = double(shared::vs_rng_float(rng)) * total;
    double sum = 0.0;
    uint32_t chosen = 0;
    for (uint32_t n = 0; n < w.size(); ++n)
    {
      if (w[n] > 0.0)
      {
        chosen = n; // the last positive one, in case rounding leaves u >= sum
        sum += w[n];
        if (u < sum)
        {
          break;
        }
      }
    }
    out.push_back(chosen);
    w[chosen] = 0.0;
  }
  return out;
}
}
