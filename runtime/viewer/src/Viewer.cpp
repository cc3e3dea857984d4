#include "voxc/viewer/Viewer.h"

#include "Presenter.h"

#include "voxc/core/Errors.h"
#include "voxc/explore/Png.h"
#include "voxc/render/MeshRenderer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <optional>
#include <thread>

namespace voxc::viewer {

namespace {

constexpr glm::vec3 kWireframeColour{0.05f, 0.05f, 0.05f};
constexpr glm::vec3 kChunkBorderColour{0.9f, 0.15f, 0.1f};
constexpr double kWatchIntervalSeconds = 0.25;
constexpr float kPanelWidth = 360.0f;

using Clock = std::chrono::steady_clock;

// The add brush's material choice: the surface's where it is clicked, or the voxels' own (0), or an id.
constexpr int kSurfaceMaterial = -1;

// The material of the densest solid sample at the corners of the cell that holds `point` (a hit
// on the surface): what "the surface's material" gives an add. 0 when no corner is solid.
uint8_t surfaceMaterial(const ChunkedGrid& grid, float iso, glm::vec3 point) {
    const ChunkLayout& layout = grid.layout();
    const glm::ivec3 cell = glm::ivec3(glm::floor(point)) - layout.gridOrigin;
    float densest = iso;
    uint8_t material = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 at = cell + glm::ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        if (glm::any(glm::lessThan(at, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(at, layout.gridSize))) continue;
        if (grid.at(at) > densest) densest = grid.at(at), material = grid.materialAt(at);
    }
    return material;
}

void log(const std::string& line) { std::cerr << "view: " << line << (line.ends_with('\n') ? "" : "\n"); }

struct GlfwLibrary {
    GlfwLibrary() {
        if (!glfwInit())
            throw UserError("voxc view needs a display: none could be opened (set DISPLAY, or run it under xvfb-run)");
    }
    ~GlfwLibrary() { glfwTerminate(); }
};

struct Window {
    GLFWwindow* handle;
    explicit Window(rendering::ImageSize size, const std::string& title) {
        glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
        handle = glfwCreateWindow(int(size.width), int(size.height), title.c_str(), nullptr, nullptr);
        if (handle == nullptr) throw UserError("voxc view: the window could not be created");
    }
    ~Window() { glfwDestroyWindow(handle); }
};

// The interactive loop and the script share this state; each frame draws the world when it changed.
class App {
public:
    explicit App(const ViewerOptions& options)
        : options_(options), glfw_(), context_(options.context),
          session_(context_, options.session), window_(options.size, "voxc view " + options.session.path),
          presenter_(window_.handle, context_.device().name) {
        if (!session_.lastError().empty()) log("the file does not check; fix it and save:\n" + session_.lastError());
        if (session_.hasWorld()) setCamera(options.camera);
        else camera_ = {glm::vec3(100.0f), glm::vec3(0.0f)}; // until the file checks
        editsPath_ = options.editsPath.empty() ? options.session.path + ".edits.json" : options.editsPath;
    }

    void runInteractive() {
        while (!glfwWindowShouldClose(window_.handle)) {
            glfwWaitEventsTimeout(kWatchIntervalSeconds); // idle without spinning; the watch needs a timeout
            watchFile();
            pollRefine();
            frame();
        }
        if (!options_.screenshot.empty()) screenshot(options_.screenshot);
    }

    void runScript() {
        for (const Action& action : options_.script) {
            glfwPollEvents();
            run(action);
            frame();
        }
        if (!options_.screenshot.empty()) screenshot(options_.screenshot);
    }

private:
    [[noreturn]] void fail(const Action& action, const std::string& message) const {
        throw UserError(fmt::format("{}:{}:{}: {}", options_.scriptPath, action.loc.line, action.loc.column, message));
    }

