#include "vsVisibilityGridUpdater.h"

#include "vsContext.h"
#include "vsError.h"
#include "vsImage.h"
#include "sampling/octahedral.h"
#include "sampling/update_order.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace vs
{
VisibilityGridUpdater::VisibilityGridUpdater(std::shared_ptr<Context> context)
  : Context_(std::move(context))
{
}

VisibilityGridUpdater::~VisibilityGridUpdater() = default;

void VisibilityGridUpdater::Invalidate()
{
  this->Signature_.clear();
  this->Swept_.clear();
}

uint32_t VisibilityGridUpdater::PendingDirections() const
{
  uint32_t pending = 0;
  for (size_t n = 0; n < this->Swept_.size(); ++n)
  {
    pending += !this->Swept_[n] && (this->Required_.empty() || this->Required_[n]);
  }
  return pending;
}

double VisibilityGridUpdater::PendingSweepSeconds() const
{
  const double pool = this->Grid_ ? this->Grid_->PoolRemainingSeconds() : 0.0;
  return pool + double(this->PendingDirections()) * this->SecondsPerDirection_;
}

uint32_t VisibilityGridUpdater::SweptDirections() const
{
  return uint32_t(std::count(this->Swept_.begin(), this->Swept_.end(), uint8_t(1)));
}

double VisibilityGridUpdater::SweptImportance() const
{
  double swept = 0.0, total = 0.0;
  for (size_t n = 0; n < this->Swept_.size(); ++n)
  {
    if (!this->Required_.empty() && !this->Required_[n])
    {
      continue;
    }
    const double w = n < this->Importance_.size() ? double(this->Importance_[n]) : 1.0;
    total += w;
    swept += this->Swept_[n] ? w : 0.0;
  }
  return total > 0.0 ? swept / total : (this->Grid() ? 1.0 : 0.0);
}

std::vector<uint32_t> VisibilityGridUpdater::FillOrder(
  uint32_t side, const std::vector<uint32_t>& candidates, const std::vector<float>& importance)
{
  // Rank of each direction in the bit-reversed Morton order: the tie-break.
  const uint32_t count = side * side;
  std::vector<uint32_t> rank(count, 0);
  for (uint32_t k = 0; k < count; ++k)
  {
    rank[shared::vs_round_robin_direction(k, side)] = k;
  }
  std::vector<uint32_t> order = candidates;
  auto weight = [&](uint32_t n) { return n < importance.size() ? importance[n] : 0.0f; };
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    if (weight(a) != weight(b))
    {
      return weight(a) > weight(b);
    }
    return rank[a] < rank[b];
  });
  return order;
}

std::vector<std::pair<uint32_t, uint32_t>> VisibilityGridUpdater::NearestSwept(
  uint32_t side, const std::vector<uint8_t>& swept, const std::vector<uint8_t>& targets)
{
  const uint32_t count = side * side;
  std::vector<glm::vec3> centre(count);
  std::vector<uint32_t> sources;
  for (uint32_t n = 0; n < count; ++n)
  {
    centre[n] = shared::vs_texel_dir(glm::uvec2(n % side, n / side), side);
    if (n < swept.size() && swept[n])
    {
      sources.push_back(n);
    }
  }
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
  if (sources.empty())
  {
    return pairs;
  }
  for (uint32_t n = 0; n < count; ++n)
  {
    if ((n < swept.size() && swept[n]) || (!targets.empty() && !(n < targets.size() && targets[n])))
    {
      continue;
    }
    uint32_t best = sources.front();
    float bestDot = -2.0f;
    for (uint32_t m : sources)
    {
      const float c = glm::dot(centre[n], centre[m]);
      if (c > bestDot)
      {
        bestDot = c;
        best = m;
      }
    }
    pairs.emplace_back(n, best);
  }
  return pairs;
}

