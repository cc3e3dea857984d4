#include "Presenter.h"

#include "voxc/core/Errors.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <functional>
#include <fmt/format.h>
#include <vector>

namespace voxc::viewer {

namespace {

void check(VkResult result, const char* what) {
    if (result != VK_SUCCESS) throw InternalError(fmt::format("{} failed ({})", what, int(result)));
}

// ImGui's backend reports its own Vulkan failures through this.
void checkFromImGui(VkResult result) { check(result, "ImGui's Vulkan backend"); }

// A host-visible, coherent buffer, mapped for its whole life.
struct HostBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
    VkDeviceSize bytes = 0;
};

} // namespace

struct Presenter::Impl {
    GLFWwindow* window = nullptr;
    VkInstance instance = VK_NULL_HANDLE;
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    std::string deviceName;
    uint32_t queueFamily = 0;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    VkSurfaceFormatKHR format{};
    bool bgra = false; // the swapchain's bytes are B, G, R, A (else R, G, B, A)
    VkSwapchainKHR swapchain = VK_NULL_HANDLE;
    VkExtent2D extent{};
    std::vector<VkImage> images;
    std::vector<VkImageView> views;
    std::vector<VkFramebuffer> framebuffers;
    VkRenderPass renderPass = VK_NULL_HANDLE; // the panel, drawn over the copied picture
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkFence frameDone = VK_NULL_HANDLE;
    VkSemaphore imageAcquired = VK_NULL_HANDLE, renderDone = VK_NULL_HANDLE;
    HostBuffer staging;  // the picture on its way in
    HostBuffer readback; // the window on its way out (capture)
    bool canCapture = false; // the swapchain's images can be copied from
    bool imguiVulkan = false, imguiGlfw = false;

    void createInstance();
    void chooseDevice(const std::string& preferred);
    void createDevice();
    void createRenderPass();
    void createSwapchain();
    void destroySwapchain();
    void ensure(HostBuffer& host, VkDeviceSize bytes, VkBufferUsageFlags usage);
    void destroy(HostBuffer& host);
    void initImGui();
    void runOnce(const std::function<void(VkCommandBuffer)>& record);
    ~Impl();
};

void Presenter::Impl::createInstance() {
    uint32_t count = 0;
    const char** required = glfwGetRequiredInstanceExtensions(&count);
    if (required == nullptr) throw UserError("voxc view: the Vulkan loader cannot present to this display (no WSI extensions)");
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "voxc view";
    app.apiVersion = VK_API_VERSION_1_1;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledExtensionCount = count;
    info.ppEnabledExtensionNames = required;
    check(vkCreateInstance(&info, nullptr, &instance), "vkCreateInstance (window)");
    check(glfwCreateWindowSurface(instance, window, nullptr, &surface), "glfwCreateWindowSurface");
}

void Presenter::Impl::chooseDevice(const std::string& preferred) {
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance, &count, devices.data());
    // The first device whose family draws and presents; the generating device's name first.
    for (int pass = 0; pass < 2 && physicalDevice == VK_NULL_HANDLE; ++pass)
        for (VkPhysicalDevice candidate : devices) {
            VkPhysicalDeviceProperties properties;
            vkGetPhysicalDeviceProperties(candidate, &properties);
            if (pass == 0 && preferred != properties.deviceName) continue;
            uint32_t familyCount = 0;
            vkGetPhysicalDeviceQueueFamilyProperties(candidate, &familyCount, nullptr);
            std::vector<VkQueueFamilyProperties> families(familyCount);
            vkGetPhysicalDeviceQueueFamilyProperties(candidate, &familyCount, families.data());
            for (uint32_t family = 0; family < familyCount; ++family) {
                VkBool32 presents = VK_FALSE;
                vkGetPhysicalDeviceSurfaceSupportKHR(candidate, family, surface, &presents);
                if (presents && (families[family].queueFlags & VK_QUEUE_GRAPHICS_BIT)) {
                    physicalDevice = candidate;
                    queueFamily = family;
                    deviceName = properties.deviceName;
                    break;
                }
            }
            if (physicalDevice != VK_NULL_HANDLE) break;
        }
    if (physicalDevice == VK_NULL_HANDLE) throw UserError("voxc view: no Vulkan device can draw to this window");
}

