#include "vsVisibilityUpdateScheduler.h"
#include "vsError.h"

#include "sampling/rng.h"
#include "sampling/update_order.h"

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

std::vector<uint32_t> VisibilityUpdateScheduler::OnDataChange(const UpdateSchedule& schedule, uint32_t side,
  const std::vector<float>& importance, const std::vector<uint8_t>& eligible)
{
  if (side < 1 || side > 64 || (side & (side - 1)) != 0)
  {
    throw InputError("lazy visibility updates need a power-of-two direction resolution, got " + std::to_string(side));
  }
  if (!eligible.empty() && eligible.size() != size_t(side) * side)
  {
    throw InputError("lazy visibility updates need " + std::to_string(side * side) +
      " eligibility flags (one per direction), got " + std::to_string(eligible.size()));
  }
  auto isEligible = [&](uint32_t n) { return eligible.empty() || eligible[n] != 0; };
  auto allEligible = [&]() {
    std::vector<uint32_t> out;
    for (uint32_t n : AllDirections(side))
    {
      if (isEligible(n))
      {
        out.push_back(n);
      }
    }
    return out;
  };
  const uint32_t k = std::max(1u, schedule.DirectionsPerFrame);
  switch (schedule.Scheme)
  {
    case UpdateScheme::RoundRobin:
      return this->NextRoundRobin(side, k, eligible);
    case UpdateScheme::EnvironmentGuided:
    {
      if (eligible.empty())
      {
        return this->DrawFromEnvironment(side, k, importance, schedule.Seed);
      }
      std::vector<float> masked = importance;
      for (size_t n = 0; n < masked.size() && n < eligible.size(); ++n)
      {
        masked[n] = eligible[n] ? masked[n] : 0.0f;
      }
      return this->DrawFromEnvironment(side, k, masked, schedule.Seed);
    }
    case UpdateScheme::Static:
      if (++this->SinceRefresh_ < std::max(1u, schedule.StaticInterval))
      {
        return {};
      }
      this->SinceRefresh_ = 0;
      return allEligible();
    default:
      return allEligible();
  }
}

// The next k eligible directions of the update order; ineligible ones are passed over (they
// still advance the position, so the order stays the same cycle whatever is eligible).
std::vector<uint32_t> VisibilityUpdateScheduler::NextRoundRobin(
  uint32_t side, uint32_t k, const std::vector<uint8_t>& eligible)
{
  const uint32_t count = side * side;
  std::vector<uint32_t> out;
  for (uint32_t step = 0; step < count && out.size() < k; ++step)
  {
    const uint32_t n = shared::vs_round_robin_direction(uint32_t(this->RoundRobinNext_ % count), side);
    ++this->RoundRobinNext_;
    if (eligible.empty() || eligible[n])
    {
      out.push_back(n);
    }
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