std::vector<double> VisibilityGridUpdater::Signature(const GridUpdateRequest& r)
{
  const VisibilityGridParameters& gp = r.Parameters;
  std::vector<double> s = { double(gp.DirectionResolution), gp.VoxelsPerCell, double(gp.KernelResolution),
    double(gp.Filtering), gp.FilterAngleFraction, gp.AutoKernelRaysPerCell, gp.StepSize, double(gp.Algorithm),
    double(gp.StorageFormat), double(gp.BruteForceSamples), double(gp.StopTransmittance),
    double(gp.ExtinctionPooling), double(gp.MaxPooling), double(gp.NearestInterpolation) };
  for (const glm::vec3& w : gp.Directions)
  {
    s.insert(s.end(), { w.x, w.y, w.z });
  }
  for (const auto& pl : r.WorldPlanes)
  {
    s.insert(s.end(), { pl.x, pl.y, pl.z, pl.w });
  }
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row)
      s.push_back(r.Geometry.WorldToIndex[c][row]);
  for (int i = 0; i < 3; ++i)
  {
    s.insert(s.end(), { r.Geometry.BoxMin[i], r.Geometry.BoxMax[i], double(r.Geometry.Dims[i]) });
  }
  s.insert(s.end(), { double(r.Geometry.CropFlags), r.Geometry.CropLo.x, r.Geometry.CropLo.y, r.Geometry.CropLo.z,
                      r.Geometry.CropHi.x, r.Geometry.CropHi.y, r.Geometry.CropHi.z });
  return s;
}

GridUpdateResult VisibilityGridUpdater::Sweep(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, const GridUpdateRequest& request, std::vector<uint32_t> directions,
  const VisibilityGrid::Progress& progress)
{
  GridUpdateResult result;
  if (directions.empty())
  {
    return result;
  }
  std::sort(directions.begin(), directions.end());
  const uint64_t before = this->Grid_->DirectionsComputed();
  this->Grid_->Compute(volume, tf, majorants, request.Geometry, request.WorldPlanes, request.Parameters,
    directions.size() == this->Swept_.size() ? std::vector<uint32_t>() : directions, progress);
  result.DirectionsSwept = uint32_t(this->Grid_->DirectionsComputed() - before);
  result.Seconds = this->Grid_->LastSeconds();
  for (uint32_t n : directions)
  {
    this->Swept_[n] = 1;
  }
  if (result.DirectionsSwept > 0)
  {
    // A running estimate of one direction's cost, for the progressive budget.
    const double perDirection = result.Seconds / double(result.DirectionsSwept);
    this->SecondsPerDirection_ =
      this->SecondsPerDirection_ > 0.0 ? 0.5 * (this->SecondsPerDirection_ + perDirection) : perDirection;
  }
  return result;
}

