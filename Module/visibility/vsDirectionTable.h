// vsDirectionTable.h — the grid strategies' direction maps made once per
// visibility cell (sampling/direction_table.h, direction_table.glsl): per cell,
// the 16-bit shares of every inner node of its D x D map's quadtree, which the
// render kernel descends in log2 D reads instead of building the map (2 D²
// reads and its sum pyramid) at every scatter event.
//
// The table is a pdf of its own: any table made from this environment keeps the
// estimator unbiased, even one made from an earlier state of the grid
// (visibility + ε > 0 everywhere), so it is rebuilt when the grid's contents
// change only to sample better. It must be rebuilt for a new environment,
// direction resolution or strategy (Visibility's map has no light in it).
#ifndef vsDirectionTable_h
#define vsDirectionTable_h

#include "vissweepCoreModule.h"

#include "vsVulkan.h"

#include <cstdint>
#include <memory>

namespace vs
{
class Buffer;
class ComputePipeline;
class Context;
class DeviceEnvironment;
class VisibilityGrid;

class VISSWEEPCORE_EXPORT DirectionTable
{
public:
  explicit DirectionTable(std::shared_ptr<Context> context);
  ~DirectionTable();

  /** Makes the table current for this grid, environment, strategy
   * (VS_STRATEGY_VISIBILITY, _COMBINED or _TWO_STEP) and ε: builds it unless it
   * already holds exactly these. Returns Valid(): false (and no table) when it
   * would not fit one storage buffer. */
  bool Update(const VisibilityGrid& grid, const DeviceEnvironment& environment, uint32_t strategy, float epsilon);
  /** Whether the table may be read for this grid, environment, strategy and ε
   * as it is: made for them, perhaps from an earlier state of the grid's values
   * (a valid pdf, see above). */
  bool Usable(const VisibilityGrid& grid, const DeviceEnvironment& environment, uint32_t strategy, float epsilon) const;
  /** Whether it was made from the grid's current values too. */
  bool Current(
    const VisibilityGrid& grid, const DeviceEnvironment& environment, uint32_t strategy, float epsilon) const;

  bool Valid() const { return this->Nodes_ != nullptr; }
  const Buffer& Nodes() const { return *this->Nodes_; }
  /** The builder's pipeline for a grid of this storage format, D and map (made once per process;
   *  callers may make it ahead of the first Update, on another thread). */
  static std::shared_ptr<ComputePipeline> Pipeline(
    const std::shared_ptr<Context>& context, vk::Format format, uint32_t D, uint32_t map);
  /** Bytes of the table for this many cells at D x D directions. */
  static uint64_t BytesFor(uint64_t cells, uint32_t D);
  /** Builds since this object was made, and the device seconds of the last one.
   */
  uint64_t Builds() const { return this->Builds_; }
  double LastSeconds() const { return this->LastSeconds_; }
  /** Device seconds rendered with the table since it was last built (the
   * renderer adds them): what a caller weighs against LastSeconds() to decide
   * whether to rebuild for newer values. */
  void AddSecondsUsed(double seconds) { this->SecondsUsed_ += seconds; }
  double SecondsUsed() const { return this->SecondsUsed_; }

private:
  struct Key
  {
    uint64_t Grid = 0, Environment = 0;
    uint32_t Strategy = 0, D = 0;
    uint32_t Cells[3] = { 0, 0, 0 };
    float Epsilon = 0.0f;
    /** The same layout, light, map and ε (the grid's values may differ). */
    bool Compatible(const Key& o) const
    {
      return Environment == o.Environment && Strategy == o.Strategy && D == o.D && Epsilon == o.Epsilon &&
        Cells[0] == o.Cells[0] && Cells[1] == o.Cells[1] && Cells[2] == o.Cells[2];
    }
  };
  static Key KeyOf(const VisibilityGrid& grid, const DeviceEnvironment& environment, uint32_t strategy, float epsilon);

  std::shared_ptr<Context> Context_;
  std::unique_ptr<Buffer> Nodes_;
  Key Key_;
  uint64_t Builds_ = 0;
  double LastSeconds_ = 0.0;
  double SecondsUsed_ = 0.0;
};
} // namespace vs

#endif