    void run(const Action& action) {
        switch (action.kind) {
        case Action::Kind::Camera: requireWorld(action), setCamera(action.text); break;
        case Action::Kind::Carve:
        case Action::Kind::Add: {
            requireWorld(action);
            const Brush::Op op = action.kind == Action::Kind::Carve ? Brush::Op::Carve : Brush::Op::Add;
            const bool hit = action.alongRay ? brushAlong(op, action.origin, action.direction) : brushAtPixel(op, action.pixel);
            if (!hit) fail(action, "the ray meets no surface");
            // What a click waits for before the next frame: the edit, then the world's mesh.
            const auto start = Clock::now();
            refreshMesh();
            log(fmt::format("{} in {:.1f} ms ({} chunks whose mesh it can change), the mesh ({} triangles) in {:.1f} ms",
                            action.kind == Action::Kind::Carve ? "carve" : "add", lastEdit_->ms, lastEdit_->chunksRemeshed, mesh_.triangles.size() / 3,
                            std::chrono::duration<double, std::milli>(Clock::now() - start).count()));
            break;
        }
        case Action::Kind::Set:
            if (action.text == "radius" || action.text == "softness") {
                if (!(action.value > 0 && action.value <= 256)) fail(action, fmt::format("{} {}: expected more than 0, at most 256", action.text, action.value));
                (action.text == "radius" ? radius_ : softness_) = float(action.value);
                break;
            }
            try {
                reported(session_.setParameter(action.text, action.value), fmt::format("{} = {}", action.text, action.value));
            } catch (const UserError& e) {
                fail(action, e.what());
            }
            break;
        case Action::Kind::Undo: session_.undo(), sceneChanged(); break;
        case Action::Kind::Redo: session_.redo(), sceneChanged(); break;
        case Action::Kind::Reload: reload(); break;
        case Action::Kind::SaveEdits: saveEdits(action.text); break;
        case Action::Kind::Wait: {
            const auto until = Clock::now() + std::chrono::duration<double>(action.value);
            while (Clock::now() < until) {
                glfwPollEvents();
                watchFile();
                pollRefine();
                frame();
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
            }
            break;
        }
        case Action::Kind::WaitChange: {
            log(fmt::format("waiting for {} to change", session_.path()));
            const auto until = Clock::now() + std::chrono::duration<double>(action.value);
            while (!session_.fileChanged()) {
                if (Clock::now() >= until) fail(action, fmt::format("{} did not change within {} s", session_.path(), action.value));
                glfwPollEvents();
                pollRefine();
                frame();
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
            }
            reload();
            break;
        }
        case Action::Kind::WaitRefined: {
            const auto until = Clock::now() + std::chrono::duration<double>(action.value);
            while (session_.refining()) {
                if (Clock::now() >= until) fail(action, fmt::format("the full solve did not finish within {} s", action.value));
                glfwPollEvents();
                pollRefine();
                frame();
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
            }
            break;
        }
        case Action::Kind::Screenshot: screenshot(action.text); break;
        case Action::Kind::ScreenshotWindow: {
            rendering::Picture window;
            // A frame may be skipped while the swapchain follows a resize; the next one shows.
            for (int attempt = 0; attempt < 10 && window.rgb.empty(); ++attempt) frame(&window);
            if (window.rgb.empty()) fail(action, "the window showed no frame to capture");
            writePicture(action.text, window);
            break;
        }
        }
    }

    void requireWorld(const Action& action) const {
        if (!session_.hasWorld()) fail(action, "there is no world: the file has not checked yet");
    }

    void reload() { reported(session_.reload(), "the file changed"); }

    // Says how a reload went (the panel shows the same), after `why` (a save, a slider).
    void reported(bool reloaded, const std::string& why) {
        if (reloaded) {
            if (!framed_) setCamera(options_.camera); // the first world after a start with a broken file
            const WorldStats& s = session_.stats();
            log(fmt::format("reloaded {} ({}; {}{} triangles; check {:.0f} ms, solve {:.0f} ms, compile {:.0f} ms, run {:.0f} ms, mesh {:.0f} ms)",
                            session_.path(), why, s.preview ? "a coarse preview while the full solve runs; " : "",
                            s.triangles, s.checkMs, s.solveMs, s.compileMs, s.runMs, s.meshMs));
        } else {
            log(fmt::format("{} does not check ({}); keeping the last good world:\n{}", session_.path(), why, session_.lastError()));
        }
        sceneChanged();
    }

