#pragma once
// `voxc view`: a window (GLFW) showing a Session's world drawn by MeshRenderer, a Dear ImGui panel
// (parameters, brush, edits, statistics, the last reload's diagnostics), orbit and fly camera,
// click to carve and shift-click to add, the file watched and reloaded when saved. With a script
// it runs the actions (voxc/viewer/Script.h) and exits, so tests drive it under Xvfb.
// docs/viewer.md.
#include "voxc/render/Camera.h"
#include "voxc/viewer/Script.h"
#include "voxc/viewer/Session.h"

#include <string>
#include <vector>

namespace voxc::viewer {

struct ViewerOptions {
    SessionOptions session;         // with the --edits replayed on the world first
    std::string editsPath;          // where "save edits" (Ctrl+S) writes
    ContextOptions context;         // the device that generates and draws (and its pipeline cache)
    rendering::ImageSize size{1280, 720};
    std::string camera = "iso";     // as `voxc render --camera`
    std::string scriptPath;         // for the actions' locations
    std::vector<Action> script;     // run, then exit; empty: until the window closes
    std::string screenshot;         // written when the script ends (or the window closes)
};

// Throws UserError: no display, no device that draws to it, or a script action that failed
// (located at the action: a pick that missed, a wait-change that timed out, an unknown parameter).
void runViewer(const ViewerOptions& options);

} // namespace voxc::viewer