GridUpdateResult VisibilityGridUpdater::Update(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, const GridUpdateRequest& request, const VisibilityGrid::Progress& progress)
{
  const VisibilityGridParameters& gp = request.Parameters;
  gp.Validate();
  const uint32_t side = gp.DirectionResolution;
  const uint32_t count = side * side;
  if (!request.Required.empty() && request.Required.size() != count)
  {
    throw InputError("the visibility grid needs " + std::to_string(count) + " required-direction flags, got " +
      std::to_string(request.Required.size()));
  }
  if (!this->Grid_)
  {
    this->Grid_ = std::make_unique<VisibilityGrid>(this->Context_);
  }
  GridUpdateResult result;
  std::vector<uint32_t> lazy;
  const std::vector<double> signature = Signature(request);
  const bool dataChanged = request.DataVersion != this->DataVersion_;
  if (!this->Grid_->Valid() || request.FullUpdate || signature != this->Signature_ || this->Swept_.size() != count ||
    (request.Exact && (dataChanged || this->Stale_)))
  {
    // A full invalidation: a new grid at visibility 1 (the product pdf is then environment
    // sampling), every needed direction pending.
    VisibilityGrid::CheckFits(*this->Context_, request.Geometry, gp);
    if (!this->Grid_->Allocate(request.Geometry, gp, true, 1.0f))
    {
      this->Grid_->Clear(1.0f);
    }
    this->Swept_.assign(count, 0);
    this->FillSource_.assign(count, NoFillSource);
    this->Filled_ = 0;
    this->Signature_ = signature;
    this->Scheduler_.OnFullUpdate();
    this->Allowance_ = 0.0;
    this->Stale_ = false;
    ++this->Generation_;
    result.NewGrid = true;
  }
  else if (dataChanged)
  {
    lazy = this->Scheduler_.OnDataChange(request.Schedule, side, request.Importance, request.Required);
    // The directions not in `lazy` keep an earlier data's visibility (unbiased for the Monte Carlo
    // estimate, wrong as the light of an exact request): remembered until the next full update.
    this->Stale_ = true;
  }
  this->DataVersion_ = request.DataVersion;
  this->Required_ = request.Required;
  this->Importance_ = request.Importance;

  // Needed but not swept since the last full update, brightest first.
  std::vector<uint32_t> pending;
  for (uint32_t n = 0; n < count; ++n)
  {
    if ((request.Required.empty() || request.Required[n]) && !this->Swept_[n] &&
      std::find(lazy.begin(), lazy.end(), n) == lazy.end())
    {
      pending.push_back(n);
    }
  }
  pending = FillOrder(side, pending, request.Importance);

  std::vector<uint32_t> now = lazy;
  double poolSeconds = 0.0; // progressive: the part of the pooled extinction built in this call
  if (request.FillIn && !request.Progressive)
  {
    now.insert(now.end(), pending.begin(), pending.end());
  }
  else if (request.FillIn && !pending.empty() && !result.NewGrid)
  {
    // Progressive (the call that makes a new grid sweeps nothing, so its frame does not wait).
    // The budgets of the calls accumulate into an allowance, and directions are swept while the
    // allowance covers their estimated cost: over many frames the sweeps take the budget's share
    // of the time, even when one direction costs more than one frame's budget (a sweep that
    // cost more than granted leaves a debt). The first direction is swept as soon as the pooled
    // extinction is built, whatever the allowance: its cost is unknown until then (an assumed
    // 0.1 s held the first sweep of ch2, ~0.01 s, back for 2 s at Auto's 5% share); a budget of 0
    // sweeps one direction per call.
    const double per = this->SecondsPerDirection_;
    const bool budgeted = request.BudgetSeconds > 0.0;
    if (budgeted)
    {
      this->Allowance_ += request.BudgetSeconds;
    }
    // The pooled extinction the sweeps march comes first, slab by slab within the allowance (at
    // least a slab per call; whole with a budget of 0, one unit of work per call): built whole
    // inside the first sweep it stalled that frame, about 0.5 s on the 0.5 mm MRI, and its cost
    // made the first direction look that expensive.
    bool poolReady = true;
    poolSeconds = this->Grid_->AdvancePool(volume, tf, majorants,
      budgeted ? this->Allowance_ : std::numeric_limits<double>::infinity(), poolReady);
    if (budgeted)
    {
      this->Allowance_ -= poolSeconds;
    }
    size_t n = poolReady ? 1 : 0;
    if (poolReady && budgeted && per > 0.0)
    {
      n = this->Allowance_ > 0.0 ? std::min(pending.size(), size_t(this->Allowance_ / per)) : 0;
    }
    n = std::min(n, pending.size());
    now.insert(now.end(), pending.begin(), pending.begin() + std::ptrdiff_t(n));
  }
  GridUpdateResult swept = this->Sweep(volume, tf, majorants, request, now, progress);
  if (request.FillUnswept && swept.DirectionsSwept > 0 && this->PendingDirections() > 0)
  {
    // The still unswept directions read their nearest swept neighbour's visibility in every cell
    // (until they are swept): a redirection, no copy (VisibilityGrid::RedirectDirections). Copies
    // cost ch2's progressive sweeps 3-4x their own device time and took that out of their
    // allowance. Only what changed is redirected: a direction whose nearest swept one is new.
    auto pairs = NearestSwept(side, this->Swept_, request.Required);
    pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                  [&](const std::pair<uint32_t, uint32_t>& p) { return this->FillSource_[p.first] == p.second; }),
      pairs.end());
    this->Grid_->RedirectDirections(pairs);
    for (const auto& [to, from] : pairs)
    {
      this->FillSource_[to] = from;
    }
    this->Filled_ += pairs.size();
  }
  if (request.Progressive && request.BudgetSeconds > 0.0)
  {
    this->Allowance_ -= swept.Seconds; // may go negative: a debt paid by later grants
  }
  swept.Seconds += poolSeconds;
  swept.NewGrid = result.NewGrid;
  return swept;
}

GridUpdateResult VisibilityGridUpdater::Complete(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, const GridUpdateRequest& request, const VisibilityGrid::Progress& progress)
{
  if (!this->Grid())
  {
    throw InputError("the visibility grid is not computed yet");
  }
  std::vector<uint32_t> missing;
  for (uint32_t n = 0; n < this->Swept_.size(); ++n)
  {
    if (!this->Swept_[n])
    {
      missing.push_back(n);
    }
  }
  return this->Sweep(volume, tf, majorants, request, missing, progress);
}
}