    // Puts the background solve's world on screen once it is done.
    void pollRefine() {
        if (const std::optional<bool> refined = session_.poll()) reported(*refined, "the full solve replaced the preview");
    }

    void watchFile() {
        const auto now = Clock::now();
        if (now - lastWatch_ < std::chrono::duration<double>(kWatchIntervalSeconds)) return;
        lastWatch_ = now;
        if (session_.fileChanged()) reload();
    }

    void setCamera(const std::string& spec) {
        refreshMesh(); // presets frame the mesh as it now stands, as `voxc render` frames its mesh
        const rendering::ImageSize size = presenter_.extent();
        camera_ = rendering::parseCamera(spec, frameBounds(), float(size.width) / float(size.height));
        framed_ = true;
        pictureStale_ = true;
    }

    rendering::Bounds frameBounds() const {
        const rendering::Bounds bounds = rendering::meshBounds(mesh_);
        if (bounds.min.x <= bounds.max.x) return bounds;
        const glm::ivec3 size = session_.stats().size; // no surface: the grid's box
        return {glm::vec3(0.0f), glm::vec3(glm::max(size - 1, glm::ivec3(1)))};
    }

    void sceneChanged() {
        meshStale_ = true;
        sceneStale_ = true;
        pictureStale_ = true;
    }

    void refreshMesh() {
        if (!meshStale_) return;
        mesh_ = session_.hasWorld() ? session_.world().mesh() : Mesh{};
        meshStale_ = false;
        sceneStale_ = true;
    }

    // The ray through the centre of pixel (x, y) of the view, from the near plane to the far one.
    std::pair<glm::vec3, glm::vec3> pixelRay(glm::vec2 pixel) const {
        const rendering::ImageSize size = presenter_.extent();
        const glm::mat4 inverse = glm::inverse(rendering::viewProjection(camera_, float(size.width) / float(size.height)));
        const glm::vec2 ndc{2.0f * (pixel.x + 0.5f) / float(size.width) - 1.0f, 2.0f * (pixel.y + 0.5f) / float(size.height) - 1.0f};
        glm::vec4 near = inverse * glm::vec4(ndc, 0.0f, 1.0f), far = inverse * glm::vec4(ndc, 1.0f, 1.0f);
        near /= near.w;
        far /= far.w;
        return {glm::vec3(near), glm::vec3(far - near)};
    }

    bool brushAtPixel(Brush::Op op, glm::vec2 pixel) {
        const auto [origin, direction] = pixelRay(pixel);
        return brushAlong(op, origin, direction);
    }

    bool brushAlong(Brush::Op op, glm::vec3 origin, glm::vec3 direction) {
        const std::optional<PickHit> hit = session_.world().pick(origin, direction);
        if (!hit) return false;
        uint8_t material = 0;
        if (op == Brush::Op::Add)
            material = addMaterial_ == kSurfaceMaterial ? surfaceMaterial(session_.world().grid(), session_.iso(), hit->point)
                                                        : uint8_t(addMaterial_);
        Brush brush{op, hit->point, radius_, softness_, material};
        lastEdit_ = session_.edit(brush);
        sceneChanged();
        return true;
    }

    void saveEdits(const std::string& path) {
        session_.saveEdits(path);
        saved_ = fmt::format("wrote {} ({} edits)", path, session_.edits().size());
        log(saved_);
    }

    // Ctrl+S and the button: a file that cannot be written is said in the panel, the window stays.
    void saveEditsInteractively() {
        try {
            saveEdits(editsPath_);
        } catch (const UserError& e) {
            saved_ = e.what();
            log(saved_);
        }
    }

    void screenshot(const std::string& path) { writePicture(path, picture()); }

    void writePicture(const std::string& path, const rendering::Picture& shown) {
        explore::Image image(int(shown.width), int(shown.height), {});
        image.rgb = shown.rgb;
        explore::writePng(path, image);
        log(fmt::format("wrote {} ({}x{})", path, shown.width, shown.height));
    }

