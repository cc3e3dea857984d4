#include "voxc/render/MeshRenderer.h"

#include "DeviceBuffer.h" // voxc_vulkan's private buffers (runtime/vulkan/src)
#include "CommandSlot.h"

#include "voxc/codegen/Spirv.h"
#include "voxc/core/Errors.h"
#include "voxc/shaders/ShaderSources.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <unordered_set>

namespace voxc::rendering {

float encodeSrgb(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

glm::vec3 towardsLight(const Camera& camera) {
    const glm::vec3 towardsEye = glm::normalize(camera.eye - camera.target);
    const glm::vec3 right = glm::normalize(glm::cross(camera.up, towardsEye));
    return glm::normalize(glm::vec3(0.0f, 1.0f, 0.0f) + 0.5f * towardsEye - 0.6f * right);
}

void LineSet::add(glm::vec3 from, glm::vec3 to, glm::vec3 colour) {
    points.push_back(from);
    points.push_back(to);
    colours.push_back(colour);
    colours.push_back(colour);
}

Bounds meshBounds(const Mesh& mesh) {
    Bounds bounds{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
    for (const glm::vec3& p : mesh.positions) {
        bounds.min = glm::min(bounds.min, p);
        bounds.max = glm::max(bounds.max, p);
    }
    return bounds;
}

LineSet wireframeLines(const Mesh& mesh, glm::vec3 colour) {
    LineSet lines;
    std::unordered_set<uint64_t> seen;
    for (size_t t = 0; t + 2 < mesh.triangles.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = mesh.triangles[t + e], b = mesh.triangles[t + (e + 1) % 3];
            if (seen.insert(uint64_t(std::min(a, b)) << 32 | std::max(a, b)).second)
                lines.add(mesh.positions[a], mesh.positions[b], colour);
        }
    return lines;
}

LineSet chunkBorderLines(const ChunkLayout& layout, glm::vec3 colour) {
    LineSet lines;
    const glm::ivec3 gridLast = layout.gridOrigin + layout.gridSize - 1;
    for (int z = 0; z < layout.chunkCount.z; ++z)
        for (int y = 0; y < layout.chunkCount.y; ++y)
            for (int x = 0; x < layout.chunkCount.x; ++x) {
                const glm::ivec3 first = (layout.chunkBase + glm::ivec3(x, y, z)) * layout.chunkSize;
                const glm::vec3 lo = glm::max(first, layout.gridOrigin);
                const glm::vec3 hi = glm::min(first + layout.chunkSize, gridLast);
                for (int axis = 0; axis < 3; ++axis) {
                    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                    for (int corner = 0; corner < 4; ++corner) {
                        glm::vec3 from = lo, to = hi;
                        from[u] = to[u] = (corner & 1) ? hi[u] : lo[u];
                        from[v] = to[v] = (corner & 2) ? hi[v] : lo[v];
                        lines.add(from, to, colour);
                    }
                }
            }
    return lines;
}

} // namespace voxc::rendering

namespace voxc {

using namespace vulkan_detail;

namespace {

constexpr VkFormat kColourFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr glm::vec3 kUnknownMaterial{0.6f, 0.6f, 0.6f}; // the exporters' neutral grey

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal; // zero for lines: drawn unlit
    glm::vec3 colour;
    glm::vec2 light{1.0f}; // ambient occlusion and sun visibility (rendering::VertexLight)
};

struct FramePush {
    glm::mat4 viewProjection;
    glm::vec4 eye;
    glm::vec4 light;
};

// Graphics entry points, beside the compute ones VulkanApi loads for every context.
#define VOXC_VK_RENDER_FUNCTIONS(X)  \
    X(vkCreateImage)                 \
    X(vkDestroyImage)                \
    X(vkGetImageMemoryRequirements)  \
    X(vkBindImageMemory)             \
    X(vkCreateImageView)             \
    X(vkDestroyImageView)            \
    X(vkCreateRenderPass)            \
    X(vkDestroyRenderPass)           \
    X(vkCreateFramebuffer)           \
    X(vkDestroyFramebuffer)          \
    X(vkCreateGraphicsPipelines)     \
    X(vkCmdBeginRenderPass)          \
    X(vkCmdEndRenderPass)            \
    X(vkCmdBindVertexBuffers)        \
    X(vkCmdBindIndexBuffer)          \
    X(vkCmdDrawIndexed)              \
    X(vkCmdDraw)                     \
    X(vkCmdCopyImageToBuffer)

struct RenderApi {
#define VOXC_VK_DECLARE(name) PFN_##name name = nullptr;
    VOXC_VK_RENDER_FUNCTIONS(VOXC_VK_DECLARE)
#undef VOXC_VK_DECLARE
};

RenderApi loadRenderApi(const VulkanContext::Impl& ctx) {
    RenderApi api;
#define VOXC_VK_LOAD(name)                                                                     \
    api.name = reinterpret_cast<PFN_##name>(ctx.api.vkGetDeviceProcAddr(ctx.device, #name)); \
    if (!api.name) throw InternalError("the Vulkan driver has no " #name);
    VOXC_VK_RENDER_FUNCTIONS(VOXC_VK_LOAD)
#undef VOXC_VK_LOAD
    return api;
}

struct Target {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
};

} // namespace

struct MeshRenderer::Impl {
    VulkanContext::Impl& ctx;
    RenderApi api;
    rendering::ImageSize size;
    Target colour, depth;
    VkRenderPass renderPass = VK_NULL_HANDLE;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline faces = VK_NULL_HANDLE, lines = VK_NULL_HANDLE;
    DeviceBuffer readback;
    DeviceBuffer faceVertices, faceIndices, lineVertices;
    uint32_t faceIndexCount = 0, lineVertexCount = 0;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;

    Impl(VulkanContext::Impl& context, rendering::ImageSize imageSize) : ctx(context), api(loadRenderApi(context)), size(imageSize) {}
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl();

    void requireGraphicsQueue() const;
    Target createTarget(VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect);
    void destroyTarget(Target& target);
    void createRenderPass();
    VkPipeline createPipeline(VkShaderModule vertex, VkShaderModule fragment, VkPrimitiveTopology topology,
                              VkCompareOp depthCompare);
    void createPipelines();
    void upload(DeviceBuffer& buffer, const void* data, size_t bytes, VkBufferUsageFlags usage);
    void record(const rendering::Camera& camera);
};

void MeshRenderer::Impl::requireGraphicsQueue() const {
    uint32_t count = 0;
    ctx.api.vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    ctx.api.vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &count, families.data());
    if (!(families[ctx.queueFamily].queueFlags & VK_QUEUE_GRAPHICS_BIT))
        throw UserError(fmt::format("the device '{}' computes on a queue that cannot draw; render on another "
                                    "--device (lavapipe draws)",
                                    ctx.info.name));
}

Target MeshRenderer::Impl::createTarget(VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect) {
    Target target;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {size.width, size.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    check(api.vkCreateImage(ctx.device, &info, nullptr, &target.image), "vkCreateImage");
    VkMemoryRequirements requirements;
    api.vkGetImageMemoryRequirements(ctx.device, target.image, &requirements);
    // Device-local when there is such a type among those the image allows, else the first allowed.
    uint32_t chosen = UINT32_MAX;
    for (uint32_t type = 0; type < ctx.memory.memoryTypeCount; ++type) {
        if (!(requirements.memoryTypeBits & (1u << type))) continue;
        if (chosen == UINT32_MAX) chosen = type;
        if (ctx.memory.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT) {
            chosen = type;
            break;
        }
    }
    VkMemoryAllocateInfo allocation{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocation.allocationSize = requirements.size;
    allocation.memoryTypeIndex = chosen;
    check(ctx.api.vkAllocateMemory(ctx.device, &allocation, nullptr, &target.memory), "vkAllocateMemory");
    check(api.vkBindImageMemory(ctx.device, target.image, target.memory, 0), "vkBindImageMemory");
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = target.image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {aspect, 0, 1, 0, 1};
    check(api.vkCreateImageView(ctx.device, &view, nullptr, &target.view), "vkCreateImageView");
    return target;
}

void MeshRenderer::Impl::destroyTarget(Target& target) {
    if (target.view) api.vkDestroyImageView(ctx.device, target.view, nullptr);
    if (target.image) api.vkDestroyImage(ctx.device, target.image, nullptr);
    if (target.memory) ctx.api.vkFreeMemory(ctx.device, target.memory, nullptr);
    target = Target{};
}

void MeshRenderer::Impl::createRenderPass() {
    std::array<VkAttachmentDescription, 2> attachments{};
    attachments[0].format = kColourFormat;
    attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL; // read back by a copy
    attachments[1] = attachments[0];
    attachments[1].format = kDepthFormat;
    attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    const VkAttachmentReference colourRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    const VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &colourRef;
    subpass.pDepthStencilAttachment = &depthRef;
    // In: the previous frame's copy and depth writes finish before this frame clears the targets.
    // Out: the colour writes finish before the copy to the readback buffer.
    const VkPipelineStageFlags attachmentStages = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                  VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                                                  VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    std::array<VkSubpassDependency, 2> dependencies{};
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = 0;
    dependencies[0].srcStageMask = attachmentStages | VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[0].dstStageMask = attachmentStages;
    dependencies[0].srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    dependencies[1].srcSubpass = 0;
    dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = uint32_t(attachments.size());
    info.pAttachments = attachments.data();
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = uint32_t(dependencies.size());
    info.pDependencies = dependencies.data();
    check(api.vkCreateRenderPass(ctx.device, &info, nullptr, &renderPass), "vkCreateRenderPass");

    const std::array<VkImageView, 2> views{colour.view, depth.view};
    VkFramebufferCreateInfo framebufferInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    framebufferInfo.renderPass = renderPass;
    framebufferInfo.attachmentCount = uint32_t(views.size());
    framebufferInfo.pAttachments = views.data();
    framebufferInfo.width = size.width;
    framebufferInfo.height = size.height;
    framebufferInfo.layers = 1;
    check(api.vkCreateFramebuffer(ctx.device, &framebufferInfo, nullptr, &framebuffer), "vkCreateFramebuffer");
}

VkPipeline MeshRenderer::Impl::createPipeline(VkShaderModule vertex, VkShaderModule fragment,
                                              VkPrimitiveTopology topology, VkCompareOp depthCompare) {
    std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
    stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vertex;
    stages[0].pName = "main";
    stages[1] = stages[0];
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = fragment;
    const VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
    const std::array<VkVertexInputAttributeDescription, 4> attributes{{
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
        {2, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, colour)},
        {3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, light)},
    }};
    VkPipelineVertexInputStateCreateInfo input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    input.vertexBindingDescriptionCount = 1;
    input.pVertexBindingDescriptions = &binding;
    input.vertexAttributeDescriptionCount = uint32_t(attributes.size());
    input.pVertexAttributeDescriptions = attributes.data();
    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = topology;
    const VkViewport viewport{0.0f, 0.0f, float(size.width), float(size.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {size.width, size.height}};
    VkPipelineViewportStateCreateInfo viewportState{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewportState.viewportCount = 1;
    viewportState.pViewports = &viewport;
    viewportState.scissorCount = 1;
    viewportState.pScissors = &scissor;
    // The meshes are closed and wind counter-clockwise seen from air, so a face seen from behind is
    // hidden by others and is not drawn. Vulkan decides the winding in framebuffer coordinates
    // (y down), where the projection's flipped y keeps a face seen from air counter-clockwise.
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = topology == VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depthState{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depthState.depthTestEnable = VK_TRUE;
    depthState.depthWriteEnable = VK_TRUE;
    depthState.depthCompareOp = depthCompare;
    VkPipelineColorBlendAttachmentState blendAttachment{};
    blendAttachment.colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = 1;
    blend.pAttachments = &blendAttachment;
    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.stageCount = uint32_t(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &input;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewportState;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depthState;
    info.pColorBlendState = &blend;
    info.layout = layout;
    info.renderPass = renderPass;
    VkPipeline pipeline = VK_NULL_HANDLE;
    check(api.vkCreateGraphicsPipelines(ctx.device, ctx.pipelineCache, 1, &info, nullptr, &pipeline),
          "vkCreateGraphicsPipelines");
    return pipeline;
}

void MeshRenderer::Impl::createPipelines() {
    VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(FramePush)};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.pushConstantRangeCount = 1;
    layoutInfo.pPushConstantRanges = &range;
    check(ctx.api.vkCreatePipelineLayout(ctx.device, &layoutInfo, nullptr, &layout), "vkCreatePipelineLayout");

    const auto module = [&](const char* file, codegen::GraphicsStage stage) {
        const std::vector<uint32_t> spirv = codegen::compileGraphicsShader(file, std::string(shaderSource(file)), stage);
        VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        info.codeSize = spirv.size() * sizeof(uint32_t);
        info.pCode = spirv.data();
        VkShaderModule shader = VK_NULL_HANDLE;
        check(ctx.api.vkCreateShaderModule(ctx.device, &info, nullptr, &shader), "vkCreateShaderModule");
        return shader;
    };
    VkShaderModule vertex = module("render_mesh_vert.glsl", codegen::GraphicsStage::Vertex);
    VkShaderModule fragment = VK_NULL_HANDLE;
    try {
        fragment = module("render_mesh_frag.glsl", codegen::GraphicsStage::Fragment);
        faces = createPipeline(vertex, fragment, VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, VK_COMPARE_OP_LESS);
        lines = createPipeline(vertex, fragment, VK_PRIMITIVE_TOPOLOGY_LINE_LIST, VK_COMPARE_OP_LESS_OR_EQUAL);
    } catch (...) {
        ctx.api.vkDestroyShaderModule(ctx.device, vertex, nullptr);
        if (fragment) ctx.api.vkDestroyShaderModule(ctx.device, fragment, nullptr);
        throw;
    }
    ctx.api.vkDestroyShaderModule(ctx.device, vertex, nullptr);
    ctx.api.vkDestroyShaderModule(ctx.device, fragment, nullptr);
}

void MeshRenderer::Impl::upload(DeviceBuffer& buffer, const void* data, size_t bytes, VkBufferUsageFlags usage) {
    destroyBuffer(ctx, buffer);
    if (bytes == 0) return;
    buffer = createBuffer(ctx, bytes, usage, MemoryUse::HostAccess);
    std::memcpy(buffer.mapped, data, bytes);
    flushForDevice(ctx, buffer);
}

void MeshRenderer::Impl::record(const rendering::Camera& camera) {
    check(ctx.api.vkResetCommandBuffer(commands, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(ctx.api.vkBeginCommandBuffer(commands, &begin), "vkBeginCommandBuffer");

    std::array<VkClearValue, 2> clear{};
    clear[0].color = {{rendering::encodeSrgb(rendering::kBackground.r), rendering::encodeSrgb(rendering::kBackground.g),
                        rendering::encodeSrgb(rendering::kBackground.b), 1.0f}};
    clear[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    pass.renderPass = renderPass;
    pass.framebuffer = framebuffer;
    pass.renderArea = {{0, 0}, {size.width, size.height}};
    pass.clearValueCount = uint32_t(clear.size());
    pass.pClearValues = clear.data();
    api.vkCmdBeginRenderPass(commands, &pass, VK_SUBPASS_CONTENTS_INLINE);

    const float aspect = float(size.width) / float(size.height);
    FramePush push{rendering::viewProjection(camera, aspect), glm::vec4(camera.eye, 0.0f),
                   glm::vec4(rendering::towardsLight(camera), 0.3f)};
    const VkShaderStageFlags pushStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    const VkDeviceSize offset = 0;
    if (faceIndexCount > 0) {
        ctx.api.vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, faces);
        ctx.api.vkCmdPushConstants(commands, layout, pushStages, 0, sizeof(push), &push);
        api.vkCmdBindVertexBuffers(commands, 0, 1, &faceVertices.buffer, &offset);
        api.vkCmdBindIndexBuffer(commands, faceIndices.buffer, 0, VK_INDEX_TYPE_UINT32);
        api.vkCmdDrawIndexed(commands, faceIndexCount, 1, 0, 0, 0);
    }
    if (lineVertexCount > 0) {
        push.eye.w = 0.002f; // a fifth of a percent of the way to the eye: in front of the faces under the lines
        ctx.api.vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, lines);
        ctx.api.vkCmdPushConstants(commands, layout, pushStages, 0, sizeof(push), &push);
        api.vkCmdBindVertexBuffers(commands, 0, 1, &lineVertices.buffer, &offset);
        api.vkCmdDraw(commands, lineVertexCount, 1, 0, 0);
    }
    api.vkCmdEndRenderPass(commands);

    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {size.width, size.height, 1};
    api.vkCmdCopyImageToBuffer(commands, colour.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &copy);
    VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = readback.buffer;
    toHost.size = VK_WHOLE_SIZE;
    ctx.api.vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1,
                                 &toHost, 0, nullptr);
    check(ctx.api.vkEndCommandBuffer(commands), "vkEndCommandBuffer");
}

MeshRenderer::Impl::~Impl() {
    if (ctx.device) ctx.api.vkDeviceWaitIdle(ctx.device);
    if (fence) ctx.api.vkDestroyFence(ctx.device, fence, nullptr);
    if (commandPool) ctx.api.vkDestroyCommandPool(ctx.device, commandPool, nullptr);
    for (DeviceBuffer* buffer : {&readback, &faceVertices, &faceIndices, &lineVertices}) destroyBuffer(ctx, *buffer);
    for (VkPipeline pipeline : {faces, lines})
        if (pipeline) ctx.api.vkDestroyPipeline(ctx.device, pipeline, nullptr);
    if (layout) ctx.api.vkDestroyPipelineLayout(ctx.device, layout, nullptr);
    if (framebuffer) api.vkDestroyFramebuffer(ctx.device, framebuffer, nullptr);
    if (renderPass) api.vkDestroyRenderPass(ctx.device, renderPass, nullptr);
    destroyTarget(depth);
    destroyTarget(colour);
}

MeshRenderer::MeshRenderer(VulkanContext& context, rendering::ImageSize size)
    : impl_(std::make_unique<Impl>(*context.impl_, size)) {
    Impl& s = *impl_;
    s.requireGraphicsQueue();
    s.colour = s.createTarget(kColourFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              VK_IMAGE_ASPECT_COLOR_BIT);
    s.depth = s.createTarget(kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
    s.createRenderPass();
    s.createPipelines();
    s.readback = createBuffer(s.ctx, VkDeviceSize(size.width) * size.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              MemoryUse::HostAccess);
    const CommandSlot slot = createCommandSlot(s.ctx);
    s.commandPool = slot.pool;
    s.commands = slot.commands;
    s.fence = slot.fence;
}

MeshRenderer::~MeshRenderer() = default;

void MeshRenderer::setScene(const Mesh& mesh, std::span<const Material> materials, const rendering::LineSet& lines,
                            const rendering::VertexLight* light) {
    Impl& s = *impl_;
    VOXC_ASSERT(lines.points.size() == lines.colours.size() && lines.points.size() % 2 == 0);
    VOXC_ASSERT(!light || (light->ambient.size() == mesh.positions.size() && light->sun.size() == mesh.positions.size()));
    std::array<glm::vec3, 256> palette;
    palette.fill(kUnknownMaterial);
    for (const Material& material : materials) palette[material.id] = material.color;
    std::vector<Vertex> vertices(mesh.positions.size());
    for (size_t v = 0; v < vertices.size(); ++v)
        vertices[v] = {mesh.positions[v], mesh.normals[v],
                       mesh.vertexMaterials.empty() ? kUnknownMaterial : palette[mesh.vertexMaterials[v]],
                       light ? glm::vec2(light->ambient[v], light->sun[v]) : glm::vec2(1.0f)};
    std::vector<Vertex> lineVertices(lines.points.size());
    for (size_t v = 0; v < lineVertices.size(); ++v) lineVertices[v] = {lines.points[v], glm::vec3(0.0f), lines.colours[v], glm::vec2(1.0f)};
    if (mesh.triangles.size() > size_t(UINT32_MAX) || lineVertices.size() > size_t(UINT32_MAX))
        throw UserError("render: the mesh is too large to draw in one call");
    s.ctx.api.vkDeviceWaitIdle(s.ctx.device); // the buffers may still be in use by a frame
    s.upload(s.faceVertices, vertices.data(), vertices.size() * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    s.upload(s.faceIndices, mesh.triangles.data(), mesh.triangles.size() * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    s.upload(s.lineVertices, lineVertices.data(), lineVertices.size() * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    s.faceIndexCount = uint32_t(mesh.triangles.size());
    s.lineVertexCount = uint32_t(lineVertices.size());
}

rendering::Picture MeshRenderer::draw(const rendering::Camera& camera) {
    Impl& s = *impl_;
    s.record(camera);
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &s.commands;
    check(s.ctx.api.vkQueueSubmit(s.ctx.queue, 1, &submit, s.fence), "vkQueueSubmit");
    check(s.ctx.api.vkWaitForFences(s.ctx.device, 1, &s.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    check(s.ctx.api.vkResetFences(s.ctx.device, 1, &s.fence), "vkResetFences");
    invalidateForHost(s.ctx, s.readback);

    rendering::Picture picture{s.size.width, s.size.height, {}};
    const size_t pixels = size_t(s.size.width) * s.size.height;
    picture.rgb.resize(pixels * 3);
    const auto* rgba = static_cast<const uint8_t*>(s.readback.mapped);
    for (size_t p = 0; p < pixels; ++p) std::memcpy(&picture.rgb[p * 3], &rgba[p * 4], 3);
    return picture;
}

} // namespace voxc
