// vsVulkan.h — the one place that includes Vulkan-Hpp for VisSweep's core.
//
// The loader is opened at run time (vk::DynamicLoader), not linked: a machine
// without libvulkan.so.1 gets a clear vs::VulkanUnavailableError instead of a
// library that fails to load. Vulkan-Hpp turns failed calls into exceptions.
#ifndef vsVulkan_h
#define vsVulkan_h

#ifndef VULKAN_HPP_DISPATCH_LOADER_DYNAMIC
#define VULKAN_HPP_DISPATCH_LOADER_DYNAMIC 1
#endif
#ifndef VULKAN_HPP_NO_CONSTRUCTORS
#define VULKAN_HPP_NO_CONSTRUCTORS
#endif
#include <vulkan/vulkan.hpp>

#endif