    // The view as it now stands, drawn again only when the scene, the camera or the size changed.
    const rendering::Picture& picture() {
        const rendering::ImageSize size = presenter_.extent();
        if (!renderer_ || rendererSize_.width != size.width || rendererSize_.height != size.height) {
            renderer_.reset();
            renderer_.emplace(context_, size);
            rendererSize_ = size;
            sceneStale_ = true;
        }
        refreshMesh();
        if (sceneStale_) {
            rendering::LineSet lines;
            if (wireframe_) lines = rendering::wireframeLines(mesh_, kWireframeColour);
            if (chunkBorders_ && session_.hasWorld()) {
                const rendering::LineSet borders = rendering::chunkBorderLines(session_.world().grid().layout(), kChunkBorderColour);
                lines.points.insert(lines.points.end(), borders.points.begin(), borders.points.end());
                lines.colours.insert(lines.colours.end(), borders.colours.begin(), borders.colours.end());
            }
            renderer_->setScene(mesh_, session_.hasWorld() ? session_.program().materials : std::vector<Material>{}, lines);
            sceneStale_ = false;
            pictureStale_ = true;
        }
        if (pictureStale_) {
            rendering::enclose(camera_, frameBounds()); // near and far as `voxc render` sets them for this mesh
            const auto start = Clock::now();
            picture_ = renderer_->draw(camera_);
            drawMs_ = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            pictureStale_ = false;
        }
        return picture_;
    }

    void frame(rendering::Picture* window = nullptr) {
        presenter_.beginFrame();
        handleInput();
        panel();
        presenter_.present(picture(), window);
    }

    void handleInput();
    void panel();
    void orbit(float yawDegrees, float pitchDegrees);

    const ViewerOptions& options_;
    GlfwLibrary glfw_; // first: no display fails before the world is generated
    VulkanContext context_;
    Session session_;
    Window window_;
    Presenter presenter_;
    std::optional<MeshRenderer> renderer_;
    rendering::ImageSize rendererSize_{};
    rendering::Camera camera_;
    Mesh mesh_;
    rendering::Picture picture_;
    bool meshStale_ = true, sceneStale_ = true, pictureStale_ = true;
    bool framed_ = false; // a camera was set on a world (else the first world that checks gets one)
    bool wireframe_ = false, chunkBorders_ = false;
    float radius_ = 4.0f, softness_ = 2.0f;
    int addMaterial_ = kSurfaceMaterial;
    std::optional<EditStats> lastEdit_;
    double drawMs_ = 0.0;
    std::string editsPath_;
    std::string saved_; // how the last save went
    Clock::time_point lastWatch_ = Clock::now();
    glm::dvec2 lastCursor_{0.0};
};

void App::orbit(float yawDegrees, float pitchDegrees) {
    const glm::vec3 offset = camera_.eye - camera_.target;
    const float distance = glm::length(offset);
    float yaw = std::atan2(offset.x, offset.z), pitch = std::asin(glm::clamp(offset.y / distance, -1.0f, 1.0f));
    yaw += glm::radians(yawDegrees);
    pitch = glm::clamp(pitch + glm::radians(pitchDegrees), glm::radians(-89.0f), glm::radians(89.0f));
    camera_.eye = camera_.target + distance * glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    camera_.up = {0.0f, 1.0f, 0.0f};
    pictureStale_ = true;
}

// Right drag orbits, middle drag pans, the wheel zooms, W A S D Q E fly; left click carves,
// shift-left click adds; Ctrl+Z undo, Ctrl+Y redo, Ctrl+S save the edits. The panel keeps what it hovers.
void App::handleInput() {
    const ImGuiIO& io = ImGui::GetIO();
    GLFWwindow* w = window_.handle;
    glm::dvec2 cursor;
    glfwGetCursorPos(w, &cursor.x, &cursor.y);
    const glm::vec2 delta = glm::vec2(cursor - lastCursor_);
    lastCursor_ = cursor;
    if (!session_.hasWorld()) return;
    const glm::vec3 forward = glm::normalize(camera_.target - camera_.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera_.up));
    const glm::vec3 up = glm::cross(right, forward);
    const float scale = glm::length(camera_.eye - camera_.target);
    if (!io.WantCaptureMouse) {
        if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS && delta != glm::vec2(0.0f)) orbit(-0.3f * delta.x, 0.3f * delta.y);
        if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS && delta != glm::vec2(0.0f)) {
            const glm::vec3 move = (-delta.x * right + delta.y * up) * scale * 0.0015f;
            camera_.eye += move, camera_.target += move, pictureStale_ = true;
        }
        if (io.MouseWheel != 0.0f) {
            camera_.eye = camera_.target + (camera_.eye - camera_.target) * std::pow(0.9f, io.MouseWheel);
            pictureStale_ = true;
        }
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            int windowWidth = 0, windowHeight = 0;
            glfwGetWindowSize(w, &windowWidth, &windowHeight);
            const rendering::ImageSize size = presenter_.extent();
            const glm::vec2 pixel = glm::vec2(cursor) * glm::vec2(float(size.width) / float(std::max(windowWidth, 1)),
                                                                  float(size.height) / float(std::max(windowHeight, 1)));
            brushAtPixel(io.KeyShift ? Brush::Op::Add : Brush::Op::Carve, pixel);
        }
    }
    if (io.WantCaptureKeyboard) return;
    const float step = scale * 0.02f;
    const auto held = [&](int key) { return glfwGetKey(w, key) == GLFW_PRESS; };
    glm::vec3 fly{0.0f};
    if (!io.KeyCtrl) {
        if (held(GLFW_KEY_W)) fly += forward;
        if (held(GLFW_KEY_S)) fly -= forward;
        if (held(GLFW_KEY_D)) fly += right;
        if (held(GLFW_KEY_A)) fly -= right;
        if (held(GLFW_KEY_E)) fly += up;
        if (held(GLFW_KEY_Q)) fly -= up;
    }
    if (fly != glm::vec3(0.0f)) camera_.eye += fly * step, camera_.target += fly * step, pictureStale_ = true;
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Z)) session_.undo(), sceneChanged();
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Y)) session_.redo(), sceneChanged();
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_S)) saveEditsInteractively();
}