void Presenter::Impl::createDevice() {
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    const char* extensions[] = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = extensions;
    check(vkCreateDevice(physicalDevice, &info, nullptr, &device), "vkCreateDevice (window)");
    vkGetDeviceQueue(device, queueFamily, 0, &queue);

    // The picture is already sRGB-encoded (MeshRenderer's shader), so the swapchain must not encode again.
    uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(physicalDevice, surface, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(physicalDevice, surface, &count, formats.data());
    const auto found = std::find_if(formats.begin(), formats.end(), [](const VkSurfaceFormatKHR& f) {
        return f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM;
    });
    if (found == formats.end()) throw UserError("voxc view: the window offers no 8-bit UNORM RGBA or BGRA format");
    format = *found;
    bgra = format.format == VK_FORMAT_B8G8R8A8_UNORM;

    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = queueFamily;
    check(vkCreateCommandPool(device, &pool, nullptr, &commandPool), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = commandPool;
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(device, &allocate, &commands), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    check(vkCreateFence(device, &fence, nullptr, &frameDone), "vkCreateFence");
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    check(vkCreateSemaphore(device, &semaphore, nullptr, &imageAcquired), "vkCreateSemaphore");
    check(vkCreateSemaphore(device, &semaphore, nullptr, &renderDone), "vkCreateSemaphore");
}

void Presenter::Impl::createRenderPass() {
    VkAttachmentDescription colour{};
    colour.format = format.format;
    colour.samples = VK_SAMPLE_COUNT_1_BIT;
    colour.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD; // the picture copied in just before
    colour.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    colour.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    colour.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    colour.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    colour.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    const VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &reference;
    // The copy's writes land before the panel blends over them.
    VkSubpassDependency dependency{};
    dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
    dependency.dstSubpass = 0;
    dependency.srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependency.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependency.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    dependency.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 1;
    info.pAttachments = &colour;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 1;
    info.pDependencies = &dependency;
    check(vkCreateRenderPass(device, &info, nullptr, &renderPass), "vkCreateRenderPass");
}

void Presenter::Impl::createSwapchain() {
    VkSurfaceCapabilitiesKHR capabilities;
    check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physicalDevice, surface, &capabilities),
          "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    if (!(capabilities.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw UserError("voxc view: the window's images cannot be copied to");
    extent = capabilities.currentExtent;
    if (extent.width == UINT32_MAX) {
        int width = 0, height = 0;
        glfwGetFramebufferSize(window, &width, &height);
        extent = {uint32_t(width), uint32_t(height)};
    }
    extent.width = std::clamp(extent.width, std::max(1u, capabilities.minImageExtent.width), capabilities.maxImageExtent.width);
    extent.height = std::clamp(extent.height, std::max(1u, capabilities.minImageExtent.height), capabilities.maxImageExtent.height);
    uint32_t imageCount = std::max(2u, capabilities.minImageCount);
    if (capabilities.maxImageCount > 0) imageCount = std::min(imageCount, capabilities.maxImageCount);
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface;
    info.minImageCount = imageCount;
    info.imageFormat = format.format;
    info.imageColorSpace = format.colorSpace;
    info.imageExtent = extent;
    info.imageArrayLayers = 1;
    canCapture = capabilities.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                      (canCapture ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = capabilities.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR; // always supported
    info.clipped = VK_TRUE;
    check(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain), "vkCreateSwapchainKHR");
    uint32_t count = 0;
    vkGetSwapchainImagesKHR(device, swapchain, &count, nullptr);
    images.resize(count);
    vkGetSwapchainImagesKHR(device, swapchain, &count, images.data());
    for (VkImage image : images) {
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format.format;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        views.push_back(VK_NULL_HANDLE);
        check(vkCreateImageView(device, &view, nullptr, &views.back()), "vkCreateImageView");
        VkFramebufferCreateInfo framebuffer{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        framebuffer.renderPass = renderPass;
        framebuffer.attachmentCount = 1;
        framebuffer.pAttachments = &views.back();
        framebuffer.width = extent.width;
        framebuffer.height = extent.height;
        framebuffer.layers = 1;
        framebuffers.push_back(VK_NULL_HANDLE);
        check(vkCreateFramebuffer(device, &framebuffer, nullptr, &framebuffers.back()), "vkCreateFramebuffer");
    }
}

void Presenter::Impl::destroySwapchain() {
    vkDeviceWaitIdle(device);
    for (VkFramebuffer framebuffer : framebuffers) vkDestroyFramebuffer(device, framebuffer, nullptr);
    for (VkImageView view : views) vkDestroyImageView(device, view, nullptr);
    framebuffers.clear();
    views.clear();
    images.clear();
    if (swapchain) vkDestroySwapchainKHR(device, swapchain, nullptr);
    swapchain = VK_NULL_HANDLE;
}

void Presenter::Impl::destroy(HostBuffer& host) {
    if (host.buffer) vkDestroyBuffer(device, host.buffer, nullptr);
    if (host.memory) vkFreeMemory(device, host.memory, nullptr);
    host = HostBuffer{};
}

void Presenter::Impl::ensure(HostBuffer& host, VkDeviceSize bytes, VkBufferUsageFlags usage) {
    if (bytes <= host.bytes) return;
    vkDeviceWaitIdle(device);
    destroy(host);
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = bytes;
    info.usage = usage;
    check(vkCreateBuffer(device, &info, nullptr, &host.buffer), "vkCreateBuffer");
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device, host.buffer, &requirements);
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memory);
    const VkMemoryPropertyFlags wanted = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    uint32_t type = 0;
    while (type < memory.memoryTypeCount &&
           !((requirements.memoryTypeBits & (1u << type)) && (memory.memoryTypes[type].propertyFlags & wanted) == wanted))
        ++type;
    if (type == memory.memoryTypeCount) throw InternalError("no host-visible coherent memory for the window's picture");
    VkMemoryAllocateInfo allocation{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocation.allocationSize = requirements.size;
    allocation.memoryTypeIndex = type;
    check(vkAllocateMemory(device, &allocation, nullptr, &host.memory), "vkAllocateMemory");
    check(vkBindBufferMemory(device, host.buffer, host.memory, 0), "vkBindBufferMemory");
    check(vkMapMemory(device, host.memory, 0, VK_WHOLE_SIZE, 0, &host.mapped), "vkMapMemory");
    host.bytes = bytes;
}

void Presenter::Impl::runOnce(const std::function<void(VkCommandBuffer)>& record) {
    check(vkWaitForFences(device, 1, &frameDone, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    check(vkResetFences(device, 1, &frameDone), "vkResetFences");
    check(vkResetCommandBuffer(commands, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(commands, &begin), "vkBeginCommandBuffer");
    record(commands);
    check(vkEndCommandBuffer(commands), "vkEndCommandBuffer");
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    check(vkQueueSubmit(queue, 1, &submit, frameDone), "vkQueueSubmit");
    check(vkWaitForFences(device, 1, &frameDone, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

void Presenter::Impl::initImGui() {
    // One combined image sampler: the font texture, the only image the panel draws.
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    pool.maxSets = 1;
    pool.poolSizeCount = 1;
    pool.pPoolSizes = &size;
    check(vkCreateDescriptorPool(device, &pool, nullptr, &descriptorPool), "vkCreateDescriptorPool");
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini beside the user's files
    ImGui::StyleColorsDark();
    imguiGlfw = ImGui_ImplGlfw_InitForVulkan(window, true);
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = instance;
    info.PhysicalDevice = physicalDevice;
    info.Device = device;
    info.QueueFamily = queueFamily;
    info.Queue = queue;
    info.DescriptorPool = descriptorPool;
    info.MinImageCount = 2;
    info.ImageCount = uint32_t(images.size());
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkFromImGui;
    imguiVulkan = ImGui_ImplVulkan_Init(&info, renderPass);
    if (!imguiGlfw || !imguiVulkan) throw InternalError("Dear ImGui's GLFW or Vulkan backend did not start");
    runOnce([](VkCommandBuffer commandBuffer) { ImGui_ImplVulkan_CreateFontsTexture(commandBuffer); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

Presenter::Impl::~Impl() {
    if (device) vkDeviceWaitIdle(device);
    if (imguiVulkan) ImGui_ImplVulkan_Shutdown();
    if (imguiGlfw) ImGui_ImplGlfw_Shutdown();
    if (ImGui::GetCurrentContext()) ImGui::DestroyContext();
    if (device) {
        destroySwapchain();
        destroy(staging);
        destroy(readback);
        if (descriptorPool) vkDestroyDescriptorPool(device, descriptorPool, nullptr);
        if (renderPass) vkDestroyRenderPass(device, renderPass, nullptr);
        for (VkSemaphore semaphore : {imageAcquired, renderDone})
            if (semaphore) vkDestroySemaphore(device, semaphore, nullptr);
        if (frameDone) vkDestroyFence(device, frameDone, nullptr);
        if (commandPool) vkDestroyCommandPool(device, commandPool, nullptr);
        vkDestroyDevice(device, nullptr);
    }
    if (surface) vkDestroySurfaceKHR(instance, surface, nullptr);
    if (instance) vkDestroyInstance(instance, nullptr);
}

Presenter::Presenter(GLFWwindow* window, const std::string& deviceName) : impl_(std::make_unique<Impl>()) {
    Impl& s = *impl_;
    s.window = window;
    s.createInstance();
    s.chooseDevice(deviceName);
    s.createDevice();
    s.createRenderPass();
    s.createSwapchain();
    s.initImGui();
}

Presenter::~Presenter() = default;

rendering::ImageSize Presenter::extent() const { return {impl_->extent.width, impl_->extent.height}; }
const std::string& Presenter::deviceName() const { return impl_->deviceName; }

void Presenter::beginFrame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

bool Presenter::present(const rendering::Picture& picture, rendering::Picture* window) {
    Impl& s = *impl_;
    ImGui::Render();
    int width = 0, height = 0;
    glfwGetFramebufferSize(s.window, &width, &height);
    if (width == 0 || height == 0) return false; // minimised: nothing to show
    if (uint32_t(width) != s.extent.width || uint32_t(height) != s.extent.height) {
        s.destroySwapchain();
        s.createSwapchain();
        return false;
    }
    if (picture.width != s.extent.width || picture.height != s.extent.height) return false;
    if (window && !s.canCapture) throw UserError("voxc view: this window's images cannot be read back");
    uint32_t index = 0;
    const VkResult acquired = vkAcquireNextImageKHR(s.device, s.swapchain, UINT64_MAX, s.imageAcquired, VK_NULL_HANDLE, &index);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        s.destroySwapchain();
        s.createSwapchain();
        return false;
    }
    if (acquired != VK_SUBOPTIMAL_KHR) check(acquired, "vkAcquireNextImageKHR");

    check(vkWaitForFences(s.device, 1, &s.frameDone, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    const size_t pixels = size_t(picture.width) * picture.height;
    s.ensure(s.staging, pixels * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    if (window) s.ensure(s.readback, pixels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    auto* out = static_cast<uint8_t*>(s.staging.mapped);
    for (size_t p = 0; p < pixels; ++p) {
        const uint8_t* rgb = &picture.rgb[p * 3];
        out[p * 4 + 0] = s.bgra ? rgb[2] : rgb[0];
        out[p * 4 + 1] = rgb[1];
        out[p * 4 + 2] = s.bgra ? rgb[0] : rgb[2];
        out[p * 4 + 3] = 255;
    }
    check(vkResetFences(s.device, 1, &s.frameDone), "vkResetFences");
    check(vkResetCommandBuffer(s.commands, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(s.commands, &begin), "vkBeginCommandBuffer");
    VkImageMemoryBarrier toCopy{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    toCopy.srcAccessMask = 0;
    toCopy.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toCopy.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED; // every pixel is overwritten
    toCopy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    toCopy.srcQueueFamilyIndex = toCopy.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toCopy.image = s.images[index];
    toCopy.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(s.commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &toCopy);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {picture.width, picture.height, 1};
    vkCmdCopyBufferToImage(s.commands, s.staging.buffer, s.images[index], VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    pass.renderPass = s.renderPass;
    pass.framebuffer = s.framebuffers[index];
    pass.renderArea = {{0, 0}, s.extent};
    vkCmdBeginRenderPass(s.commands, &pass, VK_SUBPASS_CONTENTS_INLINE);
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), s.commands);
    vkCmdEndRenderPass(s.commands);
    if (window) {
        // The finished image (panel included) to the host, then back to where presenting wants it.
        VkImageMemoryBarrier toRead = toCopy;
        toRead.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        toRead.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        toRead.oldLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
        toRead.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        vkCmdPipelineBarrier(s.commands, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                             nullptr, 0, nullptr, 1, &toRead);
        vkCmdCopyImageToBuffer(s.commands, s.images[index], VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, s.readback.buffer, 1, &copy);
        VkImageMemoryBarrier toPresent = toRead;
        toPresent.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        toPresent.dstAccessMask = 0;
        toPresent.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        toPresent.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
        VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        toHost.srcQueueFamilyIndex = toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        toHost.buffer = s.readback.buffer;
        toHost.size = VK_WHOLE_SIZE;
        vkCmdPipelineBarrier(s.commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT | VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &toHost, 1,
                             &toPresent);
    }
    check(vkEndCommandBuffer(s.commands), "vkEndCommandBuffer");
    // The acquire semaphore guards the copy, the first use of the image.
    const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &s.imageAcquired;
    submit.pWaitDstStageMask = &waitStage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &s.commands;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &s.renderDone;
    check(vkQueueSubmit(s.queue, 1, &submit, s.frameDone), "vkQueueSubmit");
    VkPresentInfoKHR presentInfo{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    presentInfo.waitSemaphoreCount = 1;
    presentInfo.pWaitSemaphores = &s.renderDone;
    presentInfo.swapchainCount = 1;
    presentInfo.pSwapchains = &s.swapchain;
    presentInfo.pImageIndices = &index;
    const VkResult presented = vkQueuePresentKHR(s.queue, &presentInfo);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) {
        s.destroySwapchain();
        s.createSwapchain();
    } else {
        check(presented, "vkQueuePresentKHR");
    }
    if (window) {
        check(vkWaitForFences(s.device, 1, &s.frameDone, VK_TRUE, UINT64_MAX), "vkWaitForFences");
        *window = {picture.width, picture.height, std::vector<uint8_t>(pixels * 3)};
        const auto* in = static_cast<const uint8_t*>(s.readback.mapped);
        for (size_t p = 0; p < pixels; ++p) {
            window->rgb[p * 3 + 0] = in[p * 4 + (s.bgra ? 2 : 0)];
            window->rgb[p * 3 + 1] = in[p * 4 + 1];
            window->rgb[p * 3 + 2] = in[p * 4 + (s.bgra ? 0 : 2)];
        }
    }
    return true;
}

} // namespace voxc::viewer
