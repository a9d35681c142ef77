// vsPipeline.h — a compute pipeline made from embedded SPIR-V, its descriptor
// set layout (one set; binding i has type Bindings[i]) and a push-constant block;
// and DescriptorSet, the resources bound for one dispatch.
#ifndef vsPipeline_h
#define vsPipeline_h

#include "vsVulkan.h"
#include "vissweepCoreModule.h"

#include <memory>
#include <string>
#include <initializer_list>
#include <utility>
#include <vector>

namespace vs
{
class Buffer;
class Context;
class Image3D;

enum class BindingType
{
  StorageBuffer,
  StorageImage,
  /** A Buffer read through its TexelView (GLSL: samplerBuffer / usamplerBuffer, texelFetch). */
  UniformTexelBuffer
};

/** A shader's descriptor set layout from its bindings named in bindings.h: each type at its binding
 *  number, e.g. `BindingTypes(VS_RANGES_BINDING_COUNT, { { VS_RANGES_VOLUME, BindingType::StorageImage },
 *  { VS_RANGES_OUTPUT, BindingType::StorageBuffer } })`. A number outside [0, count), given twice or
 *  left out is a programming error (std::logic_error naming it). */
VISSWEEPCORE_EXPORT std::vector<BindingType> BindingTypes(
  uint32_t count, std::initializer_list<std::pair<uint32_t, BindingType>> types);

class VISSWEEPCORE_EXPORT ComputePipeline
{
public:
  /** `specialization`: the values of the shader's specialization constants 0, 1, ... (uint32
   *  each). They are folded into the module before the driver compiles it, and the code they make
   *  unreachable removed (vsSpirvSpecialization.h), where the context does so; else, or if that
   *  fails, the driver gets the module whole with the values as specialization info. */
  ComputePipeline(std::shared_ptr<Context> context, const uint32_t* spirv, size_t spirvBytes,
    std::vector<BindingType> bindings, uint32_t pushConstantBytes, const std::string& name,
    const std::vector<uint32_t>& specialization = {});
  ~ComputePipeline();
  ComputePipeline(const ComputePipeline&) = delete;
  ComputePipeline& operator=(const ComputePipeline&) = delete;

  vk::Pipeline Handle() const { return this->Pipeline_; }
  vk::PipelineLayout Layout() const { return this->Layout_; }
  vk::DescriptorSetLayout SetLayout() const { return this->SetLayout_; }
  const std::vector<BindingType>& Bindings() const { return this->Bindings_; }
  uint32_t PushConstantBytes() const { return this->PushBytes_; }
  const std::string& Name() const { return this->Name_; }
  /** Whether the driver got the module with its specialization constants folded in (see above). */
  bool SpecializedAhead() const { return this->SpecializedAhead_; }
  /** Why it did not where the context does so (the optimizer's message); empty otherwise. */
  const std::string& SpecializationProblem() const { return this->SpecializationProblem_; }
  std::shared_ptr<Context> GetContext() const { return this->Context_.lock(); }

private:
  std::weak_ptr<Context> Context_; // the context's pipeline cache owns pipelines: no cycle
  vk::Device Device_;
  std::string Name_;
  std::vector<BindingType> Bindings_;
  uint32_t PushBytes_ = 0;
  bool SpecializedAhead_ = false;
  std::string SpecializationProblem_;
  vk::ShaderModule Module_;
  vk::DescriptorSetLayout SetLayout_;
  vk::PipelineLayout Layout_;
  vk::Pipeline Pipeline_;
};

/** The resources of one pipeline's descriptor set; owns its small pool. */
class VISSWEEPCORE_EXPORT DescriptorSet
{
public:
  explicit DescriptorSet(const ComputePipeline& pipeline);
  ~DescriptorSet();
  DescriptorSet(const DescriptorSet&) = delete;
  DescriptorSet& operator=(const DescriptorSet&) = delete;

  DescriptorSet& Bind(uint32_t binding, const Buffer& buffer);
  /** A buffer as uniform texel buffer of `format` texels. */
  DescriptorSet& BindTexels(uint32_t binding, const Buffer& buffer, vk::Format format);
  DescriptorSet& Bind(uint32_t binding, const Image3D& image);

  vk::DescriptorSet Handle() const { return this->Set_; }

private:
  std::shared_ptr<Context> Context_;
  std::string PipelineName_;
  std::vector<BindingType> Bindings_;
  vk::DescriptorPool Pool_;
  vk::DescriptorSet Set_;
};

/** The context's pipeline named `name`, compiled on first use and shared by every pass of the
 *  process (compiling takes seconds on lavapipe). */
VISSWEEPCORE_EXPORT std::shared_ptr<ComputePipeline> SharedPipeline(const std::shared_ptr<Context>& context,
  const uint32_t* spirv, size_t spirvBytes, std::vector<BindingType> bindings, uint32_t pushConstantBytes,
  const std::string& name, const std::vector<uint32_t>& specialization = {});

/** The embedded SPIR-V of a shader, as compiled at build time (vs_spirv_<name>). */
#define VS_SPIRV(array) array, sizeof(array)
}

#endif
