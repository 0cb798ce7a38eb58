#include "vulkan_device.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include "vri/error.hpp"

namespace vri::vulkan {

namespace {

std::atomic<std::size_t> g_validation_messages{0};

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                     VkDebugUtilsMessageTypeFlagsEXT,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  ++g_validation_messages;
  std::cerr << "vulkan validation: " << (data && data->pMessage ? data->pMessage : "(no text)") << "\n";
  return VK_FALSE;
}

bool validation_wanted() {
  const char* v = std::getenv("VRI_VULKAN_VALIDATION");
  return v && std::strcmp(v, "0") != 0 && *v != '\0';
}

const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

struct Instance {
  VkInstance handle = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
};

VkDebugUtilsMessengerCreateInfoEXT messenger_info() {
  VkDebugUtilsMessengerCreateInfoEXT m{};
  m.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  m.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  m.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                  VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  m.pfnUserCallback = on_validation_message;
  return m;
}

bool instance_has(Api& api, const char* extension) {
  std::uint32_t n = 0;
  if (api.vkEnumerateInstanceExtensionProperties(nullptr, &n, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> all(n);
  api.vkEnumerateInstanceExtensionProperties(nullptr, &n, all.data());
  for (const auto& e : all)
    if (std::strcmp(e.extensionName, extension) == 0) return true;
  return false;
}

// An instance of Vulkan 1.1, with the validation layer and its messenger when `validate`.
Instance create_instance(Api& api, bool validate) {
  if (validate) {
    std::uint32_t n = 0;
    api.vkEnumerateInstanceLayerProperties(&n, nullptr);
    std::vector<VkLayerProperties> layers(n);
    api.vkEnumerateInstanceLayerProperties(&n, layers.data());
    bool found = false;
    for (const auto& l : layers) found = found || std::strcmp(l.layerName, kValidationLayer) == 0;
    if (!found)
      throw Error("vulkan: VRI_VULKAN_VALIDATION is set but the validation layer is missing (install vulkan-validationlayers)");
  }
  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "vri";
  app.pEngineName = "vri";
  app.apiVersion = VK_API_VERSION_1_1;
  std::vector<const char*> extensions;
  const VkDebugUtilsMessengerCreateInfoEXT messenger = messenger_info();
  VkInstanceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  info.pApplicationInfo = &app;
  // Drivers that implement Vulkan on another API (MoltenVK on Metal) are
  // listed only when asked for by this extension.
  if (instance_has(api, VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
    extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
    info.flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
  }
  if (validate) {
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &kValidationLayer;
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    info.pNext = &messenger;  // messages of vkCreateInstance itself
  }
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  Instance out;
  const VkResult r = api.vkCreateInstance(&info, nullptr, &out.handle);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw Error("vulkan: no Vulkan driver found (install mesa-vulkan-drivers for the CPU, or a GPU's driver)");
  check(r, "vkCreateInstance");
  api.load_instance(out.handle);
  if (validate && api.vkCreateDebugUtilsMessengerEXT)
    check(api.vkCreateDebugUtilsMessengerEXT(out.handle, &messenger, nullptr, &out.messenger),
          "vkCreateDebugUtilsMessengerEXT");
  return out;
}

void destroy(const Api& api, Instance& instance) {
  if (instance.messenger) api.vkDestroyDebugUtilsMessengerEXT(instance.handle, instance.messenger, nullptr);
  if (instance.handle) api.vkDestroyInstance(instance.handle, nullptr);
  instance = {};
}

std::vector<VkPhysicalDevice> physical_devices(const Api& api, VkInstance instance) {
  std::uint32_t n = 0;
  check(api.vkEnumeratePhysicalDevices(instance, &n, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> out(n);
  if (n) check(api.vkEnumeratePhysicalDevices(instance, &n, out.data()), "vkEnumeratePhysicalDevices");
  out.resize(n);
  return out;
}

const char* type_name(VkPhysicalDeviceType t) {
  switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
  }
}

// Lower is better: the order in which an automatic choice prefers device types.
int rank(VkPhysicalDeviceType t) {
  switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
  }
}

// The first queue family with compute, or -1.
int compute_family(const Api& api, VkPhysicalDevice device) {
  std::uint32_t n = 0;
  api.vkGetPhysicalDeviceQueueFamilyProperties(device, &n, nullptr);
  std::vector<VkQueueFamilyProperties> families(n);
  api.vkGetPhysicalDeviceQueueFamilyProperties(device, &n, families.data());
  for (std::uint32_t i = 0; i < n; ++i)
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) return static_cast<int>(i);
  return -1;
}

DeviceInfo describe(const Api& api, VkPhysicalDevice device, int index) {
  VkPhysicalDeviceProperties p;
  api.vkGetPhysicalDeviceProperties(device, &p);
  DeviceInfo info{index, p.deviceName, type_name(p.deviceType),
                  std::to_string(VK_API_VERSION_MAJOR(p.apiVersion)) + "." +
                      std::to_string(VK_API_VERSION_MINOR(p.apiVersion)) + "." +
                      std::to_string(VK_API_VERSION_PATCH(p.apiVersion)),
                  true, ""};
  if (compute_family(api, device) < 0) {
    info.usable = false;
    info.why_not = "no compute queue";
  } else if (p.apiVersion < VK_API_VERSION_1_1) {
    info.usable = false;
    info.why_not = "Vulkan 1.1 is needed";
  }
  return info;
}

}  // namespace

std::size_t VulkanDevice::validation_messages() { return g_validation_messages.load(); }

std::vector<DeviceInfo> VulkanDevice::list() {
  Api api = global_api();
  Instance instance;
  try {
    instance = create_instance(api, false);
  } catch (const Error&) {
    return {};  // a loader without drivers: no devices
  }
  std::vector<DeviceInfo> out;
  try {
    const auto devices = physical_devices(api, instance.handle);
    for (std::size_t i = 0; i < devices.size(); ++i) out.push_back(describe(api, devices[i], static_cast<int>(i)));
  } catch (...) {
    destroy(api, instance);
    throw;
  }
  destroy(api, instance);
  return out;
}

std::shared_ptr<VulkanDevice> VulkanDevice::shared() {
  // Kept for the process once made: a Python session or a viewer renders many
  // scenes, and a device costs milliseconds (lavapipe) to a second to create.
  static std::mutex mutex;
  static std::shared_ptr<VulkanDevice> current;
  std::lock_guard lock(mutex);
  if (!current) {
    current.reset(new VulkanDevice());
    // Released at exit before the layers the instance loaded tear their own
    // statics down: an atexit handler registered after them runs before them.
    // Left to `current`'s destructor (registered before), the device was
    // destroyed through a torn-down GPU-assisted validation layer: exit 139
    // after the image was written (issue 47).
    std::atexit([] { current.reset(); });
  }
  return current;
}

VulkanDevice::VulkanDevice() : api_(global_api()) {
  Instance instance = create_instance(api_, validation_wanted());
  instance_ = instance.handle;
  messenger_ = instance.messenger;
  try {
    const auto devices = physical_devices(api_, instance_);
    if (devices.empty())
      throw Error("vulkan: no Vulkan device found (install mesa-vulkan-drivers for the CPU, or a GPU's driver)");
    int chosen = -1;
    if (const char* want = std::getenv("VRI_VULKAN_DEVICE"); want && *want) {
      char* end = nullptr;
      const long i = std::strtol(want, &end, 10);
      if (*end != '\0' || i < 0 || i >= static_cast<long>(devices.size()))
        throw Error(std::string("vulkan: VRI_VULKAN_DEVICE=") + want + " names no device (`vri devices` lists " +
                    std::to_string(devices.size()) + ")");
      chosen = static_cast<int>(i);
      const DeviceInfo d = describe(api_, devices[chosen], chosen);
      if (!d.usable) throw Error("vulkan: device " + std::to_string(chosen) + " (" + d.name + ") is not usable: " + d.why_not);
    } else {
      int best = 1 << 30;
      for (std::size_t i = 0; i < devices.size(); ++i) {
        if (!describe(api_, devices[i], static_cast<int>(i)).usable) continue;
        VkPhysicalDeviceProperties p;
        api_.vkGetPhysicalDeviceProperties(devices[i], &p);
        if (rank(p.deviceType) < best) best = rank(p.deviceType), chosen = static_cast<int>(i);
      }
      if (chosen < 0) throw Error("vulkan: no usable Vulkan device (`vri devices` says why)");
    }
    physical_ = devices[chosen];
    info_ = describe(api_, physical_, chosen);
    queue_family_ = static_cast<std::uint32_t>(compute_family(api_, physical_));
    VkPhysicalDeviceProperties p;
    api_.vkGetPhysicalDeviceProperties(physical_, &p);
    max_groups_x_ = p.limits.maxComputeWorkGroupCount[0];
    max_storage_bytes_ = p.limits.maxStorageBufferRange;
    max_buffers_per_stage_ = p.limits.maxPerStageDescriptorStorageBuffers;
    // Tests pretend a smaller limit to run the split arrays and the chunked rays on small scenes.
    if (const char* v = std::getenv("VRI_VULKAN_MAX_BUFFER_BYTES"); v && *v) {
      char* end = nullptr;
      const unsigned long long want = std::strtoull(v, &end, 10);
      if (*end || want < 4096) throw Error(std::string("vulkan: VRI_VULKAN_MAX_BUFFER_BYTES=") + v + " is not a byte count >= 4096");
      max_storage_bytes_ = std::min<std::uint64_t>(max_storage_bytes_, want);
    }
    part_shift_ = static_cast<std::uint32_t>(std::bit_width(std::min<std::uint64_t>(max_storage_bytes_, 1ull << 31)) - 1);
    api_.vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);

    const float priority = 1;
    VkDeviceQueueCreateInfo queue{};
    queue.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queue.queueFamilyIndex = queue_family_;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    // A portability driver's device must be created with its subset extension.
    std::uint32_t n_extensions = 0;
    api_.vkEnumerateDeviceExtensionProperties(physical_, nullptr, &n_extensions, nullptr);
    std::vector<VkExtensionProperties> device_extensions(n_extensions);
    api_.vkEnumerateDeviceExtensionProperties(physical_, nullptr, &n_extensions, device_extensions.data());
    const char* subset = "VK_KHR_portability_subset";
    for (const auto& e : device_extensions)
      if (std::strcmp(e.extensionName, subset) == 0) {
        info.enabledExtensionCount = 1;
        info.ppEnabledExtensionNames = &subset;
      }
    check(api_.vkCreateDevice(physical_, &info, nullptr, &device_), "vkCreateDevice");
    api_.load_device(device_);
    api_.vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

    VkCommandPoolCreateInfo pool{};
    pool.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = queue_family_;
    check(api_.vkCreateCommandPool(device_, &pool, nullptr, &pool_), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    alloc.commandPool = pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    check(api_.vkAllocateCommandBuffers(device_, &alloc, &command_buffer_), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fence{};
    fence.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    check(api_.vkCreateFence(device_, &fence, nullptr, &fence_), "vkCreateFence");
  } catch (...) {
    release();
    throw;
  }
}

VulkanDevice::~VulkanDevice() { release(); }

void VulkanDevice::release() noexcept {
  if (device_) {
    api_.vkDeviceWaitIdle(device_);
    if (fence_) api_.vkDestroyFence(device_, fence_, nullptr);
    if (pool_) api_.vkDestroyCommandPool(device_, pool_, nullptr);
    api_.vkDestroyDevice(device_, nullptr);
  }
  Instance instance{instance_, messenger_};
  destroy(api_, instance);
  device_ = VK_NULL_HANDLE, fence_ = VK_NULL_HANDLE, pool_ = VK_NULL_HANDLE;
  instance_ = VK_NULL_HANDLE, messenger_ = VK_NULL_HANDLE;
}

std::uint32_t choose_memory_type(const VkPhysicalDeviceMemoryProperties& memory, std::uint32_t type_bits,
                                 VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) {
  auto allowed = [&](std::uint32_t i) {
    return (type_bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & required) == required;
  };
  int heap = -1;  // with device-local required: the largest heap such a type lives in
  if (required & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT)
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
      const int h = static_cast<int>(memory.memoryTypes[i].heapIndex);
      if (allowed(i) && (heap < 0 || memory.memoryHeaps[h].size > memory.memoryHeaps[heap].size)) heap = h;
    }
  int fallback = -1;
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if (!allowed(i) || (heap >= 0 && static_cast<int>(memory.memoryTypes[i].heapIndex) != heap)) continue;
    if ((memory.memoryTypes[i].propertyFlags & preferred) == preferred) return i;
    if (fallback < 0) fallback = static_cast<int>(i);
  }
  if (fallback < 0) throw Error("vulkan: the device has no suitable memory type");
  return static_cast<std::uint32_t>(fallback);
}

std::uint32_t VulkanDevice::memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required,
                                        VkMemoryPropertyFlags preferred) const {
  return choose_memory_type(memory_, type_bits, required, preferred);
}

void VulkanDevice::begin() const {
  check(api_.vkResetCommandBuffer(command_buffer_, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo b{};
  b.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  b.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(api_.vkBeginCommandBuffer(command_buffer_, &b), "vkBeginCommandBuffer");
}

void VulkanDevice::end_and_wait() const {
  check(api_.vkEndCommandBuffer(command_buffer_), "vkEndCommandBuffer");
  VkSubmitInfo s{};
  s.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  s.commandBufferCount = 1;
  s.pCommandBuffers = &command_buffer_;
  check(api_.vkResetFences(device_, 1, &fence_), "vkResetFences");
  check(api_.vkQueueSubmit(queue_, 1, &s, fence_), "vkQueueSubmit");
  check(api_.vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

}  // namespace vri::vulkan