void App::panel() {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("voxc view");
    ImGui::PushItemWidth(kPanelWidth * 0.5f); // room for the labels
    ImGui::TextWrapped("%s on %s", session_.path().c_str(), context_.device().name.c_str());
    if (!session_.lastError().empty()) {
        ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.35f, 1.0f), session_.hasWorld() ? "Does not check; the last good world stays:"
                                                                               : "Does not check:");
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(session_.lastError().c_str());
        ImGui::PopTextWrapPos();
    } else if (!session_.warnings().empty() && ImGui::CollapsingHeader("Warnings")) {
        ImGui::TextUnformatted(session_.warnings().c_str());
    }
    if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
        // Constants and the seed first, then one folded node per feature, grammar, curves, terrain and
        // lsystem block with its keys.
        std::optional<std::pair<std::string, double>> released;
        std::string feature;
        bool featureOpen = false;
        for (const Parameter& p : session_.parameters()) {
            std::string label = p.name;
            if (p.kind == Parameter::Kind::FeatureKey || p.kind == Parameter::Kind::GrammarKey ||
                p.kind == Parameter::Kind::BlockKey) {
                const size_t dot = p.name.find('.');
                if (p.name.compare(0, dot, feature) != 0 || feature.size() != dot) {
                    if (featureOpen) ImGui::TreePop();
                    feature = p.name.substr(0, dot);
                    featureOpen = ImGui::TreeNode(feature.c_str());
                }
                if (!featureOpen) continue;
                label = p.name.substr(dot + 1);
            }
            ImGui::PushID(p.name.c_str());
            double value = p.value;
            if (p.kind == Parameter::Kind::Seed) {
                // Enter or a step button: a typed number is not a new seed until it is finished.
                int seed = int(p.value);
                if (ImGui::InputInt(label.c_str(), &seed, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue))
                    released = {p.name, double(std::max(seed, 0))};
            } else if (p.integer) {
                int v = int(p.value);
                ImGui::SliderInt(label.c_str(), &v, int(p.sliderMin), int(p.sliderMax));
                value = v;
            } else {
                float v = float(p.value);
                ImGui::SliderFloat(label.c_str(), &v, float(p.sliderMin), float(p.sliderMax));
                value = sliderValue(v);
            }
            // Re-run when the slider is let go, not at every step of the drag.
            if (p.kind != Parameter::Kind::Seed && ImGui::IsItemDeactivatedAfterEdit()) released = {p.name, value};
            ImGui::PopID();
        }
        if (featureOpen) ImGui::TreePop();
        if (ImGui::Button("Reset to the file")) reported(session_.resetParameters(), "parameters reset");
        if (released) reported(session_.setParameter(released->first, released->second), fmt::format("{} = {}", released->first, released->second));
    }
    if (ImGui::CollapsingHeader("Brush", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::SliderFloat("radius", &radius_, 0.5f, 32.0f);
        ImGui::SliderFloat("softness", &softness_, 0.25f, 16.0f);
        if (session_.hasWorld()) {
            const std::vector<Material>& materials = session_.program().materials;
            constexpr const char* kSurface = "the surface's";
            constexpr const char* kKeep = "keep the voxels' own";
            std::string current = addMaterial_ == kSurfaceMaterial ? kSurface : kKeep;
            for (const Material& m : materials)
                if (m.id == addMaterial_) current = m.name;
            if (ImGui::BeginCombo("add material", current.c_str())) {
                if (ImGui::Selectable(kSurface, addMaterial_ == kSurfaceMaterial)) addMaterial_ = kSurfaceMaterial;
                if (ImGui::Selectable(kKeep, addMaterial_ == 0)) addMaterial_ = 0;
                for (const Material& m : materials)
                    if (ImGui::Selectable(m.name.c_str(), addMaterial_ == m.id)) addMaterial_ = m.id;
                ImGui::EndCombo();
            }
        }
        ImGui::TextUnformatted("click: carve, shift+click: add");
        ImGui::Text("%zu edits", session_.edits().size());
        if (ImGui::Button("Undo")) session_.undo(), sceneChanged();
        ImGui::SameLine();
        if (ImGui::Button("Redo")) session_.redo(), sceneChanged();
        ImGui::SameLine();
        if (ImGui::Button("Save edits")) saveEditsInteractively();
        ImGui::TextWrapped("to %s", editsPath_.c_str());
        if (!saved_.empty()) ImGui::TextWrapped("%s", saved_.c_str());
    }
    if (ImGui::CollapsingHeader("World", ImGuiTreeNodeFlags_DefaultOpen)) {
        const WorldStats& s = session_.stats();
        ImGui::Text("grid %dx%dx%d, chunk %d: %d chunks", s.size.x, s.size.y, s.size.z, s.chunkSize,
                    s.chunkCount.x * s.chunkCount.y * s.chunkCount.z);
        ImGui::Text("%zu triangles, %llu dispatches", s.triangles, (unsigned long long)s.dispatches);
        ImGui::Text("check %.0f ms, solve %.0f ms, compile %.0f ms, run %.0f ms, mesh %.0f ms", s.checkMs, s.solveMs,
                    s.compileMs, s.runMs, s.meshMs);
        if (session_.refining()) ImGui::TextUnformatted("a coarse preview: the full solve is running");
        if (lastEdit_)
            ImGui::Text("last edit: %.1f ms, %zu chunks whose mesh it can change", lastEdit_->ms, lastEdit_->chunksRemeshed);
        ImGui::Text("draw %.1f ms", drawMs_);
        if (ImGui::Checkbox("wireframe", &wireframe_)) sceneStale_ = pictureStale_ = true;
        ImGui::SameLine();
        if (ImGui::Checkbox("chunk borders", &chunkBorders_)) sceneStale_ = pictureStale_ = true;
        if (ImGui::Button("Frame (iso)")) setCamera("iso");
    }
    ImGui::PopItemWidth();
    ImGui::End();
}

} // namespace

void runViewer(const ViewerOptions& options) {
    App app(options);
    if (options.script.empty()) app.runInteractive();
    else app.runScript();
}

} // namespace voxc::viewer
