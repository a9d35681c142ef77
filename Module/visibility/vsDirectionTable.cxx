#include "vsDirectionTable.h"
#include "sampling/bindings.h"
#include "sampling/direction_table.h"
#include "sampling/strategies.h"
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsDeviceEnvironment.h"
#include "vsError.h"
#include "vsImage.h"
#include "vsPipeline.h"
#include "vsVisibilityGrid.h"

#include "vs_spirv_direction_table_r16.h"
#include "vs_spirv_direction_table_r32f.h"
#include "vs_spirv_direction_table_r8.h"

#include <cstring>

namespace vs
{
DirectionTable::DirectionTable(std::shared_ptr<Context> context)
  : Context_(std::move(context))
{
}

DirectionTable::~DirectionTable() = default;

uint64_t DirectionTable::BytesFor(uint64_t cells, uint32_t D)
{
  return cells * 2u * shared::vs_table_nodes(D) * sizeof(uint32_t);
}

DirectionTable::Key DirectionTable::KeyOf(
  const VisibilityGrid& grid, const DeviceEnvironment& environment, uint32_t strategy, float epsilon)
{
  if (!grid.Valid())
  {
    throw InputError("a direction table needs a visibility grid");
  }
  if (strategy != shared::VS_STRATEGY_VISIBILITY && strategy != shared::VS_STRATEGY_COMBINED &&
    strategy != shared::VS_STRATEGY_TWO_STEP)
  {
    throw InputError("a direction table is for the grid strategies "
                     "(visibility, combined, two-step)");
  }
  Key key;
  key.Grid = grid.ContentSerial();
  key.Environment = environment.Serial();
  // Combined and TwoStep warp the same map (the product with the light).
  key.Strategy = strategy == shared::VS_STRATEGY_VISIBILITY ? strategy : uint32_t(shared::VS_STRATEGY_COMBINED);
  key.D = grid.Side();
  const auto cells = grid.Cells();
  for (int i = 0; i < 3; ++i)
  {
    key.Cells[i] = cells[i];
  }
  key.Epsilon = epsilon;
  return key;
}

bool DirectionTable::Usable(
  const VisibilityGrid& grid, const DeviceEnvironment& environment, uint32_t strategy, float epsilon) const
{
  return this->Nodes_ && KeyOf(grid, environment, strategy, epsilon).Compatible(this->Key_);
}

bool DirectionTable::Current(
  const VisibilityGrid& grid, const DeviceEnvironment& environment, uint32_t strategy, float epsilon) const
{
  return this->Usable(grid, environment, strategy, epsilon) && grid.ContentSerial() == this->Key_.Grid;
}

std::shared_ptr<ComputePipeline> DirectionTable::Pipeline(
  const std::shared_ptr<Context>& context, vk::Format format, uint32_t D, uint32_t map)
{
  using B = BindingType;
  const std::vector<B> bindings = BindingTypes(shared::VS_TABLE_BINDING_COUNT,
    { { shared::VS_TABLE_VISIBILITY, B::StorageImage }, { shared::VS_TABLE_MIPS, B::StorageBuffer },
      { shared::VS_TABLE_OUTPUT, B::StorageBuffer }, { shared::VS_TABLE_SOURCES, B::StorageBuffer } });
  const std::vector<uint32_t> specialization{ D,
    map == shared::VS_STRATEGY_VISIBILITY ? map : uint32_t(shared::VS_STRATEGY_COMBINED) };
  const std::string name = std::string("direction table (") +
    (map == shared::VS_STRATEGY_VISIBILITY ? "visibility" : "product") + ", D " + std::to_string(D);
  if (format == vk::Format::eR8Unorm)
    return SharedPipeline(context, VS_SPIRV(vs_spirv_direction_table_r8), bindings, sizeof(shared::VsDirectionTablePush), name + ", r8)", specialization);
  if (format == vk::Format::eR16Unorm)
    return SharedPipeline(
      context, VS_SPIRV(vs_spirv_direction_table_r16), bindings, sizeof(shared::VsDirectionTablePush), name + ", r16)", specialization);
  return SharedPipeline(
    context, VS_SPIRV(vs_spirv_direction_table_r32f), bindings, sizeof(shared::VsDirectionTablePush), name + ", r32f)", specialization);
}

bool DirectionTable::Update(
  const VisibilityGrid& grid, const DeviceEnvironment& environment, uint32_t strategy, float epsilon)
{
  const Key key = KeyOf(grid, environment, strategy, epsilon);
  if (this->Current(grid, environment, strategy, epsilon))
  {
    return true;
  }
  const uint32_t map = key.Strategy, D = key.D;
  const auto cells = grid.Cells();
  const uint64_t count = uint64_t(cells[0]) * cells[1] * cells[2];
  const uint64_t bytes = BytesFor(count, D);
  if (D < 2 || D > 16 || bytes == 0 || bytes > this->Context_->Info().MaxStorageBufferRange ||
    count > this->Context_->Info().MaxComputeWorkGroupCount[0] * 64ull)
  {
    this->Nodes_.reset();
    return false;
  }
  if (!this->Nodes_ || this->Nodes_->Size() != bytes)
  {
    this->Nodes_.reset();
    this->Nodes_ = std::make_unique<Buffer>(this->Context_, bytes, "direction table");
  }
  std::shared_ptr<ComputePipeline> pipeline = Pipeline(this->Context_, grid.Image().Format(), D, map);
  DescriptorSet set(*pipeline);
  set.Bind(shared::VS_TABLE_VISIBILITY, grid.Image())
    .Bind(shared::VS_TABLE_MIPS, environment.Mips())
    .Bind(shared::VS_TABLE_OUTPUT, *this->Nodes_)
    .Bind(shared::VS_TABLE_SOURCES, grid.DirectionSourceBuffer());
  shared::VsDirectionTablePush push{};
  push.cells = glm::uvec3(cells[0], cells[1], cells[2]);
  push.epsilon = epsilon;
  Batch batch(this->Context_);
  batch.BeginTimer("direction table");
  batch.Dispatch(*pipeline, set, &push, sizeof(push), uint32_t((count + 63) / 64), 1, 1);
  batch.EndTimer();
  batch.Submit();
  this->LastSeconds_ = batch.Seconds("direction table");
  ++this->Builds_;
  this->SecondsUsed_ = 0.0;
  this->Key_ = key;
  return true;
}
} // namespace vs
