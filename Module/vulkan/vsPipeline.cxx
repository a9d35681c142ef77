#include "vsPipeline.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsError.h"
#include "vsImage.h"
#include "vsSpirvSpecialization.h"

#include <stdexcept>
#include <string>

namespace vs
{
namespace
{
vk::DescriptorType ToVk(BindingType t)
{
  switch (t)
  {
    case BindingType::StorageBuffer:
      return vk::DescriptorType::eStorageBuffer;
    case BindingType::UniformTexelBuffer:
      return vk::DescriptorType::eUniformTexelBuffer;
    default:
      return vk::DescriptorType::eStorageImage;
  }
}
}

std::vector<BindingType> BindingTypes(uint32_t count, std::initializer_list<std::pair<uint32_t, BindingType>> types)
{
  std::vector<BindingType> bindings(count);
  std::vector<bool> given(count, false);
  for (const auto& [binding, type] : types)
  {
    if (binding >= count || given[binding])
    {
      throw std::logic_error("descriptor binding " + std::to_string(binding) +
        (binding >= count ? " is outside the set's " + std::to_string(count) + " bindings" : " is given twice"));
    }
    bindings[binding] = type;
    given[binding] = true;
  }
  for (uint32_t binding = 0; binding < count; ++binding)
  {
    if (!given[binding])
    {
      throw std::logic_error("descriptor binding " + std::to_string(binding) + " has no type");
    }
  }
  return bindings;
}

ComputePipeline::ComputePipeline(std::shared_ptr<Context> context, const uint32_t* spirv,
  size_t spirvBytes, std::vector<BindingType> bindings, uint32_t pushConstantBytes,
  const std::string& name, const std::vector<uint32_t>& specialization)
  : Context_(context)
  , Device_(context->Device())
  , Name_(name)
  , Bindings_(std::move(bindings))
  , PushBytes_(pushConstantBytes)
{
  if (pushConstantBytes > context->Info().MaxPushConstantsSize)
  {
    throw DeviceLimitError("pipeline '" + name + "' needs " + std::to_string(pushConstantBytes) +
      " bytes of push constants; the device allows " + std::to_string(context->Info().MaxPushConstantsSize));
  }
  vk::Device device = this->Device_;
  vk::ShaderModuleCreateInfo smci;
  smci.codeSize = spirvBytes;
  smci.pCode = spirv;
  std::vector<uint32_t> specialized;
  if (!specialization.empty() && context->SpecializesModules())
  {
    // On failure the driver specializes the module as it is: slower to compile, the same kernel.
    specialized = SpecializeSpirv(spirv, spirvBytes, specialization, this->SpecializationProblem_);
    if (!specialized.empty())
    {
      smci.codeSize = specialized.size() * sizeof(uint32_t);
      smci.pCode = specialized.data();
      this->SpecializedAhead_ = true;
    }
  }
  this->Module_ = device.createShaderModule(smci);

  std::vector<vk::DescriptorSetLayoutBinding> layoutBindings;
  for (uint32_t i = 0; i < this->Bindings_.size(); ++i)
  {
    vk::DescriptorSetLayoutBinding b;
    b.binding = i;
    b.descriptorType = ToVk(this->Bindings_[i]);
    b.descriptorCount = 1;
    b.stageFlags = vk::ShaderStageFlagBits::eCompute;
    layoutBindings.push_back(b);
  }
  vk::DescriptorSetLayoutCreateInfo dslci;
  dslci.bindingCount = static_cast<uint32_t>(layoutBindings.size());
  dslci.pBindings = layoutBindings.data();
  this->SetLayout_ = device.createDescriptorSetLayout(dslci);

  vk::PushConstantRange range;
  range.stageFlags = vk::ShaderStageFlagBits::eCompute;
  range.offset = 0;
  range.size = pushConstantBytes;
  vk::PipelineLayoutCreateInfo plci;
  plci.setLayoutCount = 1;
  plci.pSetLayouts = &this->SetLayout_;
  plci.pushConstantRangeCount = pushConstantBytes ? 1 : 0;
  plci.pPushConstantRanges = &range;
  this->Layout_ = device.createPipelineLayout(plci);

  vk::ComputePipelineCreateInfo cpci;
  cpci.stage.stage = vk::ShaderStageFlagBits::eCompute;
  cpci.stage.module = this->Module_;
  cpci.stage.pName = "main";
  std::vector<vk::SpecializationMapEntry> entries;
  for (uint32_t i = 0; i < specialization.size(); ++i)
  {
    vk::SpecializationMapEntry e;
    e.constantID = i;
    e.offset = i * uint32_t(sizeof(uint32_t));
    e.size = sizeof(uint32_t);
    entries.push_back(e);
  }
  vk::SpecializationInfo spec;
  spec.mapEntryCount = static_cast<uint32_t>(entries.size());
  spec.pMapEntries = entries.data();
  spec.dataSize = specialization.size() * sizeof(uint32_t);
  spec.pData = specialization.data();
  cpci.stage.pSpecializationInfo = specialization.empty() ? nullptr : &spec;
  cpci.layout = this->Layout_;
  auto result = device.createComputePipeline(context->PipelineCacheHandle(), cpci);
  if (result.result != vk::Result::eSuccess)
  {
    throw VulkanCallError("cannot create compute pipeline '" + name + "': " + vk::to_string(result.result));
  }
  this->Pipeline_ = result.value;
}

ComputePipeline::~ComputePipeline()
{
  vk::Device device = this->Device_;
  device.destroyPipeline(this->Pipeline_);
  device.destroyPipelineLayout(this->Layout_);
  device.destroyDescriptorSetLayout(this->SetLayout_);
  device.destroyShaderModule(this->Module_);
}

std::shared_ptr<ComputePipeline> SharedPipeline(const std::shared_ptr<Context>& context, const uint32_t* spirv,
  size_t spirvBytes, std::vector<BindingType> bindings, uint32_t pushConstantBytes, const std::string& name,
  const std::vector<uint32_t>& specialization)
{
  return context->Pipeline(name, [&]() {
    return std::make_shared<ComputePipeline>(
      context, spirv, spirvBytes, bindings, pushConstantBytes, name, specialization);
  });
}

DescriptorSet::DescriptorSet(const ComputePipeline& pipeline)
  : Context_(pipeline.GetContext())
  , PipelineName_(pipeline.Name())
  , Bindings_(pipeline.Bindings())
{
  vk::Device device = this->Context_->Device();
  uint32_t buffers = 0, images = 0, texels = 0;
  for (auto b : this->Bindings_)
  {
    (b == BindingType::StorageBuffer ? buffers : b == BindingType::UniformTexelBuffer ? texels : images)++;
  }
  std::vector<vk::DescriptorPoolSize> sizes;
  if (texels)
  {
    sizes.push_back({ vk::DescriptorType::eUniformTexelBuffer, texels });
  }
  if (buffers)
  {
    sizes.push_back({ vk::DescriptorType::eStorageBuffer, buffers });
  }
  if (images)
  {
    sizes.push_back({ vk::DescriptorType::eStorageImage, images });
  }
  vk::DescriptorPoolCreateInfo pci;
  pci.maxSets = 1;
  pci.poolSizeCount = static_cast<uint32_t>(sizes.size());
  pci.pPoolSizes = sizes.data();
  this->Pool_ = device.createDescriptorPool(pci);
  vk::DescriptorSetLayout layout = pipeline.SetLayout();
  vk::DescriptorSetAllocateInfo ai;
  ai.descriptorPool = this->Pool_;
  ai.descriptorSetCount = 1;
  ai.pSetLayouts = &layout;
  this->Set_ = device.allocateDescriptorSets(ai)[0];
}

DescriptorSet::~DescriptorSet()
{
  this->Context_->Device().destroyDescriptorPool(this->Pool_);
}

DescriptorSet& DescriptorSet::Bind(uint32_t binding, const Buffer& buffer)
{
  if (binding >= this->Bindings_.size() || this->Bindings_[binding] != BindingType::StorageBuffer)
  {
    throw InputError("pipeline '" + this->PipelineName_ + "' has no storage buffer at binding " +
      std::to_string(binding) + " (for '" + buffer.Name() + "')");
  }
  vk::DescriptorBufferInfo info{ buffer.Handle(), 0, VK_WHOLE_SIZE };
  vk::WriteDescriptorSet w;
  w.dstSet = this->Set_;
  w.dstBinding = binding;
  w.descriptorCount = 1;
  w.descriptorType = vk::DescriptorType::eStorageBuffer;
  w.pBufferInfo = &info;
  this->Context_->Device().updateDescriptorSets(w, {});
  return *this;
}

DescriptorSet& DescriptorSet::BindTexels(uint32_t binding, const Buffer& buffer, vk::Format format)
{
  if (binding >= this->Bindings_.size() || this->Bindings_[binding] != BindingType::UniformTexelBuffer)
  {
    throw InputError("pipeline '" + this->PipelineName_ + "' has no texel buffer at binding " +
      std::to_string(binding) + " (for '" + buffer.Name() + "')");
  }
  vk::BufferView view = buffer.TexelView(format);
  vk::WriteDescriptorSet w;
  w.dstSet = this->Set_;
  w.dstBinding = binding;
  w.descriptorCount = 1;
  w.descriptorType = vk::DescriptorType::eUniformTexelBuffer;
  w.pTexelBufferView = &view;
  this->Context_->Device().updateDescriptorSets(w, {});
  return *this;
}

DescriptorSet& DescriptorSet::Bind(uint32_t binding, const Image3D& image)
{
  if (binding >= this->Bindings_.size() || this->Bindings_[binding] != BindingType::StorageImage)
  {
    throw InputError("pipeline '" + this->PipelineName_ + "' has no storage image at binding " +
      std::to_string(binding) + " (for '" + image.Name() + "')");
  }
  vk::DescriptorImageInfo info{ nullptr, image.View(), vk::ImageLayout::eGeneral };
  vk::WriteDescriptorSet w;
  w.dstSet = this->Set_;
  w.dstBinding = binding;
  w.descriptorCount = 1;
  w.descriptorType = vk::DescriptorType::eStorageImage;
  w.pImageInfo = &info;
  this->Context_->Device().updateDescriptorSets(w, {});
  return *this;
}
}
