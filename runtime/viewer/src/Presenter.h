#pragma once
// The window's side of the viewer: a Vulkan instance and device of its own with a swapchain on the
// GLFW window, and Dear ImGui's GLFW and Vulkan backends (libimgui-dev ships both). Each frame it
// copies a finished picture (MeshRenderer's, read back) into the swapchain image and draws the
// panel over it. Generation and MeshRenderer keep voxc's context, made without WSI extensions,
// so the picture in the window is the very picture `voxc render` and `--screenshot` write.
#include "voxc/render/MeshRenderer.h"

#include <memory>
#include <string>

struct GLFWwindow;

namespace voxc::viewer {

class Presenter {
public:
    // Presents on the device named `deviceName` when it can show the window, else on the first
    // that can. UserError when none can.
    Presenter(GLFWwindow* window, const std::string& deviceName);
    ~Presenter();
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    // The size pictures must have: the swapchain's, after the window's last resize.
    rendering::ImageSize extent() const;
    // ImGui::NewFrame with both backends.
    void beginFrame();
    // ImGui::Render, then shows `picture` (of extent()) with the panel over it, and with `window`
    // reads the shown image back into it. False when nothing was shown: a picture of another size
    // (the window was resized meanwhile; the swapchain follows it) or a minimised window.
    bool present(const rendering::Picture& picture, rendering::Picture* window = nullptr);
    const std::string& deviceName() const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

} // namespace voxc::viewer
